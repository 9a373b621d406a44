// Model: the reconstructed, textured 3D image with orbit / pan / pinch-zoom,
// the range pole targets and the accuracy report on it.
#include <nlohmann/json.hpp>

#include "ui/overlay_legend.h"
#include "ui/screens/screens.h"

namespace rockface::ui {

namespace {

// The accuracy figures the reconstruction stored with the registration
// (firmware-app writes them into parameters_json).
void draw_accuracy(const storage::Model& model) {
  const storage::Registration& r = model.registration;
  ImGui::Text("Registration: %s", r.kind.c_str());
  ImGui::Text("Scale %.4f   RMS %.1f mm", r.scale, r.rms_m * 1000);
  const auto p =
      nlohmann::json::parse(r.parameters_json.empty() ? "{}" : r.parameters_json, nullptr, false);
  if (p.is_object()) {
    for (const auto& [key, value] : p.items()) {
      if (key == "targets") continue;
      ImGui::Text("%s: %s", key.c_str(),
                  value.is_string() ? value.get<std::string>().c_str() : value.dump().c_str());
    }
  }
  if (!model.residuals.empty() && ImGui::BeginTable("residuals", 2, ImGuiTableFlags_Borders)) {
    ImGui::TableSetupColumn("control");
    ImGui::TableSetupColumn("residual (mm)");
    ImGui::TableHeadersRow();
    for (const auto& res : model.residuals) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(res.label.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.1f", res.residual.norm() * 1000);
    }
    ImGui::EndTable();
  }
}

// The range pole's targets where the registration put them.
void draw_targets(AppState& app, const storage::Model& model) {
  const auto p = nlohmann::json::parse(
      model.registration.parameters_json.empty() ? "{}" : model.registration.parameters_json,
      nullptr, false);
  if (!p.is_object() || !p.contains("targets")) return;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float r = 14 * app.targets.scale();
  for (const auto& t : p["targets"]) {
    if (!t.is_array() || t.size() != 3) continue;
    const auto at =
        app.model_view.to_screen({t[0].get<double>(), t[1].get<double>(), t[2].get<double>()});
    if (!at) continue;
    draw->AddCircle(*at, r, kTargetColour, 24, 4 * app.targets.scale());
    draw->AddLine(ImVec2(at->x - r, at->y), ImVec2(at->x + r, at->y), kTargetColour, 2);
    draw->AddLine(ImVec2(at->x, at->y - r), ImVec2(at->x, at->y + r), kTargetColour, 2);
  }
}

}  // namespace

bool require_model(AppState& app) {
  if (!app.session) {
    ImGui::TextWrapped("Open a project first (Project).");
    return false;
  }
  if (!app.session->model()) {
    ImGui::TextWrapped(
        "This project has no model yet: capture a stereo pair and reconstruct it "
        "(Capture).");
    return false;
  }
  if (!app.model_view.has_model()) {
    ImGui::TextWrapped("Loading the model ...");
    return false;
  }
  return true;
}

void draw_model_screen(AppState& app) {
  if (!require_model(app)) return;
  const float side = 360 * app.targets.scale();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  ImGui::BeginGroup();
  if (app.show_photograph) {  // ui/overlay_photo_targets.h
    app.photo_targets.draw(app.model_view.model_id(), *app.model_view.model(),
                           app.model_view.photo(), ImVec2(avail.x - side, avail.y),
                           app.targets.scale());
  } else {
    app.model_view.draw(ImVec2(avail.x - side, avail.y), app.gesture);
    ImGui::PushClipRect(app.model_view.panel_min(), app.model_view.panel_max(), true);
    draw_targets(app, *app.model_view.model());
    draw_model_overlays(app, ModelScreen::model);  // ui/overlay_legend.h
    ImGui::PopClipRect();
  }
  ImGui::EndGroup();
  ImGui::SameLine();
  ImGui::BeginChild("model side", ImVec2(0, 0));
  const DisplayMesh& mesh = app.model_view.display_mesh();
  const storage::Model& model = *app.model_view.model();
  ImGui::Text("Model %lld (%s)", static_cast<long long>(model.id), model.preset.c_str());
  const photogrammetry::SurfaceMesh& surface = *app.model_view.surface();
  ImGui::Text("%zu vertices, %zu triangles", surface.vertices.size(), surface.triangles.size());
  ImGui::Text("shown: %zu triangles", mesh.triangle_count());
  if (app.targets.button("Reset view", -1))
    app.model_view.camera().frame(mesh.centre, mesh.radius, mesh.mean_normal);
  if (app.targets.button(app.show_photograph ? "3D image" : "Photograph", -1))
    app.show_photograph = !app.show_photograph;
  ImGui::Separator();
  draw_accuracy(model);
  ImGui::EndChild();
}

}  // namespace rockface::ui

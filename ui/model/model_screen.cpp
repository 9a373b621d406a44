// Model: the reconstructed, textured 3D image with orbit / pan / pinch-zoom,
// the range pole targets and the accuracy of the 3D image in words.
#include <cctype>

#include "core/common/number_format.h"
#include "ui/app/screens.h"
#include "ui/model/accuracy_summary.h"
#include "ui/model/north_entry.h"
#include "ui/model/pole_entry.h"
#include "ui/view3d/overlay_legend.h"
#include "ui/view3d/overlay_targets.h"
#include "ui/widgets/format.h"
#include "ui/widgets/widgets_table.h"

namespace rockface::ui {

namespace {

void draw_accuracy(const storage::Model& model) {
  heading("Accuracy");
  for (const AccuracyLine& line : accuracy_lines(model)) {
    const std::string text = line.title + ": " + line.value;
    if (line.warning)
      paragraph(text, warning_colour());
    else
      paragraph(text);
  }
  if (model.residuals.size() >= 3 && ImGui::BeginTable("residuals", 2, ImGuiTableFlags_Borders)) {
    ImGui::TableSetupColumn("Control point");
    ImGui::TableSetupColumn("Residual");
    table_headers_row();
    for (const auto& res : model.residuals) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      label(res.label);
      ImGui::TableNextColumn();
      label(format::text(format::Length{res.residual.norm()}));
    }
    ImGui::EndTable();
  }
}

// Where the range pole's targets were found, and whether the 3D image shows
// them (the rings on the image and on the photograph).
void draw_targets_in_words(const AppState& app) {
  const auto& targets = app.model_view.targets();
  if (targets.empty()) return;
  heading("Range-pole targets");
  for (const TargetOnModel& t : targets) {
    const std::string pixel = "(" + format_fixed(t.detected.pixel.x(), 0) + ", " +
                              format_fixed(t.detected.pixel.y(), 0) + ")";
    std::string found = (t.detected.which.empty() ? std::string("range-pole") : t.detected.which) +
                        " target: found at pixel " + pixel + " of the left photograph";
    found[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(found[0])));
    if (!t.point)
      paragraph(found + "; not on the 3D image: " + t.why_not);
    else if (t.on_surface)
      paragraph(found + ", ringed on the 3D image");
    else
      paragraph(found +
                ", ringed on the face behind it (the pole itself is left out of the 3D image)");
  }
  ImGui::Separator();
}

}  // namespace

bool require_model(AppState& app) {
  if (!app.session) {
    paragraph("Open a project first (Project).");
    return false;
  }
  if (!app.session->model()) {
    paragraph(
        "This visit has no 3D image yet: take a stereo pair and store it (Capture); the 3D image "
        "is made from it.");
    return false;
  }
  if (!app.model_view.has_model()) {
    paragraph("Loading the 3D image …");
    return false;
  }
  return true;
}

void draw_model_screen(AppState& app) {
  if (!require_model(app)) return;
  const SplitLayout layout = split_for_side_panel(380 * app.targets.scale());
  ImGui::BeginGroup();
  if (app.model.show_photograph) {  // ui/model/overlay_photo_targets.h
    app.model.photo_targets.draw(app.model_view.model_id(), *app.model_view.model(),
                                 app.model_view.photo(), layout.main, app.targets.scale());
    const cv::Mat& photo = app.model_view.photo();
    const ImVec2 lo = app.model.photo_targets.image_min();
    const float k = app.model.photo_targets.screen_px_per_photo_px();
    north_photograph_taps(app, lo, k,
                          ImVec2(lo.x + static_cast<float>(photo.cols) * k,
                                 lo.y + static_cast<float>(photo.rows) * k));
  } else {
    add_targets_to_overlay(app.model_view, app.targets.scale());  // ui/view3d/overlay_targets.h
    const ModelView::Interaction touch = app.model_view.draw(layout.main, app.gesture);
    ImGui::PushClipRect(app.model_view.panel_min(), app.model_view.panel_max(), true);
    pole_model_taps(app, touch);  // ui/model/pole_entry.h
    draw_target_labels(app.model_view, app.targets.scale());
    draw_model_overlays(app, ModelScreen::model);  // ui/view3d/overlay_legend.h
    ImGui::PopClipRect();
  }
  ImGui::EndGroup();
  begin_side_panel("model side", layout);
  const DisplayMesh& mesh = app.model_view.display_mesh();
  const storage::Model& model = *app.model_view.model();
  const photogrammetry::SurfaceMesh& surface = *app.model_view.surface();
  heading("3D image " + std::to_string(model.id) + " (" + model.preset + " preset)");
  paragraph(
      format::count(static_cast<std::int64_t>(surface.vertices.size()), "point", "points") + ", " +
      format::count(static_cast<std::int64_t>(surface.triangles.size()), "triangle", "triangles") +
      (mesh.triangle_count() < surface.triangles.size()
           ? " (" + format::count(static_cast<std::int64_t>(mesh.triangle_count())) +
                 " drawn; measuring uses them all)"
           : std::string()));
  if (app.targets.button("Reset view", -1))
    app.model_view.camera().frame(mesh.centre, mesh.radius, mesh.mean_normal);
  if (app.targets.button(app.model.show_photograph ? "3D image" : "Photograph", -1))
    app.model.show_photograph = !app.model.show_photograph;
  ImGui::Separator();
  draw_targets_in_words(app);
  draw_north_section(app);  // ui/model/north_entry.h
  draw_pole_section(app);   // ui/model/pole_entry.h
  ImGui::Separator();
  draw_accuracy(model);
  ImGui::EndChild();
}

}  // namespace rockface::ui

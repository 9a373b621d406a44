// Mapping: the traces of the visit on the model, and the stereonet of their
// planes and of the visit's joints beside it.
#include "ui/screens/screens.h"
#include "ui/stereonet_view.h"

namespace rockface::ui {

namespace {

void draw_traces(AppState& app) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float s = app.targets.scale();
  for (const auto& m : app.session->measurements()) {
    if (m.kind != storage::Measurement::Kind::trace) continue;
    std::vector<ImVec2> line;
    for (const auto& p : m.points)
      if (const auto q = app.model_view.to_screen(p)) line.push_back(*q);
    draw->AddPolyline(line.data(), static_cast<int>(line.size()), kTraceColour, 0, 4 * s);
  }
}

}  // namespace

void draw_mapping_screen(AppState& app) {
  if (!require_model(app)) return;
  const float side = 380 * app.targets.scale();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  ImGui::BeginGroup();
  app.model_view.draw(ImVec2(avail.x - side, avail.y), app.gesture);
  ImGui::PushClipRect(app.model_view.panel_min(), app.model_view.panel_max(), true);
  draw_traces(app);
  ImGui::PopClipRect();
  ImGui::EndGroup();
  ImGui::SameLine();
  ImGui::BeginChild("mapping side", ImVec2(0, 0));
  if (app.targets.button("Undo", 0, !app.mapping.points.empty())) app.mapping.points.pop_back();
  std::vector<StereonetPlane> planes;
  for (const auto& j : app.session->joints())
    planes.push_back({j.dip_deg, j.dipdir_deg, IM_COL32(0, 90, 200, 255), true});
  for (const auto& m : app.session->measurements())
    if (m.kind == storage::Measurement::Kind::trace && m.dip_deg)
      planes.push_back({*m.dip_deg, *m.dipdir_deg, kTraceColour, false});
  draw_stereonet(planes, side - 20 * app.targets.scale());
  ImGui::EndChild();
}

}  // namespace rockface::ui

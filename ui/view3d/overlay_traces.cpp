#include "ui/view3d/overlay_traces.h"

#include <array>

#include "ui/app/app_state.h"

namespace rockface::ui {

namespace {

// Joints' colours: saturated and light, none of them a verdict's (red,
// orange, yellow, green, grey) or the pending trace's blue, each readable
// on grey rock.
constexpr std::array<ImU32, 6> kJointPalette{
    IM_COL32(170, 90, 255, 255),  IM_COL32(0, 220, 200, 255),   IM_COL32(200, 220, 255, 255),
    IM_COL32(255, 150, 230, 255), IM_COL32(140, 255, 120, 255), IM_COL32(120, 60, 30, 255)};

void add_line(AppState& app, const std::string& what, const std::vector<Eigen::Vector3d>& points,
              ImU32 colour, float width) {
  const SurfaceDrape* drape = app.model_view.drape();
  if (!drape || points.size() < 2) return;
  for (const auto& run : app.model_view.drape_cache().runs(*drape, points, false))
    app.model_view.overlay().lines.push_back({what, run, colour, width, false});
}

}  // namespace

ImU32 joint_colour(const std::string& joint_label, const std::vector<storage::Joint>& joints) {
  if (joint_label.empty()) return kTraceColour;
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (joints[i].label == joint_label) return kJointPalette[i % kJointPalette.size()];
  return kTraceColour;
}

void add_traces_to_overlay(AppState& app) {
  if (!app.session) return;
  const float width = 4 * app.targets.scale();
  for (const auto& m : app.session->measurements())
    if (m.kind == storage::Measurement::Kind::trace)
      add_line(app, "trace " + m.label, m.points,
               joint_colour(m.joint_label, app.session->joints()), width);
  add_line(app, "trace being marked", app.mapping.marker.points(), kPendingTraceColour, width);
}

}  // namespace rockface::ui

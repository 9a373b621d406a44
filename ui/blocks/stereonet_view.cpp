#include "ui/blocks/stereonet_view.h"

#include <algorithm>

#include "core/common/units.h"
#include "core/geometry/stereonet.h"
#include "ui/view3d/overlay_text.h"

namespace rockface::ui {

void draw_stereonet(const std::vector<StereonetPlane>& planes, float size) {
  using namespace geometry;
  // At the foot of a full panel the room left below is nothing or less:
  // the net then takes the panel's width (or sixteen lines) and the panel
  // scrolls to it.
  size = std::max(size, std::min(ImGui::GetContentRegionAvail().x, 16 * ImGui::GetFontSize()));
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  // Room above the circle for the N, at any type size.
  const float radius = size / 2 - std::max(16.0f, ImGui::GetTextLineHeight() + 2);
  const ImVec2 centre(corner.x + size / 2, corner.y + size / 2);
  // Unit-circle coordinates (x east, y north) to screen (y down).
  auto at = [&](const Eigen::Vector2d& p) {
    return ImVec2(centre.x + static_cast<float>(p.x()) * radius,
                  centre.y - static_cast<float>(p.y()) * radius);
  };
  draw->AddCircleFilled(centre, radius, IM_COL32(255, 255, 255, 255), 96);
  draw->AddCircle(centre, radius, IM_COL32(0, 0, 0, 255), 96, 2);
  draw->AddLine(ImVec2(centre.x - 6, centre.y), ImVec2(centre.x + 6, centre.y),
                IM_COL32(0, 0, 0, 255));
  draw->AddLine(ImVec2(centre.x, centre.y - 6), ImVec2(centre.x, centre.y + 6),
                IM_COL32(0, 0, 0, 255));
  draw_text(draw, ImVec2(centre.x - ImGui::CalcTextSize("N").x / 2, corner.y),
            IM_COL32(0, 0, 0, 255), "N",
            {corner, ImVec2(corner.x + size, corner.y + size), "stereonet"});
  for (const auto& plane : planes) {
    const PlaneOrientation o{deg_to_rad(plane.dip_deg), deg_to_rad(plane.dipdir_deg)};
    if (plane.great_circle) {
      std::vector<ImVec2> line;
      for (const auto& p : project_great_circle(o, Projection::EqualArea, Hemisphere::Lower))
        line.push_back(at(p));
      draw->AddPolyline(line.data(), static_cast<int>(line.size()), plane.colour, 0, 2);
    }
    draw->AddCircleFilled(at(project_pole(o, Projection::EqualArea, Hemisphere::Lower)), 5,
                          plane.colour, 12);
  }
  ImGui::Dummy(ImVec2(size, size));
}

}  // namespace rockface::ui

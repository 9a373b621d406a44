#pragma once
// A lower-hemisphere equal-area stereonet drawn with ImGui: the primitive
// circle with north, and each plane as its great circle and pole. The
// projection itself is core/geometry/stereonet.
#include <string>
#include <vector>

#include <imgui.h>

namespace rockface::ui {

struct StereonetPlane {
  double dip_deg = 0, dipdir_deg = 0;
  ImU32 colour = IM_COL32(0, 0, 0, 255);
  bool great_circle = true;  // else the pole only
};

// Draws at the cursor in a square of `size` pixels and advances the cursor.
void draw_stereonet(const std::vector<StereonetPlane>& planes, float size);

}  // namespace rockface::ui

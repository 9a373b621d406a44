#pragma once
// The scale bar on the 3D image: a round length (1, 2 or 5 times a power of
// ten metres) as long on the screen as it is at the surface in the middle
// of the view (a perspective view has no one scale: the bar says where it
// holds). A model that was not scaled (no range pole, no control points)
// gets "not to scale" instead.
#include "ui/view3d/model_view.h"

namespace rockface::ui {

// Whether the model's registration scaled it to metres.
bool model_is_scaled(const storage::Model& model);

// A rectangle of the screen that an overlay drew on (for tests: the flat
// marks drawn over the 3D image, not on its surface).
struct DrawnRect {
  ImVec2 min{1e9f, 1e9f}, max{-1e9f, -1e9f};
  void add(ImVec2 a, ImVec2 b);
  void add_text(ImVec2 at, const char* text);
};

// Bottom left of the model panel; `scale` is the UI's (1 = 1280 x 800).
DrawnRect draw_scale_bar(const ModelView& view, float scale);

}  // namespace rockface::ui

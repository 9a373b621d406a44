#pragma once
// The north arrow on the 3D image. The project frame is x = East, y =
// North, z = Up (DESIGN.md) once the model is oriented (compass line, or
// control points): the arrow is north as the view shows it, with the
// direction the view looks in (azimuth from north, clockwise), since a face
// photographed head-on is often seen looking north and its north arrow then
// points into the screen. A model that was not oriented says so instead.
#include "ui/view3d/model_view.h"
#include "ui/view3d/overlay_scale_bar.h"

namespace rockface::ui {

// Whether the model's registration oriented it to north.
bool model_is_oriented(const storage::Model& model);

// The azimuth (degrees, [0, 360)) the view looks in, horizontally; nothing
// when it looks straight up or down.
std::optional<double> view_azimuth_deg(const ModelView& view);

// Top left of the model panel.
DrawnRect draw_north_arrow(const ModelView& view, float scale);

}  // namespace rockface::ui

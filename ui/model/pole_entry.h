#pragma once
// The Model screen's range pole for a 3D image imported in a local frame
// (issue 43): a scanner's or a drone's cloud has no photograph in which the
// pole could be found, so it comes in not to scale. The geologist taps the
// pole's lower target, then its upper one, on the 3D image, and the visit is
// scaled and levelled by them with the pole's length typed on the Capture
// screen (PoleRunner: firmware-app/import/scale_import_by_pole.h).
#include <vector>

#include <Eigen/Core>

#include "ui/view3d/model_view.h"

namespace rockface::ui {

struct AppState;

struct PoleEntryState {
  bool open = false;
  std::vector<Eigen::Vector3d> targets;  // tapped on the 3D image, lower first, at most two
  void clear();
};

// The "Scale" section of the side panel for an imported 3D image nothing
// registered: the entry when it is open.
void draw_pole_section(AppState& app);

// This frame's tap on the 3D image while the entry is open: the next
// target (a third tap starts again); draws the tapped targets over it.
void pole_model_taps(AppState& app, const ModelView::Interaction& touch);

}  // namespace rockface::ui

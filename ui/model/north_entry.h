#pragma once
// The Model screen's north (issue 42): a visit stored without a compass line
// is turned as its camera stood, and the tablet said nothing of it. Here the
// geologist gives north after the fact: taps the two ends of a line whose
// bearing was read with the compass (a painted line, a string, the edge of
// the pole's shadow) on the left photograph of the visit's first pair,
// types the bearing read from the first tap to the second (and the magnetic
// declination when the compass does not correct it), and the visit's 3D
// images are turned as the reconstruction would have turned them
// (NorthRunner: the workflow `rockface orient` runs).
#include <optional>
#include <vector>

#include <imgui.h>
#include <Eigen/Core>

#include "ui/widgets/keypad.h"

namespace rockface::ui {

struct AppState;

struct NorthEntryState {
  enum class Field { bearing, declination };
  bool open = false;
  std::vector<Eigen::Vector2d> ends;  // left photograph's pixels tapped, at most two
  TypedNumber bearing{5}, declination{4};
  bool declination_west = false;
  Field typing = Field::bearing;
  void clear();
};

// The "North" section of the side panel: where north came from, and the
// entry when it is open.
void draw_north_section(AppState& app);

// A tap on the photograph while the entry is open: the next end of the
// line (a third tap starts the line again). `image_min` and `px_per_photo_px`
// place the photograph on the screen (PhotoTargetsView); draws the ends and
// the line over it.
void north_photograph_taps(AppState& app, ImVec2 image_min, float px_per_photo_px,
                           ImVec2 image_max);

}  // namespace rockface::ui

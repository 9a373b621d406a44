#pragma once
// The Model screen's own state: the left photograph with the detected pole
// targets (issue 27), shown in place of the 3D image when chosen; north
// given on it from a compass line (issue 42); an imported cloud scaled by
// the range pole's targets tapped on the 3D image (issue 43).
#include "ui/model/north_entry.h"
#include "ui/model/overlay_photo_targets.h"
#include "ui/model/pole_entry.h"

namespace rockface::ui {

struct ModelScreenState {
  PhotoTargetsView photo_targets;
  bool show_photograph = false;
  NorthEntryState north;
  PoleEntryState pole;  // an imported cloud scaled by its pole (issue 43)
};

}  // namespace rockface::ui

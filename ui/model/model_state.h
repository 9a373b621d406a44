#pragma once
// The Model screen's own state: the left photograph with the detected pole
// targets (issue 27), shown in place of the 3D image when chosen; north
// given on it from a compass line (issue 42).
#include "ui/model/north_entry.h"
#include "ui/model/overlay_photo_targets.h"

namespace rockface::ui {

struct ModelScreenState {
  PhotoTargetsView photo_targets;
  bool show_photograph = false;
  NorthEntryState north;
};

}  // namespace rockface::ui

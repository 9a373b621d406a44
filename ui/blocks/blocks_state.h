#pragma once
// The Blocks screen's own state: the block tapped and its motion, and the
// Wedges, Rock mass and Support views.
#include <cstddef>
#include <optional>

#include "ui/blocks/motion_playback.h"
#include "ui/blocks/rockmass_view.h"
#include "ui/blocks/support_view.h"
#include "ui/blocks/wedges_view.h"

namespace rockface::ui {

struct BlocksState {
  std::optional<std::size_t> selected_block;  // index into session->blocks()
  MotionPlayback motion;                      // the selected block's motion after failure
  WedgesState wedges;                         // the Wedges view
  RockMassState rockmass;                     // the Rock mass view
  SupportViewState support;                   // the Support view (issue 44)
};

}  // namespace rockface::ui

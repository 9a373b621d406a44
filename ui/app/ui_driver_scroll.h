#pragma once
// How a finger brings a target scrolled out of view into view: which panel
// to drag (the innermost that hides it, or the panel around a panel that is
// itself out of view), from where (inside the panel's part on the screen,
// never on a control that takes drags itself nor in a panel nested in it
// that scrolls too) and how far (the content follows the finger:
// ui/widgets/widgets_scroll.h).
#include <optional>

#include <Eigen/Core>

#include "ui/widgets/widgets.h"

namespace rockface::ui {

// Whether `t` shows as much of itself as its panel can: the whole of it,
// or a panel's whole height or width of it when it is taller or wider.
bool shown_whole(const TargetRect& t);

// Whether a drag can bring `t` (further) into view: a panel it lies in
// scrolls and does not show all of it. A target cut only by what no drag
// moves (the 3D image's edge, a panel that does not scroll) is not.
bool scrolled_out_of_view(const TargetRect& t);

struct DragPlan {
  Eigen::Vector2f from, to;
};

// The next drag toward bringing `t` into view; `attempt` > 0 picks another
// start point (the last drag did not move it). Nothing when no drag can:
// it is cut by a panel that does not scroll, or no start point is free.
std::optional<DragPlan> drag_toward(const TargetRect& t, const TouchTargets& all, int attempt);

}  // namespace rockface::ui

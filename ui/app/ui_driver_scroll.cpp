#include "ui/app/ui_driver_scroll.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rockface::ui {

namespace {

// Pixels a drag starts inside its panel's edge: a fingertip's half width
// would be more, but the panel's last pixels are its own too.
constexpr float kInsetPx = 4;
// Half a pixel of ImGui's rounding of item rectangles.
constexpr float kRoundingPx = 0.5f;

// How far the content must move (toward lower coordinates when positive)
// for [lo, hi] to lie in [a, b]; a span longer than the panel is brought to
// its start.
float needed(float lo, float hi, float a, float b) {
  if (lo < a - kRoundingPx) return lo - a;
  if (hi > b + kRoundingPx) return std::min(hi - b, lo - a);
  return 0;
}

bool inside(ImVec2 p, ImVec2 min, ImVec2 max) {
  return p.x >= min.x && p.x < max.x && p.y >= min.y && p.y < max.y;
}

bool same_panel(const ScrollView& a, const ScrollView& b) {
  return a.inner_min.x == b.inner_min.x && a.inner_min.y == b.inner_min.y &&
         a.inner_max.x == b.inner_max.x && a.inner_max.y == b.inner_max.y;
}

// A start point that is no control taking drags and in no panel nested in
// `v` that scrolls too (that panel would take the drag).
bool free_start(ImVec2 p, const ScrollView& v, const TouchTargets& all) {
  for (const auto& [label, r] : all.all()) {
    if (r.drags && r.visible && inside(p, r.shown_min, r.shown_max)) return false;
    const auto in_v = std::find_if(r.views.begin(), r.views.end(),
                                   [&](const ScrollView& w) { return same_panel(w, v); });
    if (in_v == r.views.end()) continue;  // drawn elsewhere (another panel, a popup)
    for (auto w = r.views.begin(); w != in_v; ++w)
      if (w->scrolls && !w->clip_empty() && inside(p, w->clip_min, w->clip_max)) return false;
  }
  return true;
}

}  // namespace

bool shown_whole(const TargetRect& t) {
  if (!t.visible) return false;
  if (t.views.empty()) return true;
  const ScrollView& v = t.views.front();
  // What of it lies in its panel's part on the screen, against what could.
  const float w = std::min(t.max.x, v.clip_max.x) - std::max(t.min.x, v.clip_min.x);
  const float h = std::min(t.max.y, v.clip_max.y) - std::max(t.min.y, v.clip_min.y);
  const float can_w = std::min(t.max.x - t.min.x, v.inner_max.x - v.inner_min.x);
  const float can_h = std::min(t.max.y - t.min.y, v.inner_max.y - v.inner_min.y);
  return w + 2 * kRoundingPx >= can_w && h + 2 * kRoundingPx >= can_h;
}

bool scrolled_out_of_view(const TargetRect& t) {
  ImVec2 lo = t.min, hi = t.max;
  for (const ScrollView& v : t.views) {
    const bool out = needed(lo.y, hi.y, v.inner_min.y, v.inner_max.y) != 0 ||
                     needed(lo.x, hi.x, v.inner_min.x, v.inner_max.x) != 0;
    if (out && v.scrolls) return true;
    if (out) return false;
    if (v.clip_empty()) {
      lo = v.inner_min;
      hi = v.inner_max;
    }
  }
  return false;
}

std::optional<DragPlan> drag_toward(const TargetRect& t, const TouchTargets& all, int attempt) {
  ImVec2 lo = t.min, hi = t.max;  // what must come into view
  for (const ScrollView& v : t.views) {
    const float dy = needed(lo.y, hi.y, v.inner_min.y, v.inner_max.y);
    const float dx = needed(lo.x, hi.x, v.inner_min.x, v.inner_max.x);
    if (dy == 0 && dx == 0) continue;  // in this panel's content area: the next one out
    if (!v.scrolls) return std::nullopt;
    if (v.clip_empty()) {
      // The panel itself is out of view: bring it into its panel first.
      lo = v.inner_min;
      hi = v.inner_max;
      continue;
    }
    // The content follows the finger: the finger moves by minus the
    // content's move, at most across the panel's part on the screen.
    const float room_y = std::max(0.0f, v.clip_max.y - v.clip_min.y - 2 * kInsetPx);
    const float room_x = std::max(0.0f, v.clip_max.x - v.clip_min.x - 2 * kInsetPx);
    // A move within the slop is a tap: past it by a pixel or two at least
    // (the content then moves a little further than needed, which a
    // target smaller than the panel allows).
    const float least = all.drag_slop_px() + 2;
    auto finger = [&](float content, float room) {
      const float f = std::clamp(-content, -room, room);
      return std::copysign(std::min(std::max(std::fabs(f), least), room), f);
    };
    const float fy = finger(dy, room_y), fx = finger(dx, room_x);
    // One axis a drag, the vertical first. It starts on the side the finger
    // moves away from, so that the whole move fits the panel.
    const bool vertical = dy != 0;
    constexpr std::array<float, 7> kAcross{0.5f, 0.3f, 0.7f, 0.15f, 0.85f, 0.05f, 0.95f};
    for (std::size_t k = 0; k < kAcross.size(); ++k) {
      const float f = kAcross[(k + static_cast<std::size_t>(attempt)) % kAcross.size()];
      ImVec2 start;
      if (vertical)
        start = ImVec2(v.clip_min.x + f * (v.clip_max.x - v.clip_min.x),
                       fy < 0 ? v.clip_max.y - kInsetPx : v.clip_min.y + kInsetPx);
      else
        start = ImVec2(fx < 0 ? v.clip_max.x - kInsetPx : v.clip_min.x + kInsetPx,
                       v.clip_min.y + f * (v.clip_max.y - v.clip_min.y));
      if (!free_start(start, v, all)) continue;
      const Eigen::Vector2f from(start.x, start.y);
      return DragPlan{from, from + (vertical ? Eigen::Vector2f(0, fy) : Eigen::Vector2f(fx, 0))};
    }
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace rockface::ui

#include "ui/trace_marker.h"

#include <cmath>

#include "core/common/error.h"

namespace rockface::ui {

void TraceMarker::set_mode(Mode mode) {
  if (mode != mode_) clear();
  mode_ = mode;
}

void TraceMarker::clear() {
  taps_.clear();
  points_.clear();
  plane_.reset();
  problem_.clear();
}

bool TraceMarker::tap(const measure::Ray& ray, const TraceContext& context) {
  if (!context.picker) return false;
  const auto hit = context.picker->pick(ray);
  if (!hit) {
    problem_ = "no surface under the tap";
    return false;
  }
  // A third tap in two-tap mode starts the next trace.
  if (mode_ == Mode::two_taps && taps_.size() == 2) clear();
  taps_.push_back(hit->point);
  remeasure(context);
  return true;
}

void TraceMarker::undo(const TraceContext& context) {
  if (taps_.empty()) return;
  taps_.pop_back();
  remeasure(context);
}

void TraceMarker::remeasure(const TraceContext& context) {
  plane_.reset();
  problem_.clear();
  points_ = taps_;
  try {
    if (mode_ == Mode::two_taps && taps_.size() == 2) {
      if (!context.photo_view || !context.photo || context.photo->empty()) {
        problem_ = "no calibrated photograph to trace on: the ends are joined straight";
      } else {
        const auto ends = measure::project_to_view(*context.photo_view, taps_);
        measure::TraceRequest request;
        request.from = ends[0];
        request.to = ends[1];
        const measure::TracedPath path =
            measure::trace_between(*context.photo, nullptr, request, "trace ends");
        const measure::TraceMeasurement m = measure::measure_trace(
            *context.picker, *context.photo_view, "trace", path.pixels, context.settings, "trace");
        points_ = m.points;
        plane_ = m.plane;
        return;
      }
    }
    if (points_.size() >= 3) {
      plane_ = measure::measure_trace_points(*context.picker, "trace", points_, context.settings,
                                             "trace")
                   .plane;
    }
  } catch (const InputError& e) {
    problem_ = e.what();
  }
}

}  // namespace rockface::ui

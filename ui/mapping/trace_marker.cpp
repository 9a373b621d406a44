#include "ui/mapping/trace_marker.h"

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
  detail_.clear();
}

bool TraceMarker::tap(const measure::Ray& ray, const TraceContext& context) {
  if (!context.picker) return false;
  const auto hit = context.picker->pick(ray);
  if (!hit) {
    problem_ = "This tap is off the 3D surface: tap on the rock.";
    detail_ = "tap: no surface of the 3D image under the tap";
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
  detail_.clear();
  points_ = taps_;
  try {
    if (mode_ == Mode::two_taps && taps_.size() == 2) {
      if (!context.photo_view || !context.photo || context.photo->empty()) {
        problem_ =
            "This 3D image has no calibrated photograph to trace on: the two ends are joined "
            "straight. Tap points along the trace to follow it.";
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
    detail_ = e.what();
    problem_ = trace_problem_in_words(mode_, e.reason());
  } catch (const Error& e) {
    // The path search found no way between the ends (core/measure's Error).
    detail_ = e.what();
    problem_ = trace_problem_in_words(mode_, e.what());
  }
}

std::string trace_problem_in_words(TraceMarker::Mode mode, const std::string& reason) {
  auto has = [&](const char* words) { return reason.find(words) != std::string::npos; };
  const bool two_taps = mode == TraceMarker::Mode::two_taps;
  if (has("no surface of the 3D image"))
    return two_taps ? "The line found between the two ends runs off the 3D surface: tap two ends "
                      "closer together on the rock, or tap points along the trace."
                    : "A point of this trace is off the 3D surface: undo the last tap and tap on "
                      "the rock.";
  if (has("same pixel")) return "Both ends are the same point: tap the other end of the trace.";
  if (has("outside the image"))
    return "An end is outside the photograph of this 3D image: tap both ends on the rock it shows.";
  if (has("no path between"))
    return "No line was found between the two ends: tap them again, or tap points along the "
           "trace.";
  if (has("not a number"))
    return "A tapped point has no position on the model: undo it and tap again on the rock.";
  if (has("needs at least"))
    return two_taps ? "Tap the other end of the trace." : "Tap more points along the trace.";
  // Any other refusal: its reason (core/measure words it for people, only
  // its field path is technical) and the way out.
  return "This trace cannot be measured (" + reason + "): undo the last tap and try again.";
}

}  // namespace rockface::ui

#pragma once
// The trace being marked on the Mapping screen. Taps arrive as rays from
// the model view; picking on the mesh, semi-automatic tracing and the plane
// fit with its uncertainty are core/measure's: this class only keeps the
// taps, asks core/measure, and holds the answer for the screen.
//
// Two ways to mark: tap points along the trace (a polyline of picks), or
// tap its two ends and let the least-cost path through the photograph
// follow the dark line between them.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/measure/least_cost_trace.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/plane_measurement.h"

namespace rockface::ui {

// What a trace is measured against: the model's picker, and (for two-tap
// tracing) the photograph the model is textured with and its view.
struct TraceContext {
  const measure::MeshPicker* picker = nullptr;
  const measure::PhotoView* photo_view = nullptr;  // null: no two-tap tracing
  const cv::Mat* photo = nullptr;
  measure::MeasureSettings settings;
};

class TraceMarker {
 public:
  enum class Mode { points, two_taps };

  void set_mode(Mode mode);
  Mode mode() const { return mode_; }

  // A tap's ray; false (and `problem()` says why) when no surface is hit.
  bool tap(const measure::Ray& ray, const TraceContext& context);
  void undo(const TraceContext& context);
  void clear();

  const std::vector<Eigen::Vector3d>& taps() const { return taps_; }
  // The trace's points: the taps, or the traced path between two taps.
  const std::vector<Eigen::Vector3d>& points() const { return points_; }
  // The plane fitted so far (from three points, or from a traced path).
  const std::optional<measure::PlaneEstimate>& plane() const { return plane_; }
  // What went wrong with the last tap, in words for the screen: what
  // happened and what to do ("This tap is off the 3D surface: tap on the
  // rock."). Empty when nothing did.
  const std::string& problem() const { return problem_; }
  // The library's precise message for the same (field and index, e.g.
  // "trace.pixels[784]: no surface of the 3D image under this pick"), for
  // logs and bug reports; never shown on the screen.
  const std::string& detail() const { return detail_; }

 private:
  void remeasure(const TraceContext& context);
  Mode mode_ = Mode::points;
  std::vector<Eigen::Vector3d> taps_, points_;
  std::optional<measure::PlaneEstimate> plane_;
  std::string problem_, detail_;
};

// A failure of core/measure while measuring a trace of `mode`, in words for
// the geologist: what happened and what to do.
std::string trace_problem_in_words(TraceMarker::Mode mode, const std::string& reason);

}  // namespace rockface::ui

#pragma once
// Semi-automatic tracing: the user taps the two ends of a trace and the path
// between them follows the discontinuity, as the least-cost 8-connected path
// (Dijkstra) through the photograph within a corridor around the straight
// line. The cost is chosen per trace: darkness (a joint trace is a thin line
// darker than its surroundings), image gradient (an edge: a step in
// brightness), or surface curvature (a sharp fold of the 3D image, from the
// mesh).
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::measure {

enum class TraceCost { Darkness, Gradient, Curvature };

// "darkness" | "gradient" | "curvature"; throws InputError(where, ...) otherwise.
TraceCost trace_cost_by_name(const std::string& name, const std::string& where);
const char* trace_cost_name(TraceCost cost);

struct TraceRequest {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();  // pixels of the photograph
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  TraceCost cost = TraceCost::Darkness;
  double corridor_px = 0;  // half-width of the search corridor; 0: from the tolerances
};

struct TracedPath {
  std::vector<Eigen::Vector2d> pixels;  // from `from` to `to`, one per pixel step
  double mean_cost = 0;                 // per pixel step, in [0, 1]
};

// `image`: the photograph (CV_8UC1 or CV_8UC3). `mesh`: the 3D image on that
// photograph (its vertex pixels), needed only for TraceCost::Curvature and
// otherwise may be null. Throws InputError(where, ...) for ends outside the
// image, ends that coincide, or a curvature cost without a mesh.
TracedPath trace_between(const cv::Mat& image, const photogrammetry::SurfaceMesh* mesh,
                         const TraceRequest& request, const std::string& where);

}  // namespace rockface::measure

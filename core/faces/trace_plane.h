#pragma once
// The joint plane behind each trace. A trace tied to a joint takes the
// joint's orientation and is located by its own points (a joint of the scene
// stands for a set of parallel discontinuities; the trace says which one).
// A trace with no joint is fitted: its points must have relief (lie on two
// or more patches that are not coplanar, far enough from a straight line for
// the marking error to tilt the plane by less than kMaxFitUncertaintyDeg) and
// lie on one plane (planarity test); otherwise its orientation is unknown
// and the trace is left out of blocks.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/faces/free_surface.h"
#include "core/geometry/orientation.h"
#include "core/geometry/plane.h"

namespace rockface::faces {

struct TraceJoint {
  int index = -1;  // caller's joint index (scene order)
  std::string id;
  geometry::PlaneOrientation orientation;  // radians
  std::optional<double> friction;          // radians
  double cohesion = 0;                     // Pa
};

struct TraceInput {
  std::string id;
  std::optional<TraceJoint> joint;
  std::vector<Eigen::Vector3d> points;  // datum-relative
};

enum class TracePlaneSource { Joint, Fitted };

struct TracePlane {
  geometry::Plane plane;  // datum-relative, upward normal
  TracePlaneSource source = TracePlaneSource::Joint;
  double uncertainty = 0;   // radians: of the fit (0 for a given joint)
  double max_residual = 0;  // m: largest distance of a point from the plane
};

struct TracePlaneResult {
  std::optional<TracePlane> plane;
  std::string problem;  // why there is no plane (or a warning with a plane)
};

// `patches_touched`: the patches the trace's points lie on (from
// points_on_patches). tolerance: the snap tolerance, m.
TracePlaneResult resolve_trace_plane(const TraceInput& trace, const FreeSurface& surface,
                                     const std::vector<int>& patches_touched, double tolerance);

// For each point, the patches it lies on (within `tolerance` of the plane and
// of the polygon); a point near a shared edge lies on both.
std::vector<std::vector<int>> points_on_patches(const std::vector<Eigen::Vector3d>& points,
                                                const FreeSurface& surface, double tolerance);

}  // namespace rockface::faces

#pragma once
// Measurements on the 3D image (CloudCompare Compass is the model): a trace
// (a polyline of picks along a discontinuity's trace) gives the joint plane
// through it; an area (a polygon of picks on an exposed joint face or a free
// face) gives the plane of the surface inside; a point gives the local
// surface normal. Each keeps the photo and pixels it came from.
//
// A trace defines a plane only with relief: a straight trace on a flat face
// is a line, and a trace wandering within one flat face lies in the face's
// plane, not the joint's. Both are reported as "orientation unknown",
// never as a confident wrong dip (tolerances.h).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/orientation.h"
#include "core/geometry/plane_fit.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/photo_view.h"
#include "core/measure/tolerances.h"

namespace rockface::measure {

struct MeasureSettings {
  // Precision (m, one sigma) of a point picked on the 3D image: the
  // reconstruction's predicted depth precision (sigma_Z of its report).
  double point_sigma = 0.01;
  double max_plane_sigma_deg = kMaxPlaneSigmaDeg;
  double sample_step_px = kTraceSampleStepPx;
  // Distance (m) over which the errors of neighbouring picked points are
  // correlated (the dense-matching window on the surface): the fit counts
  // one independent point per such length. 0: every point independent.
  double correlation_length = 0;
};

// The plane behind a measurement, or why there is none.
struct PlaneEstimate {
  bool known = false;
  geometry::PlaneFit fit;                  // of the points kept (centroid, spreads); always filled
  std::size_t outliers = 0;                // points dropped by the robust fit (tolerances.h)
  geometry::PlaneOrientation orientation;  // radians; meaningful when known
  double sigma = 0;  // radians: one standard deviation of the normal (when known)
  // Trace only: RMS spread of the points along the local surface normal (m),
  // the relief the trace has off the face it was drawn on.
  double relief_off_face = 0;
  std::string problem;  // "orientation unknown: ..." when not known; may warn when known
};

struct TraceMeasurement {
  std::string id;
  std::vector<PhotoPixel> picks;        // the taps (or the traced path) in the photo
  std::vector<Eigen::Vector3d> points;  // on the mesh, every sample_step_px along the picks
  std::vector<Eigen::Vector3d> surface_normals;  // of the mesh at each point
  PlaneEstimate plane;
  double length = 0;  // m, along the points
  // An end lies at the edge of the mapped area (image border or no surface
  // beyond it): the true trace is longer than measured. censored_ends: the
  // start (first pick) and the end (last pick) each; censored: either.
  bool censored = false;
  std::array<bool, 2> censored_ends{false, false};
};

struct AreaMeasurement {
  std::string id;
  std::vector<PhotoPixel> outline;              // the polygon in the photo
  std::vector<Eigen::Vector3d> outline_points;  // its corners on the mesh, one per corner
  std::size_t vertices = 0;                     // mesh vertices inside
  double area = 0;                              // m^2 of the triangles inside
  PlaneEstimate plane;
};

struct PointMeasurement {
  std::string id;
  PhotoPixel pick;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  PlaneEstimate plane;  // the local surface plane within `radius` of the point
};

// The robust plane of points on the 3D image (least squares, points farther
// than kOutlierInSigmas dropped and the plane refitted), its sigma from the
// point precision or the scatter seen, whichever is larger, counting one
// independent point per correlation length. `kept` (optional) marks the
// points used. Leaves `known` false and `problem` empty: callers judge.
PlaneEstimate plane_of_points(const std::vector<Eigen::Vector3d>& points,
                              const MeasureSettings& settings, std::vector<char>* kept = nullptr);

// The planarity test of measuring: "orientation unknown: WHAT is not
// planar ..." when the points scatter off their plane by more than
// `max_rms_in_sigmas` point sigmas (RMS); empty when they pass.
std::string planarity_problem(const PlaneEstimate& estimate, const MeasureSettings& settings,
                              double max_rms_in_sigmas, const std::string& what);

// The plane of a trace's points, with the surface normals at them (for the
// relief-off-the-face test; may be empty when unknown).
PlaneEstimate fit_trace_plane(const std::vector<Eigen::Vector3d>& points,
                              const std::vector<Eigen::Vector3d>& surface_normals,
                              const MeasureSettings& settings);

// A trace picked as a polyline of pixels in `view` (at least two distinct
// pixels). Throws InputError naming `where` (e.g. "traces[2]") and the pick
// for a pixel outside the image or not finite, a one-point trace, or a pick
// with no surface under it.
TraceMeasurement measure_trace(const MeshPicker& picker, const PhotoView& view, std::string id,
                               const std::vector<Eigen::Vector2d>& pixels,
                               const MeasureSettings& settings, const std::string& where);

// A trace given as 3D points on the surface (no photo): the normals are
// taken from the nearest mesh triangles.
TraceMeasurement measure_trace_points(const MeshPicker& picker, std::string id,
                                      const std::vector<Eigen::Vector3d>& points,
                                      const MeasureSettings& settings, const std::string& where);

// An area: a polygon of at least three pixels in `view`. Throws InputError
// naming the corner ("where.polygon[2]") when a corner has no surface of the
// mesh under it, and naming the polygon when it has no mesh inside it.
AreaMeasurement measure_area(const MeshPicker& picker, const PhotoView& view, std::string id,
                             const std::vector<Eigen::Vector2d>& polygon,
                             const MeasureSettings& settings, const std::string& where);

// A point and the local surface plane (the mesh within `radius` m).
PointMeasurement measure_point(const MeshPicker& picker, const PhotoView& view, std::string id,
                               const Eigen::Vector2d& pixel, double radius,
                               const MeasureSettings& settings, const std::string& where);

}  // namespace rockface::measure

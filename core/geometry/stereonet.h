#pragma once
// Stereonet projections of directions, plane poles and great circles, as
// data for plotting: points in the unit circle with x to the East and y to
// the North (the primitive circle is radius 1).
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/orientation.h"

namespace rockface::geometry {

enum class Projection { EqualAngle, EqualArea };  // Wulff, Schmidt (Lambert)
enum class Hemisphere { Lower, Upper };

// A direction of an axis (sense ignored: it is folded into the hemisphere).
Eigen::Vector2d project_direction(const Eigen::Vector3d& d, Projection p, Hemisphere h);
// The pole of a plane (its normal as an axis).
Eigen::Vector2d project_pole(const PlaneOrientation& plane, Projection p, Hemisphere h);
// The great circle of a plane, `samples` points from one end of the
// primitive circle to the other (a horizontal plane gives the primitive).
std::vector<Eigen::Vector2d> project_great_circle(const PlaneOrientation& plane, Projection p,
                                                  Hemisphere h, int samples = 91);
// The inverse of project_direction: the unit direction (in the hemisphere
// looked at) plotted at `point`; nothing outside the primitive circle.
std::optional<Eigen::Vector3d> direction_at(const Eigen::Vector2d& point, Projection p,
                                            Hemisphere h);

}  // namespace rockface::geometry

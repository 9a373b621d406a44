#pragma once
// The noise of a point cloud normal to its surface, measured on the cloud
// itself: a scanner's file does not say how far its points scatter, and the
// over- and underbreak of a round count a deviation only beyond twice that
// (core/tunnel/profile_deviation.h: "predicted depth sigma"). The points are
// binned by the caller's surface coordinates (a face's best plane, a round's
// developed view) into square cells; a plane is fitted to each cell's points
// and the rms of its residuals taken (scaled by n / (n - 3) for the three
// parameters fitted); the cloud's figure is the median over the cells, so
// that edges, steps and a few cells across a hole do not count.
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace rockface::photogrammetry {

// cell_m: small beside the surface's curvature (a break's bump of metres),
// large beside the spacing (tens of points a cell). None when fewer than
// ten cells hold ten points.
std::optional<double> cloud_noise_sigma(const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<Eigen::Vector2d>& uv, double cell_m);

}  // namespace rockface::photogrammetry

#include "firmware-app/import/import_control_points.h"

#include <fstream>
#include <limits>
#include <optional>

#include "core/common/error.h"

namespace rockface::app {

namespace {

// The surface point under `pixel` nearest the camera: barycentric in the
// pixels of each triangle that holds it.
std::optional<Eigen::Vector3d> surface_under(const Eigen::Vector2d& pixel,
                                             const std::vector<Eigen::Vector3d>& vertices,
                                             const std::vector<std::array<int, 3>>& triangles,
                                             const std::vector<Eigen::Vector2f>& pixels,
                                             const Eigen::Vector3d& camera_centre) {
  std::optional<Eigen::Vector3d> best;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& t : triangles) {
    const Eigen::Vector2d a = pixels[static_cast<std::size_t>(t[0])].cast<double>();
    const Eigen::Vector2d b = pixels[static_cast<std::size_t>(t[1])].cast<double>();
    const Eigen::Vector2d c = pixels[static_cast<std::size_t>(t[2])].cast<double>();
    const double area = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (area == 0) continue;
    const double wb =
        ((pixel.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (pixel.y() - a.y())) / area;
    const double wc =
        ((b.x() - a.x()) * (pixel.y() - a.y()) - (pixel.x() - a.x()) * (b.y() - a.y())) / area;
    const double wa = 1 - wb - wc;
    // 1e-9: a pick exactly on an edge or a vertex belongs to its triangles.
    if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
    const Eigen::Vector3d p = wa * vertices[static_cast<std::size_t>(t[0])] +
                              wb * vertices[static_cast<std::size_t>(t[1])] +
                              wc * vertices[static_cast<std::size_t>(t[2])];
    const double d = (p - camera_centre).norm();
    if (d < nearest) {
      nearest = d;
      best = p;
    }
  }
  return best;
}

}  // namespace

photogrammetry::ControlPointRegistration register_import_to_control(
    const std::string& gcp_file, const std::vector<Eigen::Vector3d>& vertices,
    const std::vector<std::array<int, 3>>& triangles, const std::vector<Eigen::Vector2f>& pixels,
    const Eigen::Vector3d& camera_centre) {
  std::ifstream in(gcp_file);
  if (!in) throw InputError(gcp_file, "cannot open the control points' file");
  const std::vector<photogrammetry::ControlPoint> points =
      photogrammetry::parse_control_points(in, gcp_file);
  if (points.size() < 3)
    throw InputError(gcp_file, "ground control needs three points at least, the file has " +
                                   std::to_string(points.size()));
  std::vector<Eigen::Vector3d> picked;
  for (const auto& p : points) {
    const auto on = surface_under(p.pixel, vertices, triangles, pixels, camera_centre);
    if (!on)
      throw InputError(gcp_file, "point " + p.id + ": its pixel " + std::to_string(p.pixel.x()) +
                                     ", " + std::to_string(p.pixel.y()) +
                                     " is on no surface of the view");
    picked.push_back(*on);
  }
  return photogrammetry::register_to_control_points(picked, points, gcp_file);
}

}  // namespace rockface::app

#include "core/rockmass/face_window.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/common/error.h"
#include "core/geometry/plane_fit.h"

namespace rockface::rockmass {

Eigen::Vector2d FaceWindow::to_face(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d d = p - origin;
  return {d.dot(h), d.dot(v)};
}

Eigen::Vector3d FaceWindow::to_space(const Eigen::Vector2d& q) const {
  return origin + q.x() * h + q.y() * v;
}

Eigen::Vector3d FaceWindow::direction(double angle_deg) const {
  const double a = angle_deg * M_PI / 180.0;
  return std::cos(a) * h + std::sin(a) * v;
}

namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

// Andrew's monotone chain, counter-clockwise, collinear points dropped.
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0) --k;
    hull[k++] = p[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

FaceWindow face_window(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 3)
    throw InputError("face", "needs at least three mapped points to make a window, got " +
                                 std::to_string(points.size()));
  const geometry::PlaneFit fit = geometry::fit_plane(points);
  FaceWindow w;
  w.origin = fit.centroid;
  w.normal = fit.normal;
  // h horizontal in the face; a (near) horizontal face takes east.
  Eigen::Vector3d h = Eigen::Vector3d::UnitZ().cross(w.normal);
  if (h.norm() < 1e-6) h = Eigen::Vector3d::UnitX();
  w.h = h.normalized();
  w.v = w.normal.cross(w.h).normalized();
  if (w.v.z() < 0) {  // v up the face
    w.v = -w.v;
    w.h = -w.h;
  }
  std::vector<Eigen::Vector2d> flat;
  flat.reserve(points.size());
  for (const auto& p : points) flat.push_back(w.to_face(p));
  w.outline = convex_hull(flat);
  double twice = 0;
  for (std::size_t i = 0; i < w.outline.size(); ++i) {
    const auto& a = w.outline[i];
    const auto& b = w.outline[(i + 1) % w.outline.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  w.area_m2 = 0.5 * std::abs(twice);
  if (w.outline.size() < 3 || w.area_m2 <= 0)
    throw InputError("face", "the mapped points lie on a line: no window to sample");
  return w;
}

}  // namespace rockface::rockmass

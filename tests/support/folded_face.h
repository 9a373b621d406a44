#pragma once
// A 3D image built without photogrammetry, for the measurement tests: a
// folded rock face (planar facets side by side) seen by a pinhole camera,
// triangulated on the lattice of the camera's pixels like
// photogrammetry::triangulate_lattice (every vertex on the ray of its pixel),
// optionally with depth noise along the rays. Joints cut it in known traces.
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/geometry/plane.h"
#include "core/measure/photo_view.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::test {

struct Facet {
  geometry::Plane plane;
  double x_from, x_to;  // East extent
};

struct FoldedFace {
  std::vector<Facet> facets;
  double z_from = -2.0, z_to = 2.5;  // the face's vertical extent: above it, no surface
  measure::PhotoView view;
  photogrammetry::SurfaceMesh mesh;

  // The nearest facet point along a ray, if any.
  std::optional<Eigen::Vector3d> hit(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const {
    std::optional<Eigen::Vector3d> nearest;
    double nearest_t = 0;
    for (const Facet& f : facets) {
      const double den = f.plane.normal.dot(d);
      if (std::abs(den) < 1e-12) continue;
      const double t = (f.plane.offset - f.plane.normal.dot(o)) / den;
      const Eigen::Vector3d p = o + t * d;
      if (t > 0 && p.x() >= f.x_from && p.x() <= f.x_to && p.z() >= z_from && p.z() <= z_to &&
          (!nearest || t < nearest_t)) {
        nearest = p;
        nearest_t = t;
      }
    }
    return nearest;
  }

  // The straight trace of a joint on facet k, as its two end points.
  std::optional<std::array<Eigen::Vector3d, 2>> trace_on(const geometry::Plane& joint,
                                                         std::size_t k) const {
    const Facet& f = facets[k];
    const Eigen::Vector3d dir = f.plane.normal.cross(joint.normal);
    if (dir.norm() < 1e-9) return std::nullopt;
    // A point on both planes: least-norm solution of the two equations.
    Eigen::Matrix<double, 2, 3> A;
    A.row(0) = f.plane.normal;
    A.row(1) = joint.normal;
    const Eigen::Vector3d p0 = A.transpose() * (A * A.transpose()).inverse() *
                               Eigen::Vector2d(f.plane.offset, joint.offset);
    // Clip the line to the facet's x and z ranges.
    double lo = -1e9, hi = 1e9;
    auto clip = [&](double p, double d, double a, double b) {
      if (std::abs(d) < 1e-12) {
        if (p < a || p > b) lo = 1, hi = 0;
        return;
      }
      double t0 = (a - p) / d, t1 = (b - p) / d;
      if (t0 > t1) std::swap(t0, t1);
      lo = std::max(lo, t0);
      hi = std::min(hi, t1);
    };
    clip(p0.x(), dir.x(), f.x_from, f.x_to);
    clip(p0.z(), dir.z(), z_from, z_to);
    if (lo >= hi) return std::nullopt;
    return std::array<Eigen::Vector3d, 2>{p0 + lo * dir, p0 + hi * dir};
  }
};

inline void look_at_lattice(FoldedFace& f, int width, int height, double depth_sigma,
                            int lattice_step);

inline geometry::Plane plane_through(double dip_deg, double dipdir_deg, const Eigen::Vector3d& p) {
  return geometry::Plane::from_orientation({deg_to_rad(dip_deg), deg_to_rad(dipdir_deg)}, p);
}

// Three facets about 10 m north of a camera looking north: the height field
// y = 10 + 0.3 z + b_k x + c_k, continuous, folded along x = -1.5 and x = 1.5
// (b = -0.5, 0, 0.6: roughly 72/153, 73/180, 71/211). `depth_sigma` m of
// noise along the rays.
inline FoldedFace folded_face(int width = 800, int height = 600, double depth_sigma = 0,
                              int lattice_step = 2) {
  FoldedFace f;
  const double a = 0.3;
  const double slopes[3] = {-0.5, 0.0, 0.6}, edges[4] = {-4.5, -1.5, 1.5, 4.5};
  double c = 10.0 - slopes[0] * edges[1];  // facet 0 meets facet 1 (c = 10) at x = -1.5
  for (int k = 0; k < 3; ++k) {
    if (k > 0) c += (slopes[k - 1] - slopes[k]) * edges[k];
    geometry::Plane p;
    p.normal = Eigen::Vector3d(slopes[k], -1.0, a).normalized();
    p.offset = p.normal.dot(Eigen::Vector3d(edges[k], c + slopes[k] * edges[k], 0.0));
    f.facets.push_back({p, edges[k], edges[k + 1]});
  }
  look_at_lattice(f, width, height, depth_sigma, lattice_step);
  return f;
}

// The camera 0.5 m above the origin looking north, and the 3D image of
// `f.facets` on its pixel lattice (every `lattice_step` px), with
// `depth_sigma` m of noise along the rays.
inline void look_at_lattice(FoldedFace& f, int width, int height, double depth_sigma,
                            int lattice_step) {
  photogrammetry::CameraIntrinsics cam;
  cam.width = width;
  cam.height = height;
  cam.fx = cam.fy = 0.8 * width;
  cam.cx = 0.5 * (width - 1);
  cam.cy = 0.5 * (height - 1);
  f.view.name = "left";
  f.view.camera = cam;
  // Camera axes: x East, y down (= -Up), z North.
  f.view.pose.R << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  f.view.pose.centre = Eigen::Vector3d(0, 0, 0.5);

  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  const int cols = (width - 1) / lattice_step + 1, rows = (height - 1) / lattice_step + 1;
  std::vector<int> index(static_cast<std::size_t>(cols) * rows, -1);
  auto& m = f.mesh;
  m.texture_width = width;
  m.texture_height = height;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const Eigen::Vector2d px(c * lattice_step, r * lattice_step);
      const measure::Ray ray = measure::ray_through_pixel(f.view, px, "lattice");
      auto p = f.hit(ray.origin, ray.direction);
      if (!p) continue;
      if (depth_sigma > 0) *p += depth_sigma * noise(rng) * ray.direction;
      index[static_cast<std::size_t>(r) * cols + c] = static_cast<int>(m.vertices.size());
      m.vertices.push_back(*p);
      m.pixels.push_back(px.cast<float>());
      m.texcoords.emplace_back(static_cast<float>((px.x() + 0.5) / width),
                               static_cast<float>(1.0 - (px.y() + 0.5) / height));
      m.colours.push_back({128, 128, 128});
    }
  auto at = [&](int r, int c) { return index[static_cast<std::size_t>(r) * cols + c]; };
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < cols; ++c) {
      const int v00 = at(r, c), v10 = at(r + 1, c), v01 = at(r, c + 1), v11 = at(r + 1, c + 1);
      if (v00 >= 0 && v10 >= 0 && v01 >= 0) m.triangles.push_back({v00, v10, v01});
      if (v01 >= 0 && v10 >= 0 && v11 >= 0) m.triangles.push_back({v01, v10, v11});
    }
}

// Pixels of world points in the face's view.
inline std::vector<Eigen::Vector2d> pixels_of(const FoldedFace& f,
                                              const std::vector<Eigen::Vector3d>& points) {
  return measure::project_to_view(f.view, points);
}

}  // namespace rockface::test

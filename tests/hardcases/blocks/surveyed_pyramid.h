#pragma once
// Pyramids of four or more joints through one surveyed vertex on a free face
// z = 0 (issue 40), their exact volume from a 2D clip (no 3D construction),
// and the draws the shared-vertex tests share.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/construction.h"
#include "core/blocks/polyhedron.h"
#include "core/geometry/orientation.h"
#include "tests/core/blocks/block_shapes.h"

namespace rockface::blocks::test {

// A pyramid: joints through `apex` with the rock below each (their upward
// normals point out of the block), on the free face z = 0 (rock above).
struct Pyramid {
  Eigen::Vector3d apex;
  std::vector<Eigen::Vector3d> normals;  // upward unit normals of the joints
  std::vector<Eigen::Vector3d> points;   // a point of each joint
};

inline std::vector<HalfSpaceInput> halfspaces(const Pyramid& p) {
  std::vector<HalfSpaceInput> h;
  for (size_t k = 0; k < p.normals.size(); ++k)
    h.push_back(halfspace(static_cast<int>(k), "J" + std::to_string(k), PlaneKind::Joint,
                          p.normals[k], p.points[k], geometry::HalfSpace::Lower));
  h.push_back(halfspace(static_cast<int>(p.normals.size()), "F", PlaneKind::FreeFace,
                        Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Zero(),
                        geometry::HalfSpace::Upper));
  return h;
}

// The exact pyramid's base on z = 0 when every joint passes through the
// apex: the polygon n_k . (x - apex) <= 0 of all k (a square clipped by
// half-planes, no 3D construction).
inline std::vector<Eigen::Vector2d> exact_base(const Pyramid& p) {
  std::vector<Eigen::Vector2d> poly{{-1e3, -1e3}, {1e3, -1e3}, {1e3, 1e3}, {-1e3, 1e3}};
  for (const auto& n : p.normals) {
    const Eigen::Vector2d a(n.x(), n.y());
    const double c = n.dot(p.apex);
    std::vector<Eigen::Vector2d> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      const Eigen::Vector2d& u = poly[i];
      const Eigen::Vector2d& v = poly[(i + 1) % poly.size()];
      const double fu = a.dot(u) - c, fv = a.dot(v) - c;
      if (fu <= 0) out.push_back(u);
      if ((fu < 0 && fv > 0) || (fu > 0 && fv < 0)) out.push_back(u + fu / (fu - fv) * (v - u));
    }
    poly = out;
  }
  return poly;
}

// The exact volume: a cone over its base, times height / 3.
inline double exact_volume(const Pyramid& p) {
  const std::vector<Eigen::Vector2d> poly = exact_base(p);
  double area2 = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& u = poly[i];
    const Eigen::Vector2d& v = poly[(i + 1) % poly.size()];
    area2 += u.x() * v.y() - u.y() * v.x();
  }
  return area2 / 2 * p.apex.z() / 3;
}

// The joints that bound a face of the exact pyramid: those with an edge of
// its base (longer than 1 mm, its ends within 1e-9 m of the joint's line:
// rounding of coordinates of metres is ~1e-15).
inline std::vector<int> bounding_joints(const Pyramid& p) {
  const std::vector<Eigen::Vector2d> poly = exact_base(p);
  std::vector<int> out;
  for (size_t k = 0; k < p.normals.size(); ++k) {
    const Eigen::Vector3d& n = p.normals[k];
    const Eigen::Vector2d a(n.x(), n.y());
    const double c = n.dot(p.apex), len = a.norm();
    for (size_t i = 0; i < poly.size(); ++i) {
      const Eigen::Vector2d& u = poly[i];
      const Eigen::Vector2d& v = poly[(i + 1) % poly.size()];
      if (std::abs(a.dot(u) - c) <= 1e-9 * len && std::abs(a.dot(v) - c) <= 1e-9 * len &&
          (u - v).norm() > 1e-3) {
        out.push_back(static_cast<int>(k));
        break;
      }
    }
  }
  return out;
}

inline double surface_area(const Polyhedron& p) {
  double s = 0;
  for (const Face& f : p.faces()) {
    Eigen::Vector3d a2 = Eigen::Vector3d::Zero();
    const auto& x = p.vertices();
    for (size_t k = 1; k + 1 < f.loop.size(); ++k)
      a2 += (x[f.loop[k]] - x[f.loop[0]]).cross(x[f.loop[k + 1]] - x[f.loop[0]]);
    s += a2.norm() / 2;
  }
  return s;
}

// m joints around a vertical through a random apex 4-5 m up, dipping 40-70
// degrees toward directions spread around the compass (each gap < 180
// degrees: a bounded pyramid).
inline Pyramid random_pyramid(std::mt19937_64& rng, int m) {
  std::uniform_real_distribution<double> u(0, 1);
  Pyramid p;
  p.apex = Eigen::Vector3d(3 * u(rng), 2 * u(rng), 4 + u(rng));
  const double turn = 360 * u(rng);
  for (int k = 0; k < m; ++k) {
    const double dipdir = std::fmod(turn + 360.0 * k / m + 20 * (u(rng) - 0.5) + 360, 360);
    p.normals.push_back(geometry::plane_normal_deg(40 + 30 * u(rng), dipdir));
    p.points.push_back(p.apex);
  }
  return p;
}

inline std::string text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

inline double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

}  // namespace rockface::blocks::test

#pragma once
// Seeded draws of two joint sets a few thousandths of a degree apart with a
// third set and the tunnel's axis at random (issue 40), and their wedges
// around a 6 m horseshoe at an orientation uncertainty of 1e-4 degree: the
// draws the near-parallel tests share.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/orientation.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::tunnel::test {

inline constexpr double kRad = std::numbers::pi / 180.0;

struct Draw {
  double dip1, dir1;     // J1, degrees
  double apart, turn;    // J2 is J1 turned by `apart` deg toward `turn` (deg)
  double dip3, dir3;     // J3
  double trend, plunge;  // the axis
};

// `count` draws from seed 40, J2 apart from J1 log-uniformly over
// [lo_deg, hi_deg] (the first draws of a longer list are the shorter
// list's).
inline std::vector<Draw> draws(int count, double lo_deg = 0.001, double hi_deg = 0.04) {
  std::mt19937_64 rng(40);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Draw> out;
  for (int i = 0; i < count; ++i) {
    Draw d;
    d.dip1 = 20 + 65 * u(rng);
    d.dir1 = 360 * u(rng);
    d.apart = lo_deg * std::pow(hi_deg / lo_deg, u(rng));
    d.turn = 360 * u(rng);
    d.dip3 = 20 + 65 * u(rng);
    d.dir3 = 360 * u(rng);
    d.trend = 360 * u(rng);
    d.plunge = 5 * u(rng);
    out.push_back(d);
  }
  return out;
}

// J1's normal turned by `apart` about an axis square to it, chosen by `turn`.
inline Eigen::Vector3d turned(const Eigen::Vector3d& n, double apart_deg, double turn_deg) {
  const Eigen::Vector3d a = n.unitOrthogonal();
  const Eigen::Vector3d b = n.cross(a);
  const Eigen::Vector3d about = std::cos(turn_deg * kRad) * a + std::sin(turn_deg * kRad) * b;
  return Eigen::AngleAxisd(apart_deg * kRad, about) * n;
}

// The draw's wedges, J2's angle from J1 multiplied by angle_factor.
inline WedgeAnalysis analyse(Draw d, double angle_factor = 1) {
  d.apart *= angle_factor;
  const Eigen::Vector3d n1 = geometry::plane_normal_deg(d.dip1, d.dir1);
  std::vector<WedgeJointSet> sets{{"J1", n1, 30 * kRad, 0},
                                  {"J2", turned(n1, d.apart, d.turn), 30 * kRad, 0},
                                  {"J3", geometry::plane_normal_deg(d.dip3, d.dir3), 30 * kRad, 0}};
  WedgeOptions o;
  o.uncertainty = 1e-4 * kRad;
  return analyse_wedges(
      horseshoe_profile(3.0, 1.0, 5.0, -1.5),
      axis_frame(d.trend * kRad, d.plunge * kRad, Eigen::Vector3d::Zero(), "axis"),
      Eigen::Vector3d::Zero(), sets, o);
}

}  // namespace rockface::tunnel::test

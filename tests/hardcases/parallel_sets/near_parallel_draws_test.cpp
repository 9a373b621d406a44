// Two joint sets 0.001 to 0.04 degrees apart, drawn at random with a third
// set and the tunnel's axis, at an orientation uncertainty of 1e-4 degree
// (issue 40): 5 of 133 such draws gave "could not be built" (the thin
// pyramid's end piece was unbounded). Every pyramid of every draw must give
// its wedge, or an honest "no wedge" whose margin says why; nothing left
// unbuilt. The truth a wedge is checked against is the limit: a wedge
// between two sets that coincide has no volume, so its volume grows in
// proportion to their angle (a 1 % wider angle, a 1 % larger wedge, to
// the second order's share).
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry/orientation.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::tunnel {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;

struct Draw {
  double dip1, dir1;     // J1, degrees
  double apart, turn;    // J2 is J1 turned by `apart` deg toward `turn` (deg)
  double dip3, dir3;     // J3
  double trend, plunge;  // the axis
};

std::vector<Draw> draws(int count) {
  std::mt19937_64 rng(40);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Draw> out;
  for (int i = 0; i < count; ++i) {
    Draw d;
    d.dip1 = 20 + 65 * u(rng);
    d.dir1 = 360 * u(rng);
    // Log-uniform over 0.001..0.04 degrees.
    d.apart = 0.001 * std::pow(40.0, u(rng));
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
Eigen::Vector3d turned(const Eigen::Vector3d& n, double apart_deg, double turn_deg) {
  const Eigen::Vector3d a = n.unitOrthogonal();
  const Eigen::Vector3d b = n.cross(a);
  const Eigen::Vector3d about = std::cos(turn_deg * kRad) * a + std::sin(turn_deg * kRad) * b;
  return Eigen::AngleAxisd(apart_deg * kRad, about) * n;
}

WedgeAnalysis analyse(Draw d, double angle_factor = 1) {
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

TEST(NearParallelSetDraws, NoPyramidIsLeftUnbuilt) {
  int unbuilt = 0, wedges = 0, compared = 0;
  const std::vector<Draw> all = draws(133);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Draw& d = all[i];
    std::ostringstream what;
    what.precision(12);
    what << "draw " << i << ": J1 " << d.dip1 << "/" << d.dir1 << ", J2 turned " << d.apart
         << " deg toward " << d.turn << ", J3 " << d.dip3 << "/" << d.dir3 << ", axis " << d.trend
         << "/" << d.plunge;
    SCOPED_TRACE(what.str());
    const WedgeAnalysis a = analyse(d);
    wedges += static_cast<int>(a.wedges.size());
    for (const NoWedge& n : a.none) {
      if (n.unbuilt) ++unbuilt;
      EXPECT_FALSE(n.unbuilt) << n.code << ": " << n.reason;
      EXPECT_EQ(n.reason.find("could not be built"), std::string::npos)
          << n.code << ": " << n.reason;
    }
    // The angle 1 % wider: each wedge found at both is 1 % larger. V = a t
    // + b t^2 + ...: the higher orders make V(2t) / V(t) fall short of 2
    // by up to 0.21 on these draws (measured: 1.79-2.00; a sector edge
    // moves with the angle and the apex with it), so b t / a <= 0.27 and
    // they move V(1.01 t) / V(t) by under 0.01 x 0.27 = 0.0027; the
    // vertices' rounding (1e-8 m on wedges of 10 m) adds under 1e-4. A
    // wedge with a piece lost or doubled would be off by far more.
    std::map<std::string, double> volume_wider;
    for (const Wedge& w : analyse(d, 1.01).wedges) volume_wider[w.code] = w.mass.volume;
    for (const Wedge& w : a.wedges) {
      EXPECT_GT(w.mass.volume, 0) << w.code;
      if (std::abs(w.removable.margin) <= 1e-4 * kRad) {
        EXPECT_TRUE(w.removable.marginal) << w.code;
      }
      const auto wider = volume_wider.find(w.code);
      if (wider == volume_wider.end()) continue;
      ++compared;
      EXPECT_NEAR(wider->second / w.mass.volume, 1.01, 0.003) << w.code;
    }
  }
  // Most wedges are found at both angles (a wedge may come or go where its
  // margin is within the change of angle).
  EXPECT_GT(compared, wedges * 9 / 10);
  std::cout << "near-parallel draws: " << wedges << " wedges (" << compared
            << " compared at a 1 % wider angle), " << unbuilt << " unbuilt\n";
}

}  // namespace
}  // namespace rockface::tunnel

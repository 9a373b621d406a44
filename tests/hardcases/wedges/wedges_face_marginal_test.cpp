// A pyramid that opens toward the tunnel but is removable from the face
// only within the uncertainty (issue 40): an edge of it runs into the rock
// ahead of the face, so its face wedge has no finite size. The triangle it
// cuts from the face was found by dividing by the edges' distance behind
// the face (negative there) and the wedge came out "could not be built:
// face wedge ... is not a bounded solid" with a margin of 0 and no flag.
// It is a marginal "no wedge" now, and every "no wedge" whose margin is
// inside the uncertainty says it is marginal.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry/orientation.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::tunnel {
namespace {

constexpr double kRad = std::numbers::pi / 180;

struct Draw {
  double sets[3][2];  // dip, dip direction (degrees)
  double trend;       // the axis's, degrees (plunge 0)
  const char* code;   // the pyramid that was "not a bounded solid"
};

// Random draws (seeded sets and axes) that gave the unbuilt face wedge.
const Draw kDraws[] = {
    {{{64.710091249, 20.817389925}, {42.753506391, 80.898958879}, {33.243793271, 104.331269339}},
     183.086044,
     "001"},
    {{{60.099361971, 139.108141677}, {83.220326516, 348.362730430}, {33.555690517, 106.212774039}},
     162.486485,
     "101"},
    {{{66.510667991, 61.518784333}, {80.616051292, 261.986190916}, {49.784135769, 114.228894049}},
     73.793547,
     "101"},
};

TEST(WedgesFaceMarginal, AFaceWedgeReachingAheadIsAMarginalNoWedgeNotAnUnbuiltOne) {
  for (const Draw& d : kDraws) {
    SCOPED_TRACE(std::string("pyramid ") + d.code);
    std::vector<WedgeJointSet> sets;
    for (int k = 0; k < 3; ++k)
      sets.push_back({"J" + std::to_string(k + 1),
                      geometry::plane_normal_deg(d.sets[k][0], d.sets[k][1]), 30 * kRad, 0});
    WedgeOptions o;
    o.uncertainty = 2 * kRad;
    const WedgeAnalysis a =
        analyse_wedges(horseshoe_profile(3, 1, 5, -1.5),
                       axis_frame(d.trend * kRad, 0, Eigen::Vector3d::Zero(), "axis"),
                       Eigen::Vector3d::Zero(), sets, o);
    bool listed = false;
    for (const NoWedge& n : a.none) {
      EXPECT_FALSE(n.unbuilt) << n.code << ": " << n.reason;
      if (std::abs(n.margin) <= o.uncertainty) {
        EXPECT_TRUE(n.marginal) << n.code << ": " << n.reason;
      }
      if (n.code != d.code) continue;
      listed = true;
      EXPECT_TRUE(n.marginal) << n.reason;
      EXPECT_LE(n.margin, 0) << n.reason;
      EXPECT_NE(n.reason.find("no finite size"), std::string::npos) << n.reason;
    }
    EXPECT_TRUE(listed);
    for (const Wedge& w : a.wedges) EXPECT_NE(w.code, d.code);
  }
}

}  // namespace
}  // namespace rockface::tunnel

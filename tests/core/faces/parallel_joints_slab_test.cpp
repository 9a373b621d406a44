// Blocks between two exactly parallel joints, the joints turned by a
// hundredth of a degree (issue 43's round trip: J2 / J5 and J1 / J4 of the
// imported pyramid flipped between finite and infinite, and lost their
// removability, through a mesh's rounding). Without any import: a level
// rock top, two parallel joints JA and JB (80/000) 0.6 m apart along their
// normal, and three cross-cutting loops on the top:
//   B1, closed: between JD (60/090) and JC (60/270), which meet 3.46 m
//       down: a prism of the slab, finite, its volume worked here; it can
//       only slide out between JA and JB (its joint pyramid lies in their
//       plane): removable, marginal.
//   B3, open: between JC and JE (60/090), a V widening downward: the slab
//       never ends down the V, infinite.
//   B2, open: between JE and JF (30/090), both dipping east, widening with
//       depth: infinite.
// Every seed turns each joint's dip and dip direction by up to +-0.01
// degree (JA and JB then meet a few km away, converging or diverging): the
// verdicts must be those of the exactly parallel joints for every seed,
// with the same marginal flags, and the infinite blocks' margin the angle
// by which their cone is open within the joints' plane (found here by
// sweeping the plane's directions, not by the code under test).
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "tests/core/faces/trace_map_run.h"

namespace rockface::faces {
namespace {

constexpr double kSnap = 0.05;           // m
constexpr double kSpacing = 0.6;         // m along the normal of JA and JB
constexpr double kTurnDeg = 0.01;        // the largest turn of a dip or a dip direction
constexpr double kUncertaintyDeg = 1.0;  // the scene's default orientation uncertainty
constexpr double kWidthB1 = 4.0;         // m: JD at x = 0, JC at x = 4 on the top

struct JointLine {
  std::string id;
  double dip, dipdir;  // degrees
  Eigen::Vector3d through;
};

// The joints, each through a point of the top (z = 0). JB: JA moved
// kSpacing along the normal, where it cuts the top (y = kSpacing / sin 80).
std::vector<JointLine> nominal_joints() {
  const double yb = kSpacing / std::sin(deg_to_rad(80));
  return {{"JA", 80, 0, {0, 0, 0}},   {"JB", 80, 0, {0, yb, 0}}, {"JD", 60, 90, {0, 0, 0}},
          {"JC", 60, 270, {4, 0, 0}}, {"JE", 60, 90, {7, 0, 0}}, {"JF", 30, 90, {10, 0, 0}}};
}

std::vector<PatchInput> level_top() {
  using V = Eigen::Vector3d;
  // Counter-clockwise seen from above: the rock is below.
  return {{"TOP", {V(-2, -2, 0), V(13, -2, 0), V(13, 3, 0), V(-2, 3, 0)}}};
}

// Each joint's trace: where its plane cuts the top, from the point it passes
// through, far enough each way to cross the joints it meets (JA and JB run
// east-west from x = -1 to 11, the others north-south from y = -1 to 1.6).
std::vector<TraceInput> traces_of(const std::vector<JointLine>& joints) {
  std::vector<TraceInput> out;
  int index = 0;
  for (const auto& j : joints) {
    TraceJoint tj;
    tj.index = index++;
    tj.id = j.id;
    tj.orientation = {deg_to_rad(j.dip), deg_to_rad(j.dipdir)};
    tj.friction = deg_to_rad(35);
    const Eigen::Vector3d n = geometry::plane_normal(tj.orientation);
    Eigen::Vector3d along = n.cross(Eigen::Vector3d::UnitZ()).normalized();
    const bool east_west = std::abs(along.x()) > std::abs(along.y());
    if ((east_west ? along.x() : along.y()) < 0) along = -along;
    const double from = east_west ? -1 - j.through.x() : -1 - j.through.y();
    const double to = east_west ? 11 - j.through.x() : 1.6 - j.through.y();
    TraceInput t{"T" + j.id, tj, {}};
    for (int k = 0; k <= 10; ++k) {
      // Along the trace by its x (or y) coordinate: the trace's direction
      // is that axis turned by at most the seed's turn.
      const double s = from + (to - from) * k / 10;
      const double c = east_west ? along.x() : along.y();
      t.points.push_back(j.through + along * (s / c));
    }
    out.push_back(std::move(t));
  }
  return out;
}

// The largest angle by which a direction in the plane of normal `axis` stays
// inside every half-space n . d >= 0 (negative: shut by that angle), by
// sweeping the plane's directions every 1e-5 rad: the max-min has slope at
// most 1 in the direction's angle, so it is found to 5e-6 rad.
double in_plane_opening(const Eigen::Vector3d& axis, const std::vector<Eigen::Vector3d>& inward) {
  const Eigen::Vector3d u = axis.cross(Eigen::Vector3d::UnitX()).normalized();
  const Eigen::Vector3d w = axis.cross(u).normalized();
  double best = -INFINITY;
  const int steps = static_cast<int>(2 * M_PI / 1e-5);
  for (int k = 0; k < steps; ++k) {
    const double phi = k * 1e-5;
    const Eigen::Vector3d d = std::cos(phi) * u + std::sin(phi) * w;
    double worst = INFINITY;
    for (const auto& n : inward) worst = std::min(worst, std::asin(n.dot(d)));
    best = std::max(best, worst);
  }
  return best;
}

std::vector<std::string> trace_ids(const TraceBlock& b, const std::vector<TraceInput>& traces) {
  std::vector<std::string> ids;
  for (int t : b.traces) ids.push_back(traces[t].id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

TEST(ParallelJointsSlab, VerdictsOfTheExactlyParallelJointsWhateverTheLastHundredthOfADegree) {
  const auto nominal = nominal_joints();
  const auto normal = [&](int j) {
    return geometry::plane_normal_deg(nominal[j].dip, nominal[j].dipdir);
  };
  const Eigen::Vector3d top_in(0, 0, -1);  // the rock is below the top
  // B2 lies above (east of) JE and below (west of) JF; B3 below (east of)
  // JC and below (west of) JE: their cones within the plane of JA and JB.
  const double opening_b2 = in_plane_opening(normal(0), {top_in, normal(4), -normal(5)});
  const double opening_b3 = in_plane_opening(normal(0), {top_in, -normal(3), -normal(4)});
  // The V of B3 opens 30 degrees each side of the vertical, and the
  // directions between the 60 and 30 degree dips of B2 15 degrees each side
  // of their bisector; the joints' plane, 10 degrees off the vertical, takes
  // a little off both.
  ASSERT_GT(rad_to_deg(opening_b3), 29);
  ASSERT_LT(rad_to_deg(opening_b3), 30);
  ASSERT_GT(rad_to_deg(opening_b2), 14);
  ASSERT_LT(rad_to_deg(opening_b2), 15);

  // B1's volume: at depth t below the top it spans x in [t cot 60,
  // 4 - t cot 60] (JD and JC meet at t = 2 tan 60), and along the normal of
  // JA the slab is kSpacing thick, so kSpacing / sin 80 along y at every
  // depth: (4^2 tan 60 / 4) x (kSpacing / sin 80).
  const double volume_b1 =
      kWidthB1 * kWidthB1 * std::tan(deg_to_rad(60)) / 4 * kSpacing / std::sin(deg_to_rad(80));

  std::mt19937 rng(43);
  std::uniform_real_distribution<double> turn(-kTurnDeg, kTurnDeg);
  for (int seed = 0; seed <= 12; ++seed) {
    auto joints = nominal;
    if (seed > 0)
      for (auto& j : joints) {
        j.dip += turn(rng);
        j.dipdir += turn(rng);
      }
    SCOPED_TRACE("seed " + std::to_string(seed) + ": JA " + std::to_string(joints[0].dip) + "/" +
                 std::to_string(joints[0].dipdir) + ", JB " + std::to_string(joints[1].dip) + "/" +
                 std::to_string(joints[1].dipdir));
    const auto traces = traces_of(joints);
    const auto run =
        testing::run_trace_map(level_top(), traces, kSnap, 0.0, deg_to_rad(kUncertaintyDeg));
    ASSERT_EQ(run.blocks.size(), 3u);
    int seen = 0;
    for (const auto& b : run.blocks) {
      const auto ids = trace_ids(b, traces);
      const auto& f = b.finiteness;
      if (ids == std::vector<std::string>{"TJA", "TJB", "TJC", "TJD"}) {
        ++seen;
        EXPECT_TRUE(b.finite);
        EXPECT_TRUE(f.finite.value);
        EXPECT_FALSE(f.finite.marginal);
        ASSERT_TRUE(b.analysis);
        // Each plane turned by at most 0.014 degrees (2.5e-4 rad) moves by
        // at most 1 mm across the 4 m block: < 0.2 % of the slab's 0.6 m
        // and of the section's 3.5 m depth.
        EXPECT_NEAR(b.analysis->mass.volume, volume_b1, 0.005 * volume_b1);
        // It slides out between JA and JB or not at all: removable by
        // its cone within their plane, marginal (the cone has no width
        // across it, and JA and JB cannot be told from parallel).
        EXPECT_TRUE(f.removable.value);
        EXPECT_TRUE(f.removable.marginal);
      } else if (ids == std::vector<std::string>{"TJA", "TJB", "TJC", "TJE"} ||
                 ids == std::vector<std::string>{"TJA", "TJB", "TJE", "TJF"}) {
        ++seen;
        const double opening = ids[2] == "TJC" ? opening_b3 : opening_b2;
        EXPECT_FALSE(b.finite);
        EXPECT_FALSE(f.finite.value);
        EXPECT_FALSE(b.polyhedron) << "a block with corners " << kSpacing << " / tan(turn) away";
        // Open by its cone within the joints' plane, far more than the
        // uncertainty: not marginal. Turning the planes by at most 2.5e-4
        // rad turns that cone by as much (0.014 degrees); 0.03 degrees.
        EXPECT_FALSE(f.finite.marginal);
        EXPECT_NEAR(rad_to_deg(f.finite.margin), rad_to_deg(opening), 0.03);
        EXPECT_FALSE(f.removable.value);
        EXPECT_FALSE(f.removable.marginal);
      }
    }
    EXPECT_EQ(seen, 3);
  }
}

}  // namespace
}  // namespace rockface::faces

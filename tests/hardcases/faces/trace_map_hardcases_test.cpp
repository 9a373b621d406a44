// Trace maps that break naive code: traces crossing at a very shallow angle,
// a trace along a patch edge, a trace of one point, and the whole map moved
// to survey coordinates and turned.
#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "core/faces/surface_loops.h"
#include "core/faces/trace_blocks.h"
#include "core/faces/trace_network.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "tests/core/faces/benched_slope.h"

namespace rockface::faces {
namespace {

using testing::benched_slope_patches;
using testing::benched_slope_traces;
using testing::joint;
using testing::on_lower_face;
using V = Eigen::Vector3d;

constexpr double kSnap = 0.05;

struct Result {
  TraceNetwork network;
  SurfaceLoops loops;
  std::vector<TraceBlock> blocks;
};

Result run(const std::vector<PatchInput>& patches, const std::vector<TraceInput>& traces) {
  static kinematics::Effects effects = [] {
    kinematics::Effects e;
    e.push_back(std::make_unique<kinematics::GravityEffect>(V(0, 0, -9.81)));
    return e;
  }();
  Result r;
  const FreeSurface surface = FreeSurface::build(patches, kSnap);
  r.network = TraceNetwork::build(surface, traces, {kSnap, deg_to_rad(1.0)});
  r.loops = SurfaceLoops::find(r.network, surface);
  TraceBlockOptions o;
  o.snap_tolerance = kSnap;
  o.orientation_uncertainty = deg_to_rad(1.0);
  o.effects = &effects;
  NoProgress progress;
  r.blocks = trace_blocks(surface, r.network, r.loops, o, progress);
  return r;
}

// On the top of the slope: trace "a" runs east along y = 5; trace "b"
// crosses it at (15, 5) at `angle` degrees; the vertical joint "c" at x = 19
// cuts both, and "d" at x = 13 too. Between a and b, east of the crossing,
// lies a sliver triangle 4 tan(angle) m wide at c; west of it another one.
std::vector<TraceInput> shallow_crossing(double angle_deg) {
  const double t = std::tan(deg_to_rad(angle_deg));
  std::vector<TraceInput> tr;
  tr.push_back({"a", joint("Ja", 90, 0, 0), {V(12, 5, 12), V(20, 5, 12)}});
  // b dips 90 towards 360 - angle: its trace runs at `angle` to a.
  tr.push_back(
      {"b", joint("Jb", 90, 360 - angle_deg, 1), {V(12, 5 - 3 * t, 12), V(20, 5 + 5 * t, 12)}});
  tr.push_back({"c", joint("Jc", 90, 90, 2), {V(19, 2, 12), V(19, 8, 12)}});
  tr.push_back({"d", joint("Jd", 90, 90, 2), {V(13, 2, 12), V(13, 8, 12)}});
  return tr;
}

TEST(TraceMapHardcases, ShallowCrossingGivesSliversOnlyWhereWiderThanTheTolerance) {
  // The slivers' widths at their open ends (c at 4 m, d at 2 m from the
  // crossing) against the 5 cm tolerance decide whether they exist.
  for (double angle : {0.01, 0.1, 0.3, 0.5, 1.0, 2.0, 5.0}) {
    SCOPED_TRACE(angle);
    const Result r = run(benched_slope_patches(), shallow_crossing(angle));
    const double east = 4 * std::tan(deg_to_rad(angle)), west = 2 * std::tan(deg_to_rad(angle));
    const size_t expected = (east > kSnap ? 1 : 0) + (west > kSnap ? 1 : 0);
    EXPECT_EQ(r.loops.regions().size(), expected);
    for (const auto& region : r.loops.regions()) {
      EXPECT_EQ(region.loops.size(), 1u);
      EXPECT_EQ(region.loops.front().size(), 3u);  // a triangle, no stray corner
      EXPECT_GT(region.area, 0);
    }
  }
}

TEST(TraceMapHardcases, ShallowCrossingStaysPutUnderTinyPerturbation) {
  // Moving b's points by 1 mm across moves the crossing by 1 mm / sin(angle)
  // along a, but never changes which loops exist.
  for (double angle : {0.3, 2.0, 5.0}) {
    SCOPED_TRACE(angle);
    auto base = shallow_crossing(angle), moved = base;
    for (auto& p : moved[1].points) p.y() += 0.001;
    EXPECT_EQ(run(benched_slope_patches(), base).loops.regions().size(),
              run(benched_slope_patches(), moved).loops.regions().size());
  }
}

TEST(TraceMapHardcases, TraceAlongAPatchEdgeIsThatEdge) {
  // A joint dipping 80 out of the face through the crest line, marked along
  // the crest (a little off it, within the tolerance): it splits block B of
  // the benched slope into the part on the face and the part on the bench.
  auto traces = benched_slope_traces();
  traces.push_back({"crest", joint("J80c", 80, 270, 9), {V(3.01, 11, 6.0), V(2.995, 17, 5.99)}});
  const Result r = run(benched_slope_patches(), traces);
  // A, C, and B in two.
  ASSERT_EQ(r.loops.regions().size(), 4u);
  int face_part = 0, bench_part = 0;
  for (const auto& region : r.loops.regions()) {
    if (region.patches == std::vector<int>{1} && region.traces.size() == 4 &&
        std::find(region.traces.begin(), region.traces.end(), 12) != region.traces.end()) {
      ++face_part;
      // Between z = 3 and the crest on the face: 4 m x 3 sqrt(5) / 2 m.
      EXPECT_NEAR(region.area, 4 * 1.5 * std::sqrt(5.0), 1e-6);  // snapped onto the exact edge
    }
    if (region.patches == std::vector<int>{2}) {
      ++bench_part;
      EXPECT_NEAR(region.area, 4 * 2, 1e-6);  // 4 m x 2 m of bench, edge exact
    }
  }
  EXPECT_EQ(face_part, 1);
  EXPECT_EQ(bench_part, 1);
  for (const auto& b : r.blocks) {
    if (r.loops.regions()[b.region].patches == std::vector<int>{1} &&
        std::find(b.traces.begin(), b.traces.end(), 12) != b.traces.end()) {
      EXPECT_TRUE(b.finite);  // under the crest joint, above the 20 degree joint
    }
    if (r.loops.regions()[b.region].patches == std::vector<int>{2}) {
      EXPECT_FALSE(b.finite);  // behind a joint that leans out: widens with depth
    }
  }
}

TEST(TraceMapHardcases, TraceOfOnePointIsRejectedByNameAndTheRestGoesOn) {
  auto traces = benched_slope_traces();
  traces.insert(traces.begin() + 3, {"dot", joint("Jy", 90, 0, 0), {on_lower_face(6, 2)}});
  const Result r = run(benched_slope_patches(), traces);
  ASSERT_EQ(r.network.notes().size(), 1u);
  EXPECT_NE(r.network.notes()[0].find("traces[3] (dot)"), std::string::npos);
  EXPECT_NE(r.network.notes()[0].find("has 1 point"), std::string::npos);
  EXPECT_EQ(r.blocks.size(), 3u);
}

TEST(TraceMapHardcases, SameBlocksInSurveyCoordinatesAndTurned) {
  // The benched slope turned by 37 degrees about the vertical and moved to
  // survey coordinates (the core works in whatever frame it is given).
  const double turn = 37;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(-deg_to_rad(turn), V::UnitZ()).toRotationMatrix();
  const V shift(512340.0, 5211870.0, 410.0);
  auto patches = benched_slope_patches();
  for (auto& p : patches)
    for (auto& x : p.polygon) x = R * x + shift;
  auto traces = benched_slope_traces();
  for (auto& t : traces) {
    for (auto& x : t.points) x = R * x + shift;
    // Turning the frame clockwise seen from above adds to every azimuth.
    t.joint->orientation.dipdir =
        geometry::wrap_azimuth(t.joint->orientation.dipdir + deg_to_rad(turn));
  }
  const Result ref = run(benched_slope_patches(), benched_slope_traces());
  const Result moved = run(patches, traces);
  ASSERT_EQ(moved.blocks.size(), ref.blocks.size());
  for (const auto& b : ref.blocks) {
    auto same = std::find_if(moved.blocks.begin(), moved.blocks.end(), [&](const TraceBlock& m) {
      auto x = m.traces, y = b.traces;
      std::sort(x.begin(), x.end());
      std::sort(y.begin(), y.end());
      return x == y;
    });
    ASSERT_NE(same, moved.blocks.end());
    EXPECT_EQ(same->finite, b.finite);
    EXPECT_EQ(same->convex, b.convex);
    if (b.analysis) {
      ASSERT_TRUE(same->analysis);
      // Coordinates of 5e6 m carry ~1e-9 m of rounding; volumes of ~10 m^3
      // then agree to ~1e-8 relative.
      EXPECT_NEAR(same->analysis->mass.volume, b.analysis->mass.volume,
                  1e-6 * b.analysis->mass.volume);
      EXPECT_NEAR(same->finiteness.removable.margin, b.finiteness.removable.margin, 1e-9);
    }
  }
}

}  // namespace
}  // namespace rockface::faces

#include "core/faces/surface_loops.h"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "core/faces/trace_network.h"
#include "tests/core/faces/benched_slope.h"

namespace rockface::faces {
namespace {

using testing::benched_slope_loops;
using testing::benched_slope_patches;
using testing::benched_slope_traces;

constexpr double kSnap = 0.05;

struct Map {
  FreeSurface surface;
  TraceNetwork network;
  SurfaceLoops loops;
};

Map map_of(const std::vector<TraceInput>& traces) {
  Map m;
  m.surface = FreeSurface::build(benched_slope_patches(), kSnap);
  m.network = TraceNetwork::build(m.surface, traces, {kSnap, 0.0});
  m.loops = SurfaceLoops::find(m.network, m.surface);
  return m;
}

std::vector<Eigen::Vector3d> outer_corners(const Map& m, const SurfaceRegion& r) {
  std::vector<Eigen::Vector3d> c;
  for (int h : r.loops.front()) c.push_back(m.network.vertices()[m.network.origin(h)]);
  return c;
}

// Whether every expected corner is a corner of the loop, and the loop has no
// corner that is not expected (it may pass through extra points only where a
// stretch bends over a patch edge, which the expectation lists).
bool same_polygon(const std::vector<Eigen::Vector3d>& got, const std::vector<Eigen::Vector3d>& want,
                  double tol) {
  if (got.size() != want.size()) return false;
  for (const auto& w : want)
    if (std::none_of(got.begin(), got.end(), [&](const auto& g) { return (g - w).norm() <= tol; }))
      return false;
  return true;
}

// How many regions match each expected polygon.
std::vector<int> matches(const Map& m, double tol) {
  const auto want = benched_slope_loops();
  std::vector<int> count(want.size(), 0);
  for (const auto& r : m.loops.regions())
    for (size_t k = 0; k < want.size(); ++k)
      if (same_polygon(outer_corners(m, r), want[k].corners, tol)) ++count[k];
  return count;
}

// Exact input: vertices come from intersecting planes; 1e-9 m covers rounding.
constexpr double kExact = 1e-9;

TEST(SurfaceLoops, BenchedSlopeFindsEveryExpectedPolygonOnce) {
  const Map m = map_of(benched_slope_traces());
  EXPECT_TRUE(m.network.notes().empty()) << m.network.notes().front();
  // The three blocks and nothing else: the outer region (everything reaching
  // the edge of the mapped surface) is excluded.
  EXPECT_EQ(m.loops.regions().size(), 3u);
  for (int c : matches(m, kExact)) EXPECT_EQ(c, 1);
  for (const auto& r : m.loops.regions()) {
    EXPECT_EQ(r.loops.size(), 1u);
    EXPECT_GT(r.area, 0);
  }
}

TEST(SurfaceLoops, LoopAcrossTheCrestCoversBothPatchesAndNamesItsTraces) {
  const Map m = map_of(benched_slope_traces());
  const auto want = benched_slope_loops();
  bool found = false;
  for (const auto& r : m.loops.regions()) {
    if (!same_polygon(outer_corners(m, r), want[1].corners, kExact)) continue;
    found = true;
    EXPECT_EQ(r.patches, (std::vector<int>{1, 2}));
    std::vector<std::string> ids;
    for (int t : r.traces) ids.push_back(benched_slope_traces()[t].id);
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, (std::vector<std::string>{"B-back", "B-low", "B-y12", "B-y16"}));
    // Area: 4 m wide; 3 m up the face's slant (sqrt(1.5^2 + 3^2)) plus 2 m of bench.
    EXPECT_NEAR(r.area, 4 * (std::hypot(1.5, 3.0) + 2), 1e-9);  // exact geometry, rounding only
  }
  EXPECT_TRUE(found);
}

// Hand marking: every point moved by up to 5 mm along the surface.
std::vector<TraceInput> jittered(std::vector<TraceInput> traces, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.005, 0.005);
  const FreeSurface s = FreeSurface::build(benched_slope_patches(), kSnap);
  for (auto& t : traces)
    for (auto& p : t.points) {
      const auto on = points_on_patches({p}, s, 1e-9);
      const SurfacePatch& P = s.patches()[on.front().front()];
      p += u(rng) * P.e1 + u(rng) * P.e2;
    }
  return traces;
}

// Snapped corners may move by up to the jitter (5 mm) plus the along-line
// error of a crossing of two jittered lines (a few mm): 2 cm bounds it.
constexpr double kSnapped = 0.02;

TEST(SurfaceLoops, SameLoopsInAnyOrderReversedSplitOrShort) {
  auto traces = benched_slope_traces();
  // Another order.
  {
    auto t = traces;
    std::reverse(t.begin(), t.end());
    std::rotate(t.begin(), t.begin() + 5, t.end());
    const Map m = map_of(t);
    EXPECT_EQ(m.loops.regions().size(), 3u);
    for (int c : matches(m, kExact)) EXPECT_EQ(c, 1);
  }
  // Every trace marked the other way round.
  {
    auto t = traces;
    for (auto& tr : t) std::reverse(tr.points.begin(), tr.points.end());
    const Map m = map_of(t);
    EXPECT_EQ(m.loops.regions().size(), 3u);
    for (int c : matches(m, kExact)) EXPECT_EQ(c, 1);
  }
  // Each trace marked in two pieces that overlap or leave a 2 cm gap.
  {
    std::vector<TraceInput> t;
    for (const auto& tr : traces) {
      const Eigen::Vector3d a = tr.points.front(), b = tr.points.back();
      if (tr.points.size() > 2) {  // bends over the crest: keep it whole
        t.push_back(tr);
        continue;
      }
      TraceInput p1 = tr, p2 = tr;
      p1.id += "/1";
      p2.id += "/2";
      const Eigen::Vector3d dir = (b - a).normalized();
      const Eigen::Vector3d mid = (a + b) / 2;
      p1.points = {a, mid + 0.01 * dir};
      p2.points = {mid + 0.02 * dir, b};
      t.push_back(p2);
      t.push_back(p1);
    }
    const Map m = map_of(t);
    EXPECT_EQ(m.loops.regions().size(), 3u);
    for (int c : matches(m, kExact)) EXPECT_EQ(c, 1);
  }
  // Ends a few millimetres short of the traces they should meet, points jittered.
  {
    auto t = jittered(traces, 7);
    const Map m = map_of(t);
    EXPECT_EQ(m.loops.regions().size(), 3u);
    for (int c : matches(m, kSnapped)) EXPECT_EQ(c, 1);
  }
}

TEST(SurfaceLoops, EndsShortOfEachOtherWithinTheToleranceAreSnapped) {
  // Block C drawn as four traces that stop 3 cm before they meet: inside the
  // 5 cm tolerance they are extended to each other, beyond it they are not.
  using V = Eigen::Vector3d;
  auto ring = [](double gap) {
    std::vector<TraceInput> t;
    t.push_back({"w", testing::joint("Jw", 80, 270, 0), {V(14, 3 + gap, 12), V(14, 9 - gap, 12)}});
    t.push_back({"e", testing::joint("Je", 80, 90, 1), {V(18, 3 + gap, 12), V(18, 9 - gap, 12)}});
    t.push_back({"s", testing::joint("Js", 80, 180, 2), {V(14 + gap, 3, 12), V(18 - gap, 3, 12)}});
    t.push_back({"n", testing::joint("Jn", 80, 0, 3), {V(14 + gap, 9, 12), V(18 - gap, 9, 12)}});
    return t;
  };
  EXPECT_EQ(map_of(ring(0.03)).loops.regions().size(), 1u);
  EXPECT_EQ(map_of(ring(0.08)).loops.regions().size(), 0u);
}

TEST(SurfaceLoops, EndsShortOfAPatchEdgeAreExtendedToIt) {
  // The joints y = 12 and y = 16 of block B marked in two pieces each, one on
  // the face and one on the bench, each stopping `gap` before the crest.
  auto with_gap = [](double gap) {
    std::vector<TraceInput> t;
    for (const auto& tr : benched_slope_traces()) {
      if (tr.id != "B-y12" && tr.id != "B-y16") {
        t.push_back(tr);
        continue;
      }
      const double y = tr.points.front().y();
      const Eigen::Vector3d up_face = Eigen::Vector3d(1, 0, 2).normalized();
      TraceInput face = tr, bench = tr;
      face.id += "/face";
      bench.id += "/bench";
      face.points = {testing::on_lower_face(y, 2), Eigen::Vector3d(3, y, 6) - gap * up_face};
      bench.points = {Eigen::Vector3d(3 + gap, y, 6), Eigen::Vector3d(6, y, 6)};
      t.push_back(face);
      t.push_back(bench);
    }
    return t;
  };
  // 3 cm short: extended to the crest, where the pieces meet; block B is found.
  const Map near = map_of(with_gap(0.03));
  EXPECT_EQ(near.loops.regions().size(), 3u);
  for (int c : matches(near, kExact)) EXPECT_EQ(c, 1);
  // 8 cm short: beyond the tolerance, B stays open.
  EXPECT_EQ(map_of(with_gap(0.08)).loops.regions().size(), 2u);
}

TEST(SurfaceLoops, SinglePointTraceIsRejectedByName) {
  auto traces = benched_slope_traces();
  traces.push_back({"lonely", testing::joint("Jy", 90, 0, 0), {Eigen::Vector3d(1, 1, 2)}});
  const Map m = map_of(traces);
  ASSERT_EQ(m.network.notes().size(), 1u);
  EXPECT_NE(m.network.notes()[0].find("traces[12] (lonely)"), std::string::npos);
  EXPECT_NE(m.network.notes()[0].find("at least two"), std::string::npos);
  EXPECT_EQ(m.loops.regions().size(), 3u);
}

}  // namespace
}  // namespace rockface::faces

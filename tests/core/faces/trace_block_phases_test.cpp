// The phases of trace_block (trace_block_phases.h), each on its own: the
// planes of a loop (joints by name, then the patches), the shape of the loop
// (a convex prism, a reflex corner of an L), the joints of an island, the
// cells an island's block is cut out of, and a block's name.
#include "core/faces/trace_block_phases.h"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/faces/surface_loops.h"
#include "core/faces/trace_network.h"
#include "tests/core/faces/benched_slope.h"

namespace rockface::faces {
namespace {

namespace phases = trace_block_phases;
using geometry::HalfSpace;
using testing::benched_slope_patches;
using testing::joint;
using testing::on_lower_face;

constexpr double kSnap = 0.05;

// The surface, network and loops of some traces on the benched slope.
struct Map {
  FreeSurface surface;
  TraceNetwork net;
  SurfaceLoops loops;
  explicit Map(const std::vector<TraceInput>& traces)
      : surface(FreeSurface::build(benched_slope_patches(), kSnap)),
        net(TraceNetwork::build(surface, traces, {kSnap, 0.0})),
        loops(SurfaceLoops::find(net, surface)) {}
  // The region whose outer loop has the most stretches.
  const SurfaceRegion& largest() const {
    const auto& regions = loops.regions();
    return *std::max_element(regions.begin(), regions.end(), [](const auto& a, const auto& b) {
      return a.loops.front().size() < b.loops.front().size();
    });
  }
};

std::vector<TraceInput> block_a() {
  std::vector<TraceInput> t;
  for (const auto& a : testing::benched_slope_traces())
    if (a.id.rfind("A-", 0) == 0) t.push_back(a);
  return t;
}

std::vector<std::string> names(const phases::LoopPlanes& p) {
  std::vector<std::string> n;
  for (const auto& pl : p.planes) n.push_back(pl.name);
  return n;
}

TEST(TraceBlockPhases, TheLoopOfAPrismHasItsJointsByNameThenItsPatchesAndIsConvex) {
  const Map map(block_a());
  ASSERT_FALSE(map.loops.regions().empty());
  const SurfaceRegion& region = map.largest();
  TraceBlockOptions options;
  options.snap_tolerance = kSnap;
  const phases::LoopPlanes planes =
      phases::loop_planes(map.surface, map.net, map.loops, region, options);
  // The joints by name, the lower face it lies on, and the bench above it:
  // a neighbour whose plane the block could cut through (the rock behind
  // the face and the bench is salient, the loop lies below the bench).
  EXPECT_EQ(names(planes),
            (std::vector<std::string>{"A-high", "A-low", "A-y4", "A-y8", "S2", "S3"}));
  EXPECT_EQ(planes.n_joints, 4);
  EXPECT_EQ(planes.planes[4].kind, blocks::PlaneKind::FreeFace);
  EXPECT_EQ(planes.covered, (std::vector<int>{planes.planes[4].patch}));
  EXPECT_EQ(phases::neighbouring_patches(map.surface, map.loops, map.net, region, kSnap),
            (std::vector<int>{planes.planes[5].patch}));
  EXPECT_TRUE(planes.notes.empty());

  const phases::LoopShape shape =
      phases::loop_shape(map.surface, map.net, map.loops, region, planes, kSnap);
  EXPECT_FALSE(shape.reflex);
  EXPECT_TRUE(shape.rock_convex);
  EXPECT_TRUE(shape.one_side);
  ASSERT_TRUE(shape.convex());
  // The prism: on the loop's side of each joint, on the rock side of S2
  // and of S3.
  const phases::Piece piece = phases::convex_piece(map.surface, planes, shape);
  ASSERT_EQ(piece.sides.size(), 6u);
  for (int k = 4; k < 6; ++k)
    EXPECT_EQ(piece.sides[k], map.surface.patches()[planes.planes[k].patch].rock_side);
  EXPECT_TRUE(phases::island_joints(map.net, region, planes).planes.empty());
  EXPECT_EQ(phases::block_id(map.net, region).rfind("loop along A-", 0), 0u);
}

TEST(TraceBlockPhases, TheInnerCornerOfAnLShapedLoopIsReflex) {
  std::vector<TraceInput> t;
  // On the lower face (as in trace_blocks_test): the corner at (y 7, z 2.5) is reflex.
  t.push_back({"y4", joint("Jy", 90, 0, 0), {on_lower_face(4, 0.5), on_lower_face(4, 4.5)}});
  t.push_back({"y7", joint("Jy", 90, 0, 0), {on_lower_face(7, 2.5), on_lower_face(7, 4.5)}});
  t.push_back({"y10", joint("Jy", 90, 0, 0), {on_lower_face(10, 0.5), on_lower_face(10, 3)}});
  t.push_back({"low", joint("J30", 30, 270, 1), {on_lower_face(3, 1), on_lower_face(11, 1)}});
  t.push_back({"mid", joint("J80", 80, 270, 2), {on_lower_face(7, 2.5), on_lower_face(11, 2.5)}});
  t.push_back({"high", joint("J80", 80, 270, 2), {on_lower_face(3, 4), on_lower_face(8, 4)}});
  const Map map(t);
  const SurfaceRegion& region = map.largest();
  TraceBlockOptions options;
  options.snap_tolerance = kSnap;
  const auto planes = phases::loop_planes(map.surface, map.net, map.loops, region, options);
  const auto shape = phases::loop_shape(map.surface, map.net, map.loops, region, planes, kSnap);
  EXPECT_TRUE(shape.reflex);
  EXPECT_FALSE(shape.convex());
  const auto islands = phases::island_joints(map.net, region, planes);
  const auto found =
      phases::nonconvex_pieces(map.surface, map.net, map.loops, region, planes, islands, kSnap);
  EXPECT_EQ(found.pieces.size(), 3u);  // three cells of the joint lines inside the L
  ASSERT_FALSE(found.notes.empty());
  EXPECT_EQ(found.notes.back(), "non-convex: the union of 3 convex pieces");
}

TEST(TraceBlockPhases, TheJointsOfAnIslandAreThoseOfTheInnerLoopOnly) {
  std::vector<TraceInput> t = block_a();
  t.push_back({"i-y5", joint("Jy", 90, 0, 0), {on_lower_face(5, 1.8), on_lower_face(5, 3.2)}});
  t.push_back({"i-y7", joint("Jy", 90, 0, 0), {on_lower_face(7, 1.8), on_lower_face(7, 3.2)}});
  t.push_back({"i-low", joint("J30", 30, 270, 1), {on_lower_face(4.8, 2), on_lower_face(7.2, 2)}});
  t.push_back({"i-high", joint("J80", 80, 270, 2), {on_lower_face(4.8, 3), on_lower_face(7.2, 3)}});
  const Map map(t);
  const SurfaceRegion* ring = nullptr;
  for (const auto& r : map.loops.regions())
    if (r.loops.size() > 1) ring = &r;
  ASSERT_TRUE(ring);
  TraceBlockOptions options;
  options.snap_tolerance = kSnap;
  const auto planes = phases::loop_planes(map.surface, map.net, map.loops, *ring, options);
  const auto islands = phases::island_joints(map.net, *ring, planes);
  std::set<std::string> island_names;
  for (int j : islands.planes) island_names.insert(planes.planes[j].name);
  EXPECT_EQ(island_names.size(), 4u);
  for (const auto& n : island_names) EXPECT_EQ(n.rfind("i-", 0), 0u) << n;
  EXPECT_TRUE(phases::loop_shape(map.surface, map.net, map.loops, *ring, planes, kSnap).reflex);
}

TEST(TraceBlockPhases, AnIslandsBlockIsCutOutOfEachOuterPieceAndTheRestMayBeEmpty) {
  phases::Piece outer;
  outer.sides = {HalfSpace::Upper, HalfSpace::Upper, HalfSpace::Upper, HalfSpace::Lower};
  // Island planes 1 and 2; the island's block lies on (lower, upper) of them.
  const std::set<std::vector<HalfSpace>> behind = {{HalfSpace::Lower, HalfSpace::Upper}};
  const auto cut = phases::cut_out_islands({outer}, {1, 2}, behind);
  std::vector<std::string> codes;
  for (const auto& p : cut) {
    EXPECT_TRUE(p.may_be_empty);
    codes.push_back(p.code());
  }
  EXPECT_EQ(codes, (std::vector<std::string>{"0001", "0011", "0111"}));
  // Two outer pieces with the same sides on the other planes give each cell once.
  EXPECT_EQ(phases::cut_out_islands({outer, outer}, {1, 2}, behind).size(), 3u);
}

}  // namespace
}  // namespace rockface::faces

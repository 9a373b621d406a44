#include "core/faces/trace_blocks.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "core/faces/surface_loops.h"
#include "core/faces/trace_network.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "tests/core/faces/benched_slope.h"
#include "tests/core/faces/trace_map_run.h"

namespace rockface::faces {
namespace {

using testing::benched_slope_patches;
using testing::benched_slope_traces;
using testing::joint;
using testing::on_lower_face;

constexpr double kSnap = 0.05;

std::vector<TraceBlock> blocks_of(const std::vector<TraceInput>& traces,
                                  std::vector<std::string>* notes = nullptr) {
  auto run = testing::run_trace_map(benched_slope_patches(), traces, kSnap, 0.0, deg_to_rad(1.0));
  if (notes) *notes = run.notes;
  return std::move(run.blocks);
}

std::vector<std::string> ids_of(const TraceBlock& b, const std::vector<TraceInput>& traces) {
  std::vector<std::string> ids;
  for (int t : b.traces) ids.push_back(traces[t].id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

// Profile (x, z) polygon area by the shoelace formula.
double shoelace(const std::vector<Eigen::Vector2d>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const auto& u = p[i];
    const auto& v = p[(i + 1) % p.size()];
    a += u.x() * v.y() - u.y() * v.x();
  }
  return std::abs(a) / 2;
}

// Where two lines z = z0 + m (x - x0) of the slope's profile meet.
Eigen::Vector2d meet(double x0, double z0, double m, double x1, double z1, double n) {
  const double x = (z1 - z0 + m * x0 - n * x1) / (m - n);
  return {x, z0 + m * (x - x0)};
}

// Volumes of polyhedra built from planes through exact points: rounding of
// the corner solves only, ~1e-12 relative.
constexpr double kVolumeRel = 1e-9;

// The profile of block A (x, z): the face z = 2 x, the joint dipping 30 out
// of it through the face at z = 1 and the one dipping 80 through z = 4.
double profile_a(double z_top) {
  const double t30 = std::tan(deg_to_rad(30)), t80 = std::tan(deg_to_rad(80));
  const Eigen::Vector2d low(0.5, 1), high(z_top / 2, z_top);
  const Eigen::Vector2d corner = meet(0.5, 1, t30, z_top / 2, z_top, t80);
  return shoelace({low, high, corner});
}

TEST(TraceBlocks, BenchedSlopeBlocksAreFiniteOrInfiniteByConstruction) {
  const auto traces = benched_slope_traces();
  const auto blocks = blocks_of(traces);
  ASSERT_EQ(blocks.size(), 3u);
  int seen = 0;
  for (const auto& b : blocks) {
    const auto ids = ids_of(b, traces);
    if (ids == std::vector<std::string>{"A-high", "A-low", "A-y4", "A-y8"}) {
      ++seen;
      EXPECT_TRUE(b.convex);
      EXPECT_TRUE(b.finite);
      EXPECT_FALSE(b.finiteness.finite.marginal);
      ASSERT_TRUE(b.polyhedron && b.analysis);
      EXPECT_NEAR(b.analysis->mass.volume, 4 * profile_a(4), kVolumeRel * 20);
      // Between two parallel joints the joint pyramid is a plane (no
      // interior): removable only marginally, and said so.
      EXPECT_TRUE(b.finiteness.removable.marginal);
      EXPECT_NEAR(b.finiteness.jp_margin, 0, 1e-12);  // parallel planes: rounding of normals
      ASSERT_TRUE(b.analysis->mode);
      EXPECT_EQ(b.analysis->mode->type, kinematics::ModeType::Sliding);
    } else if (ids == std::vector<std::string>{"B-back", "B-low", "B-y12", "B-y16"}) {
      ++seen;
      EXPECT_TRUE(b.convex);
      EXPECT_TRUE(b.finite);
      ASSERT_TRUE(b.analysis);
      // Profile: face from z = 3 to the crest, bench to x = 5, down the
      // vertical joint to the 20 degree joint, back along it.
      const double t20 = std::tan(deg_to_rad(20));
      const double area = shoelace({{1.5, 3}, {3, 6}, {5, 6}, {5, 3 + t20 * (5 - 1.5)}});
      EXPECT_NEAR(b.analysis->mass.volume, 4 * area, kVolumeRel * 40);
      // Two free faces (face and bench) and four joints bound it.
      EXPECT_EQ(b.polyhedron->faces().size(), 6u);
    } else if (ids == std::vector<std::string>{"C-e", "C-n", "C-s", "C-w"}) {
      ++seen;
      // Widens with depth: infinite, by a clear margin (the planes lean 10
      // degrees out; the orientation uncertainty is 1).
      EXPECT_FALSE(b.finite);
      EXPECT_FALSE(b.finiteness.finite.marginal);
      EXPECT_FALSE(b.polyhedron);
    }
  }
  EXPECT_EQ(seen, 3);
}

TEST(TraceBlocks, SameBlocksWhateverTheOrderAndDirectionOfTheTraces) {
  const auto traces = benched_slope_traces();
  const auto ref = blocks_of(traces);
  auto shuffled = traces;
  std::reverse(shuffled.begin(), shuffled.end());
  for (auto& t : shuffled) std::reverse(t.points.begin(), t.points.end());
  const auto got = blocks_of(shuffled);
  ASSERT_EQ(got.size(), ref.size());
  for (size_t k = 0; k < ref.size(); ++k) {
    EXPECT_EQ(ids_of(got[k], shuffled), ids_of(ref[k], traces));
    EXPECT_EQ(got[k].finite, ref[k].finite);
    if (ref[k].analysis) {
      ASSERT_TRUE(got[k].analysis);
      // The same planes through the same points: rounding only.
      EXPECT_NEAR(got[k].analysis->mass.volume, ref[k].analysis->mass.volume,
                  kVolumeRel * ref[k].analysis->mass.volume);
    }
  }
}

TEST(TraceBlocks, LShapedLoopIsTheUnionOfItsConvexPieces) {
  // On the lower face: joints y = 4, 7, 10; the 30 degree joint at z = 1;
  // joints dipping 80 out of the face at z = 2.5 (y 7..10) and z = 4 (y 4..7).
  // The corner at (y 7, z 2.5) is reflex.
  std::vector<TraceInput> t;
  t.push_back({"y4", joint("Jy", 90, 0, 0), {on_lower_face(4, 0.5), on_lower_face(4, 4.5)}});
  t.push_back({"y7", joint("Jy", 90, 0, 0), {on_lower_face(7, 2.5), on_lower_face(7, 4.5)}});
  t.push_back({"y10", joint("Jy", 90, 0, 0), {on_lower_face(10, 0.5), on_lower_face(10, 3)}});
  t.push_back({"low", joint("J30", 30, 270, 1), {on_lower_face(3, 1), on_lower_face(11, 1)}});
  t.push_back({"mid", joint("J80", 80, 270, 2), {on_lower_face(7, 2.5), on_lower_face(11, 2.5)}});
  t.push_back({"high", joint("J80", 80, 270, 2), {on_lower_face(3, 4), on_lower_face(8, 4)}});
  const auto blocks = blocks_of(t);
  ASSERT_EQ(blocks.size(), 1u);
  const TraceBlock& b = blocks.front();
  EXPECT_FALSE(b.convex);
  EXPECT_EQ(b.codes.size(), 3u);  // three cells of the joint lines inside the L
  EXPECT_TRUE(b.finite);
  ASSERT_TRUE(b.polyhedron && b.analysis) << (b.notes.empty() ? "" : b.notes.back());
  // y 4..7 behind the whole height, y 7..10 behind the lower step.
  EXPECT_NEAR(b.analysis->mass.volume, 3 * profile_a(4) + 3 * profile_a(2.5), kVolumeRel * 20);
  EXPECT_EQ(ids_of(b, t), (std::vector<std::string>{"high", "low", "mid", "y10", "y4", "y7"}));
}

TEST(TraceBlocks, AnIslandOfTracesCutsItsOwnBlockOutOfTheOneAroundIt) {
  // Block A of the benched slope (y 4..8, z 1..4) with a rectangle of
  // traces inside it that touches none of A's: y = 5 and 7, the 30 degree
  // joint at z = 2 and the 80 degree one at z = 3. The island's joints
  // persist behind it: the inner block is a prism like A between z = 2 and
  // 3 over y 5..7, and the block behind the ring around it is A without it.
  std::vector<TraceInput> t;
  for (const auto& a : testing::benched_slope_traces())
    if (a.id.rfind("A-", 0) == 0) t.push_back(a);
  t.push_back({"i-y5", joint("Jy", 90, 0, 0), {on_lower_face(5, 1.8), on_lower_face(5, 3.2)}});
  t.push_back({"i-y7", joint("Jy", 90, 0, 0), {on_lower_face(7, 1.8), on_lower_face(7, 3.2)}});
  t.push_back({"i-low", joint("J30", 30, 270, 1), {on_lower_face(4.8, 2), on_lower_face(7.2, 2)}});
  t.push_back({"i-high", joint("J80", 80, 270, 2), {on_lower_face(4.8, 3), on_lower_face(7.2, 3)}});
  const auto blocks = blocks_of(t);
  ASSERT_EQ(blocks.size(), 2u);
  const double t30 = std::tan(deg_to_rad(30)), t80 = std::tan(deg_to_rad(80));
  const double inner_profile = shoelace(
      {{1, 2}, {1.5, 3}, meet(1, 2, t30, 1.5, 3, t80)});  // the face point at z is (z / 2, z)
  const TraceBlock* inner = nullptr;
  const TraceBlock* ring = nullptr;
  for (const auto& b : blocks)
    (b.traces.size() == 4 && ids_of(b, t)[0] == "i-high" ? inner : ring) = &b;
  ASSERT_TRUE(inner && ring);
  ASSERT_TRUE(inner->analysis && ring->analysis) << (ring->notes.empty() ? "" : ring->notes.back());
  EXPECT_TRUE(inner->finite);
  EXPECT_TRUE(ring->finite);
  EXPECT_FALSE(ring->convex);
  EXPECT_NEAR(inner->analysis->mass.volume, 2 * inner_profile, kVolumeRel * 20);
  EXPECT_NEAR(ring->analysis->mass.volume, 4 * profile_a(4) - 2 * inner_profile, kVolumeRel * 20);
  // The ring's loop includes the island's traces.
  EXPECT_EQ(ring->traces.size(), 8u);
  // Its faces toward the island's block are faces on the island's joints.
  int island_faces = 0;
  for (const auto& bp : ring->polyhedron->planes())
    island_faces += bp.kind == blocks::PlaneKind::Joint && bp.name.rfind("i-", 0) == 0 ? 1 : 0;
  EXPECT_EQ(island_faces, 4);
}

TEST(TraceBlocks, NonConvexPatchGivesTheSameBlocksAsItsConvexOriginal) {
  // The lower face with a notch out of its crest at y 9..10, away from every
  // trace: it is split into convex pieces, at least one of whose seams runs
  // under a block. Every block must come out as on the whole face.
  using V = Eigen::Vector3d;
  auto notched = testing::benched_slope_patches();
  notched[1].polygon = {V(0, 0, 0),          V(3, 0, 6),           on_lower_face(9, 6),
                        on_lower_face(9, 5), on_lower_face(10, 5), on_lower_face(10, 6),
                        V(3, 20, 6),         V(0, 20, 0)};
  const auto traces = testing::benched_slope_traces();
  const std::vector<TraceBlock> ref = blocks_of(traces);
  const auto run = testing::run_trace_map(notched, traces, kSnap, 0.0, deg_to_rad(1.0));
  ASSERT_GT(run.surface_patches, 5u);
  const auto& got = run.blocks;
  ASSERT_EQ(got.size(), ref.size());
  int over_a_seam = 0;
  for (size_t k = 0; k < ref.size(); ++k) {
    EXPECT_EQ(ids_of(got[k], traces), ids_of(ref[k], traces));
    EXPECT_EQ(got[k].finite, ref[k].finite);
    ASSERT_EQ(bool(got[k].analysis), bool(ref[k].analysis));
    if (ref[k].analysis) {
      // Same planes and corners; the pieces only add coplanar seams.
      EXPECT_NEAR(got[k].analysis->mass.volume, ref[k].analysis->mass.volume, kVolumeRel * 40);
    }
    int pieces = 0;
    for (const auto& p : got[k].planes) pieces += p.name.rfind("S2.", 0) == 0 ? 1 : 0;
    over_a_seam += pieces >= 2 ? 1 : 0;
  }
  EXPECT_GE(over_a_seam, 1);
}

TEST(TraceBlocks, BlockAtTheReentrantEdgeOfATunnelCrownAndWallWrapsTheCorner) {
  // A tunnel along y: crown z = 5 (x 0..4, rock above), east wall x = 4
  // (z 0..5, rock behind). The rock at their edge is the union of the two
  // rock sides. Joints: y = 2 and y = 5 over crown and wall; on the crown at
  // x = 2 a joint dipping 45 west (z = x + 3); on the wall at z = 2 one
  // dipping atan 4 west (z = 4 x - 14). They meet behind the corner, at
  // (17/3, 26/3): the block wraps round the edge.
  using V = Eigen::Vector3d;
  const std::vector<PatchInput> tunnel = {
      {"crown", {V(0, 0, 5), V(0, 10, 5), V(4, 10, 5), V(4, 0, 5)}},
      {"wall", {V(4, 0, 0), V(4, 0, 5), V(4, 10, 5), V(4, 10, 0)}},
  };
  std::vector<TraceInput> t;
  t.push_back({"y2", joint("Jy", 90, 0, 0), {V(1, 2, 5), V(4, 2, 5), V(4, 2, 1)}});
  t.push_back({"y5", joint("Jy", 90, 0, 0), {V(1, 5, 5), V(4, 5, 5), V(4, 5, 1)}});
  t.push_back({"crown-j", joint("J45", 45, 270, 1), {V(2, 1, 5), V(2, 6, 5)}});
  t.push_back(
      {"wall-j", joint("J76", rad_to_deg(std::atan(4.0)), 270, 2), {V(4, 1, 2), V(4, 6, 2)}});
  const FreeSurface surface = FreeSurface::build(tunnel, kSnap);
  EXPECT_TRUE(surface.rock_is_union(0, 1, kSnap));
  const TraceNetwork net = TraceNetwork::build(surface, t, {kSnap, 0.0});
  const SurfaceLoops loops = SurfaceLoops::find(net, surface);
  ASSERT_EQ(loops.regions().size(), 1u);
  EXPECT_EQ(loops.regions()[0].patches, (std::vector<int>{0, 1}));
  kinematics::Effects effects;
  effects.push_back(std::make_unique<kinematics::GravityEffect>(Eigen::Vector3d(0, 0, -9.81)));
  TraceBlockOptions options;
  options.snap_tolerance = kSnap;
  options.effects = &effects;
  NoProgress progress;
  const auto blocks = trace_blocks(surface, net, loops, options, progress);
  ASSERT_EQ(blocks.size(), 1u);
  const TraceBlock& b = blocks[0];
  EXPECT_FALSE(b.convex);
  // Behind the crown, behind the wall, and behind the edge itself.
  EXPECT_EQ(b.codes.size(), 3u);
  EXPECT_TRUE(b.finite);
  ASSERT_TRUE(b.analysis) << (b.notes.empty() ? "" : b.notes.back());
  const double area = shoelace({{2, 5}, {4, 5}, {4, 2}, {17.0 / 3, 26.0 / 3}});
  EXPECT_NEAR(b.analysis->mass.volume, 3 * area, kVolumeRel * 30);
}

TEST(TraceBlocks, FittedPlaneAcrossTheCrestGivesTheSameBlock) {
  auto traces = benched_slope_traces();
  for (auto& t : traces)
    if (t.id == "B-y12") t.joint.reset();  // marked over the crest: relief enough to fit
  std::vector<std::string> notes;
  const auto blocks = blocks_of(traces, &notes);
  EXPECT_TRUE(notes.empty());
  ASSERT_EQ(blocks.size(), 3u);
  const auto ref = blocks_of(benched_slope_traces());
  for (size_t k = 0; k < 3; ++k)
    if (ref[k].analysis) {
      ASSERT_TRUE(blocks[k].analysis);
      // The fit recovers y = 12 from exact points: rounding of the eigen
      // decomposition, ~1e-12 in the normal.
      EXPECT_NEAR(blocks[k].analysis->mass.volume, ref[k].analysis->mass.volume, 1e-8);
    }
}

TEST(TraceBlocks, TraceOnOnePlanarPatchWithoutJointHasUnknownOrientation) {
  auto traces = benched_slope_traces();
  for (auto& t : traces)
    if (t.id == "A-y4") t.joint.reset();  // a straight line on one patch: no dip
  std::vector<std::string> notes;
  const auto blocks = blocks_of(traces, &notes);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("(A-y4)"), std::string::npos);
  EXPECT_NE(notes[0].find("orientation unknown"), std::string::npos);
  // Block A lost a side: only B and C remain.
  EXPECT_EQ(blocks.size(), 2u);
}

}  // namespace
}  // namespace rockface::faces

#include "core/faces/free_surface.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/faces/trace_network.h"
#include "tests/core/faces/benched_slope.h"

namespace rockface::faces {
namespace {

using V = Eigen::Vector3d;
constexpr double kSnap = 0.05;

std::string error_of(const std::vector<PatchInput>& patches) {
  try {
    FreeSurface::build(patches, kSnap);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FreeSurface, OutwardNormalsAndRockSidesOfTheBenchedSlope) {
  const FreeSurface s = FreeSurface::build(testing::benched_slope_patches(), kSnap);
  ASSERT_EQ(s.patches().size(), 5u);
  // Floor and bench: out is up, the rock below (code 1 of an upward normal).
  for (int k : {0, 2, 4}) {
    EXPECT_NEAR((s.patches()[k].outward - V::UnitZ()).norm(), 0, 1e-12);  // exact corners
    EXPECT_EQ(s.patches()[k].rock_side, geometry::HalfSpace::Lower);
  }
  // The faces look west and up: out is (-2, 0, 1) / sqrt 5.
  EXPECT_NEAR((s.patches()[1].outward - V(-2, 0, 1).normalized()).norm(), 0, 1e-12);
  EXPECT_EQ(s.patches()[1].rock_side, geometry::HalfSpace::Lower);
  // Crest (face / bench) salient, toe (floor / face, bench / upper face) re-entrant.
  EXPECT_FALSE(s.rock_is_union(1, 2, kSnap));
  EXPECT_FALSE(s.rock_is_union(2, 1, kSnap));
  EXPECT_TRUE(s.rock_is_union(0, 1, kSnap));
  EXPECT_TRUE(s.rock_is_union(2, 3, kSnap));
}

TEST(FreeSurface, CrownLookingDownHasTheRockAbove) {
  const FreeSurface s =
      FreeSurface::build({{"crown", {V(0, 0, 5), V(0, 10, 5), V(4, 10, 5), V(4, 0, 5)}}}, kSnap);
  EXPECT_NEAR((s.patches()[0].outward + V::UnitZ()).norm(), 0, 1e-12);  // exact corners
  EXPECT_EQ(s.patches()[0].rock_side, geometry::HalfSpace::Upper);
}

TEST(FreeSurface, BadPatchesAreRejectedByName) {
  // One corner 30 cm up: the best-fit plane leaves each corner 7.5 cm off,
  // beyond the 5 cm tolerance.
  EXPECT_NE(error_of({{"W", {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0.3), V(0, 1, 0)}}})
                .find("surface.patches[0] (W): not planar"),
            std::string::npos);
  // An outline that crosses itself: a square with two corners swapped.
  EXPECT_NE(error_of({{"X", {V(0, 0, 0), V(3, 0, 0), V(3, 3, 0), V(1, -1, 0), V(0, 3, 0)}}})
                .find("surface.patches[0] (X): its outline crosses itself"),
            std::string::npos);
  EXPECT_NE(error_of({{"P", {V(0, 0, 0), V(1, 0, 0), V(2, 0, 0)}}}).find("collinear"),
            std::string::npos);
}

TEST(FreeSurface, NonConvexPatchIsSplitIntoConvexPiecesOnItsPlane) {
  // An L-shaped bench (area 3) and a comb with two notches (area 8).
  const auto surface = FreeSurface::build(
      {{"L", {V(0, 0, 0), V(2, 0, 0), V(2, 1, 0), V(1, 1, 0), V(1, 2, 0), V(0, 2, 0)}},
       {"COMB",
        {V(0, 0, 5), V(5, 0, 5), V(5, 2, 5), V(4, 2, 5), V(4, 1, 5), V(3, 1, 5), V(3, 2, 5),
         V(2, 2, 5), V(2, 1, 5), V(1, 1, 5), V(1, 2, 5), V(0, 2, 5)}}},
      0.05);
  double area_l = 0, area_comb = 0;
  int pieces_l = 0, pieces_comb = 0;
  for (int k = 0; k < static_cast<int>(surface.patches().size()); ++k) {
    const SurfacePatch& P = surface.patches()[k];
    // Every piece convex and counter-clockwise, on the input's plane.
    const size_t n = P.polygon2d.size();
    double a = 0;
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d u = P.polygon2d[(i + 1) % n] - P.polygon2d[i];
      const Eigen::Vector2d w = P.polygon2d[(i + 2) % n] - P.polygon2d[(i + 1) % n];
      EXPECT_GE(u.x() * w.y() - u.y() * w.x(), -1e-12) << P.id;  // exact corners: rounding only
      a += P.polygon2d[i].x() * P.polygon2d[(i + 1) % n].y() -
           P.polygon2d[(i + 1) % n].x() * P.polygon2d[i].y();
    }
    EXPECT_NEAR(P.outward.z(), 1, 1e-12);
    (P.input == 0 ? area_l : area_comb) += a / 2;
    ++(P.input == 0 ? pieces_l : pieces_comb);
    EXPECT_EQ(P.id.substr(0, P.id.find('.')), P.input == 0 ? "L" : "COMB");
    EXPECT_NE(surface.where(k).find(P.input == 0 ? "surface.patches[0]" : "surface.patches[1]"),
              std::string::npos);
  }
  // Areas add up exactly (same corners), with few pieces (Hertel-Mehlhorn:
  // an L needs 2, the comb 3 or 4; at most 4x the fewest).
  EXPECT_NEAR(area_l, 3, 1e-12);
  EXPECT_NEAR(area_comb, 8, 1e-12);
  EXPECT_GE(pieces_l, 2);
  EXPECT_LE(pieces_l, 3);
  EXPECT_GE(pieces_comb, 3);
  EXPECT_LE(pieces_comb, 8);
}

TEST(FreeSurface, PatchListedClockwiseIsCaughtAtItsSharedEdge) {
  // The bench listed the other way round: it would face into the rock.
  auto patches = testing::benched_slope_patches();
  std::reverse(patches[2].polygon.begin(), patches[2].polygon.end());
  const FreeSurface s = FreeSurface::build(patches, kSnap);
  try {
    TraceNetwork::build(s, {}, {kSnap, 0.0});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("(S3)"), std::string::npos) << m;
    EXPECT_NE(m.find("counter-clockwise"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace rockface::faces

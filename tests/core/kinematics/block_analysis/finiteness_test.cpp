// Finiteness and removability of whole blocks (Goodman & Shi), with the
// excavation pyramid of a non-convex free surface as a union.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/blocks/construction.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/block_analysis.h"

namespace rockface::kinematics {
namespace {

using blocks::FaceInput;
using blocks::PlaneKind;

// A block in the inner corner of a bench (rock wraps 270 degrees around the
// corner edge): section in the x-z plane, P4 -> P3 -> P2 -> P1
// counter-clockwise seen from -y, extruded over y in [0, 1]. P3-P2 lies on
// the bench floor z = 1 (rock below), P2-P1 on the wall x = 1 (rock at
// x < 1), the other two sides are joints; both ends are free.
blocks::Polyhedron bench_corner_block() {
  const std::vector<Eigen::Vector2d> xz{{0.5, 0.2}, {2, 1}, {1, 1}, {1, 2}};  // P4 P3 P2 P1
  std::vector<Eigen::Vector3d> v;
  for (const auto& p : xz) v.emplace_back(p.x(), 0, p.y());
  for (const auto& p : xz) v.emplace_back(p.x(), 1, p.y());
  // Seen from -y (outside the y = 0 end, x to the right, z up) P4 P3 P2 P1
  // runs counter-clockwise.
  std::vector<FaceInput> f{{0, "J1", PlaneKind::Joint, std::nullopt, {0, 4, 5, 1}},        // P4-P3
                           {2, "floor", PlaneKind::FreeFace, std::nullopt, {1, 5, 6, 2}},  // P3-P2
                           {3, "wall", PlaneKind::FreeFace, std::nullopt, {2, 6, 7, 3}},   // P2-P1
                           {1, "J2", PlaneKind::Joint, std::nullopt, {3, 7, 4, 0}},        // P1-P4
                           {4, "end0", PlaneKind::FreeFace, std::nullopt, {0, 1, 2, 3}},
                           {5, "end1", PlaneKind::FreeFace, std::nullopt, {7, 6, 5, 4}}};
  return blocks::build_block_from_faces("corner", v, f);
}

TEST(BlockFiniteness, NonConvexFreeSurfaceGivesUnionOfExcavationPyramids) {
  const blocks::Polyhedron b = bench_corner_block();
  const Finiteness f = block_finiteness(b, 0);
  // Two convex parts: floor + ends and wall + ends.
  ASSERT_EQ(f.excavation_pyramids.size(), 2u);
  EXPECT_TRUE(f.finite.value);
  EXPECT_TRUE(f.removable.value);  // it comes out up and away from the corner
  EXPECT_GT(f.jp_margin, 0);
  // The union's shut margin is the smaller of the parts' (computed here
  // directly), and smaller than what the intersection of all free faces
  // (the convex-block rule) would claim: the corner is closer to infinite.
  geometry::Cone jp, floor_ep, wall_ep, all_ep;
  for (const auto& p : b.planes()) {
    if (p.kind == PlaneKind::Joint) jp.add(p.inward_normal());
    if (p.kind != PlaneKind::FreeFace) continue;
    all_ep.add(p.inward_normal());
    if (p.name != "wall") floor_ep.add(p.inward_normal());
    if (p.name != "floor") wall_ep.add(p.inward_normal());
  }
  const double floor_shut = -jp.intersect(floor_ep).margin().angle;
  const double wall_shut = -jp.intersect(wall_ep).margin().angle;
  const double all_shut = -jp.intersect(all_ep).margin().angle;
  // Same cone computations on the same normals: equal to rounding.
  EXPECT_NEAR(-f.jp_ep_margin, std::min(floor_shut, wall_shut), 1e-12);
  EXPECT_LT(-f.jp_ep_margin, all_shut - 0.05);  // differs by far more than rounding
}

TEST(BlockFiniteness, ManyFreeFacesSplitIntoEveryConvexPart) {
  // A prism over a nine-pointed star (18 sides, all free faces) sitting on a
  // joint, top free: 19 free planes. Each inner corner of the star is a
  // reflex edge between two sides, so a convex part takes one side of each
  // of the 9 pairs, plus the top and the other sides: 2^9 parts of 10 planes.
  std::vector<Eigen::Vector2d> star;
  for (int k = 0; k < 18; ++k) {
    const double a = k * std::numbers::pi / 9, r = k % 2 == 0 ? 2.0 : 1.0;
    star.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  const int n = 18;
  std::vector<Eigen::Vector3d> v;
  for (const auto& p : star) v.emplace_back(p.x(), p.y(), 0);
  for (const auto& p : star) v.emplace_back(p.x(), p.y(), 1);
  std::vector<FaceInput> f;
  FaceInput bottom{0, "J", PlaneKind::Joint, std::nullopt, {}};
  for (int k = n - 1; k >= 0; --k) bottom.loop.push_back(k);
  FaceInput top{1, "top", PlaneKind::FreeFace, std::nullopt, {}};
  for (int k = 0; k < n; ++k) top.loop.push_back(n + k);
  f = {bottom, top};
  for (int k = 0; k < n; ++k)
    f.push_back({2 + k,
                 "side" + std::to_string(k),
                 PlaneKind::FreeFace,
                 std::nullopt,
                 {k, (k + 1) % n, n + (k + 1) % n, n + k}});
  const blocks::Polyhedron b = blocks::build_block_from_faces("star", v, f);
  const Finiteness fin = block_finiteness(b, 0);
  ASSERT_EQ(fin.excavation_pyramids.size(), 512u);
  for (const auto& ep : fin.excavation_pyramids) EXPECT_EQ(ep.normals().size(), 10u);
  // It lifts off its joint: finite and removable, whatever the EP split.
  EXPECT_TRUE(fin.finite.value);
  EXPECT_TRUE(fin.removable.value);
}

TEST(BlockFiniteness, BlockInsideTheRockIsNotRemovable) {
  std::vector<Eigen::Vector3d> n{Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(),
                                 Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitY(),
                                 Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()};
  const Finiteness f = halfspace_finiteness(n, {}, 0);
  EXPECT_TRUE(f.finite.value);
  EXPECT_FALSE(f.removable.value);
}

TEST(BlockFiniteness, OpenHalfSpacesAreInfiniteWithTheirMargin) {
  // Two joints and a horizontal free face whose rock lies below: a wedge
  // open downward into the rock, infinite.
  const Eigen::Vector3d n1 = geometry::plane_normal_deg(50, 90);
  const Eigen::Vector3d n2 = geometry::plane_normal_deg(50, 270);
  const Finiteness f = halfspace_finiteness({-n1, -n2}, {-Eigen::Vector3d::UnitZ()}, 0);
  EXPECT_FALSE(f.finite.value);
  EXPECT_FALSE(f.removable.value);
  // Straight down is inside all three half-spaces by 40 degrees (the joints
  // dip 50): the open angle of JP cap EP.
  EXPECT_NEAR(rad_to_deg(f.jp_ep_margin), 40, 1e-9);
}

TEST(BlockFiniteness, MarginInsideUncertaintyIsMarginal) {
  // The same wedge with joints dipping 89.5: JP cap EP open by 0.5 degrees,
  // inside a 1-degree orientation uncertainty.
  const Eigen::Vector3d n1 = geometry::plane_normal_deg(89.5, 90);
  const Eigen::Vector3d n2 = geometry::plane_normal_deg(89.5, 270);
  const Finiteness f = halfspace_finiteness({-n1, -n2}, {-Eigen::Vector3d::UnitZ()}, deg_to_rad(1));
  EXPECT_FALSE(f.finite.value);
  EXPECT_TRUE(f.finite.marginal);
  EXPECT_NEAR(rad_to_deg(f.finite.margin), 0.5, 1e-9);
}

}  // namespace
}  // namespace rockface::kinematics

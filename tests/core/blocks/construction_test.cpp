#include "core/blocks/construction.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/blocks/convexity.h"
#include "core/blocks/mass_properties.h"
#include "core/blocks/point_location.h"
#include "core/common/error.h"
#include "core/geometry/orientation.h"
#include "tests/core/blocks/block_shapes.h"

namespace rockface::blocks {
namespace {

using geometry::HalfSpace;

// Corners come from 3x3 solves of unit normals: ~1e-15 relative.
constexpr double kRel = 1e-12;

TEST(ConvexConstruction, BoxFromSixHalfSpaces) {
  const auto c = build_convex_block("B1", test::box_halfspaces(3, 2, 1));
  ASSERT_EQ(c.outcome, ConvexOutcome::Bounded);
  const Polyhedron& p = *c.polyhedron;
  EXPECT_EQ(p.vertices().size(), 8u);
  EXPECT_EQ(p.faces().size(), 6u);
  EXPECT_TRUE(c.redundant.empty());
  EXPECT_LT(c.recession_margin, 0);
  EXPECT_TRUE(is_convex(p));
  const MassProperties mp = mass_properties(p, 1000);
  EXPECT_NEAR(mp.volume, 6, 6 * kRel);
  // Plane identity survives: the face on "z1" is a free face with the block below.
  for (const auto& f : p.faces()) {
    const BlockPlane& bp = p.planes()[f.plane];
    if (bp.name == "z1") {
      EXPECT_EQ(bp.kind, PlaneKind::FreeFace);
      EXPECT_EQ(bp.side, HalfSpace::Lower);
      EXPECT_EQ(bp.index, 5);
    }
  }
}

TEST(ConvexConstruction, MissingFaceIsUnboundedNotAnError) {
  auto h = test::box_halfspaces(3, 2, 1);
  h.pop_back();  // no top: the block goes up forever
  const auto c = build_convex_block("B1", h);
  EXPECT_EQ(c.outcome, ConvexOutcome::Unbounded);
  EXPECT_FALSE(c.polyhedron);
  EXPECT_GE(c.recession_margin, 0);
  EXPECT_NEAR(c.open_direction.z(), 1, 1e-9);  // the only open direction is straight up
}

TEST(ConvexConstruction, ContradictoryHalfSpacesAreEmpty) {
  auto h = test::box_halfspaces(3, 2, 1);
  h[5].plane.offset = -1;  // top below the bottom
  EXPECT_EQ(build_convex_block("B1", h).outcome, ConvexOutcome::Empty);
}

TEST(ConvexConstruction, FourPlanesThroughOneCornerGiveOneVertex) {
  // A square pyramid: four faces through the apex (0, 0, 1), base z = 0.
  using test::halfspace;
  std::vector<HalfSpaceInput> h;
  const Eigen::Vector3d apex(0, 0, 1);
  for (int k = 0; k < 4; ++k) {
    const double az = k * std::numbers::pi / 2;
    const Eigen::Vector3d out(std::cos(az), std::sin(az), 1.0);  // outward, upward
    h.push_back(
        halfspace(k, "J" + std::to_string(k), PlaneKind::Joint, out, apex, HalfSpace::Lower));
  }
  h.push_back(halfspace(4, "F", PlaneKind::FreeFace, Eigen::Vector3d::UnitZ(),
                        Eigen::Vector3d::Zero(), HalfSpace::Upper));
  const auto c = build_convex_block("P", h);
  ASSERT_EQ(c.outcome, ConvexOutcome::Bounded);
  EXPECT_EQ(c.polyhedron->vertices().size(), 5u);
  int apex_vertex = -1;
  for (int v = 0; v < 5; ++v)
    if ((c.polyhedron->vertices()[v] - apex).norm() < 1e-12) apex_vertex = v;
  ASSERT_GE(apex_vertex, 0);
  EXPECT_EQ(c.polyhedron->planes_at_vertex(apex_vertex).size(), 4u);
  // Base 2 x 2, height 1: V = 4 / 3.
  EXPECT_NEAR(mass_properties(*c.polyhedron, 1).volume, 4.0 / 3, kRel);
}

TEST(ConvexConstruction, PlaneTouchingAlongAnEdgeIsRedundant) {
  auto h = test::box_halfspaces(1, 1, 1);
  // A plane through the edge x = 1, z = 1 at 45 degrees, block below it.
  h.push_back(test::halfspace(6, "J6", PlaneKind::Joint, Eigen::Vector3d(1, 0, 1),
                              Eigen::Vector3d(1, 0, 1), HalfSpace::Lower));
  const auto c = build_convex_block("B", h);
  ASSERT_EQ(c.outcome, ConvexOutcome::Bounded);
  ASSERT_EQ(c.redundant.size(), 1u);
  EXPECT_EQ(c.redundant[0], 6);
  EXPECT_EQ(c.polyhedron->faces().size(), 6u);
}

TEST(ConvexConstruction, SamePlaneListedTwiceIsOneFace) {
  // Two traces of one joint give its half-space twice (once exactly, once
  // shifted by rounding): one face, the later listing redundant.
  auto h = test::box_halfspaces(3, 2, 1);
  auto twin = h[1];
  twin.index = 6;
  twin.name = "x1-again";
  h.push_back(twin);
  auto near = h[3];
  near.index = 7;
  near.plane.offset += 1e-14;  // below the corner tolerance (1e-9 of the size)
  h.push_back(near);
  const auto c = build_convex_block("B", h);
  ASSERT_EQ(c.outcome, ConvexOutcome::Bounded);
  EXPECT_EQ(c.polyhedron->faces().size(), 6u);
  EXPECT_EQ(c.redundant, (std::vector<int>{6, 7}));
  EXPECT_NEAR(mass_properties(*c.polyhedron, 1).volume, 6, 6 * kRel);
}

TEST(ConvexConstruction, SamePlaneWithOppositeSidesIsEmpty) {
  auto h = test::box_halfspaces(3, 2, 1);
  auto flipped = h[0];
  flipped.side = flipped.side == HalfSpace::Upper ? HalfSpace::Lower : HalfSpace::Upper;
  h.push_back(flipped);  // the block squeezed to the plane: no volume
  EXPECT_EQ(build_convex_block("B", h).outcome, ConvexOutcome::Empty);
}

TEST(ConvexConstruction, ZeroNormalIsAnInputError) {
  auto h = test::box_halfspaces(1, 1, 1);
  h[2].plane.normal = Eigen::Vector3d::Zero();
  EXPECT_THROW(build_convex_block("B", h), InputError);
}

TEST(PointLocation, InsideOnSurfaceOutsideOfAnLBlock) {
  const Polyhedron l = test::build(test::prism(test::l_shape(1), 0, 1));
  EXPECT_EQ(locate_point(l, {0.5, 0.5, 0.5}), PointLocation::Inside);
  EXPECT_EQ(locate_point(l, {1.5, 1.5, 0.5}), PointLocation::Outside);  // the missing corner
  EXPECT_EQ(locate_point(l, {1.5, 1.0, 0.5}), PointLocation::OnSurface);
  EXPECT_NEAR(distance_to_surface(l, {1.5, 1.5, 0.5}), 0.5, 1e-12);
}

}  // namespace
}  // namespace rockface::blocks

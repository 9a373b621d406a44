// The shotcrete effect on a unit cube whose top face is free: its outline
// is the top face's four edges, its force tau x t x outline against the
// failure direction, at the top face's centre.
#include <gtest/gtest.h>

#include "core/blocks/construction.h"
#include "core/blocks/mass_properties.h"
#include "core/common/error.h"
#include "core/kinematics/effects/effect_shotcrete.h"

namespace rockface::kinematics {
namespace {

blocks::Polyhedron cube(bool free_top) {
  std::vector<blocks::HalfSpaceInput> hs;
  auto add = [&](int i, Eigen::Vector3d n, double offset, geometry::HalfSpace side, bool free) {
    blocks::HalfSpaceInput h;
    h.index = i;
    h.name = free ? "F" : "J" + std::to_string(i);
    h.kind = free ? blocks::PlaneKind::FreeFace : blocks::PlaneKind::Joint;
    h.plane.normal = n;
    h.plane.offset = offset;
    h.side = side;
    hs.push_back(h);
  };
  using geometry::HalfSpace;
  add(0, {1, 0, 0}, 0, HalfSpace::Upper, false);
  add(1, {1, 0, 0}, 1, HalfSpace::Lower, false);
  add(2, {0, 1, 0}, 0, HalfSpace::Upper, false);
  add(3, {0, 1, 0}, 1, HalfSpace::Lower, false);
  add(4, {0, 0, 1}, 0, HalfSpace::Upper, false);
  add(5, {0, 0, 1}, 1, HalfSpace::Lower, free_top);
  return *blocks::build_convex_block("cube", hs).polyhedron;
}

TEST(ShotcreteEffect, ResistsAlongTheOutlineOfTheFreeFace) {
  const blocks::Polyhedron b = cube(true);
  const blocks::MassProperties m = blocks::mass_properties(b, 2700);
  EXPECT_NEAR(free_face_outline(b), 4.0, 1e-12);              // rounding of the corners only
  const ShotcreteEffect s("shotcrete", 0.1, 2e6, {0, 0, 1});  // the block would lift out
  const EffectLoad l = s.load(b, m);
  ASSERT_TRUE(l.acts);
  EXPECT_NEAR(l.force.z(), -0.1 * 2e6 * 4, 1e-6);
  EXPECT_NEAR(l.force.head<2>().norm(), 0, 1e-9);
  // At the top face's centre (0.5, 0.5, 1), straight through the centroid:
  // no moment.
  EXPECT_NEAR(l.moment.norm(), 0, 1e-6);
}

TEST(ShotcreteEffect, NoFreeFaceNothingToLine) {
  const blocks::Polyhedron b = cube(false);
  const ShotcreteEffect s("shotcrete", 0.1, 2e6, {0, 0, -1});
  const EffectLoad l = s.load(b, blocks::mass_properties(b, 2700));
  EXPECT_FALSE(l.acts);
  ASSERT_FALSE(l.notes.empty());
  EXPECT_THROW(ShotcreteEffect("sc", 0, 1e6, {0, 0, 1}), InputError);
  EXPECT_THROW(ShotcreteEffect("sc", 0.1, 1e6, {0, 0, 0}), InputError);
}

}  // namespace
}  // namespace rockface::kinematics

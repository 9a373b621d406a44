#include "core/geometry/cone.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "core/common/units.h"
#include "core/geometry/orientation.h"

namespace rockface::geometry {
namespace {

Eigen::Vector3d n_deg(double dip, double dipdir) {
  return plane_normal_deg(dip, dipdir);
}

bool has_ray(const std::vector<Eigen::Vector3d>& rays, const Eigen::Vector3d& d, double tol) {
  const Eigen::Vector3d u = d.normalized();
  for (const auto& r : rays)
    if ((r - u).norm() < tol) return true;
  return false;
}

TEST(Cone, PublishedPyramid000) {
  // Joints 10/110, 85/70, 90/180 (a classic Goodman & Shi example).
  const Eigen::Vector3d n1 = n_deg(10, 110), n2 = n_deg(85, 70), n3 = n_deg(90, 180);
  const Eigen::Vector3d i12 = n1.cross(n2), i13 = n1.cross(n3), i23 = n2.cross(n3);
  // Published to 4 decimals.
  EXPECT_NEAR(i12.x(), -0.3407, 5e-5);
  EXPECT_NEAR(i12.y(), 0.9077, 5e-5);
  EXPECT_NEAR(i12.z(), 0.1112, 5e-5);
  EXPECT_NEAR(i13.x(), 0.9848, 5e-5);
  EXPECT_NEAR(i13.z(), -0.1632, 5e-5);
  EXPECT_NEAR(i23.x(), 0.0872, 5e-5);
  EXPECT_NEAR(i23.z(), -0.9361, 5e-5);

  const Cone jp000({n1, n2, n3});
  EXPECT_GT(jp000.margin().angle, 0);
  const auto rays = jp000.edges();
  ASSERT_EQ(rays.size(), 3u);
  // Edges recomputed from the same normals: equal to rounding (1e-12).
  EXPECT_TRUE(has_ray(rays, i13, 1e-12));
  EXPECT_TRUE(has_ray(rays, -i12, 1e-12));
  EXPECT_TRUE(has_ray(rays, -i23, 1e-12));
}

TEST(Cone, MarginOfSimpleCones) {
  // One half-space: a direction can be 90 degrees inside.
  EXPECT_NEAR(Cone({Eigen::Vector3d::UnitZ()}).margin().angle, kPi / 2, 1e-12);
  // The positive octant: best direction (1,1,1)/sqrt3, margin asin(1/sqrt3).
  const Cone octant({Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()});
  const ConeMargin m = octant.margin();
  EXPECT_NEAR(m.angle, std::asin(1 / std::sqrt(3.0)), 1e-12);
  EXPECT_NEAR(m.direction.x(), 1 / std::sqrt(3.0), 1e-12);
  // Opposite octant added: shut by the same angle.
  const Cone shut = octant.intersect(Cone({-Eigen::Vector3d(1, 1, 1)}));
  EXPECT_LT(shut.margin().angle, 0);
}

TEST(Cone, ShutMarginIsHowFarEveryHalfSpaceMustOpen) {
  // Four half-spaces whose normals are the corners of a regular tetrahedron:
  // their centroid is the origin, so the cone is shut; the best direction is
  // opposite one normal, at asin(-1/3) outside the other three.
  const double s = 1 / std::sqrt(3.0);
  const Cone tet({Eigen::Vector3d(s, s, s), Eigen::Vector3d(s, -s, -s), Eigen::Vector3d(-s, s, -s),
                  Eigen::Vector3d(-s, -s, s)});
  EXPECT_NEAR(tet.margin().angle, std::asin(-1.0 / 3.0), 1e-12);
  EXPECT_TRUE(tet.edges().empty());
}

TEST(Cone, NearlyParallelPlanesGiveContinuousMargin) {
  // A thin wedge between z = 0 and a plane tilted by eps about the y axis,
  // closed sideways by |y| <= -x: open by exactly eps/2. Swapping the tilt
  // shuts it; the shut margin then scales with eps (the sides let the best
  // direction lean sideways, so it is not eps/2, but a fixed multiple of eps).
  // No sign flip and no jump however small eps gets.
  const Eigen::Vector3d side1(-1, 1, 0), side2(-1, -1, 0), back(-1, 0, 0);
  const double shut_ratio = -1 / (2 * std::sqrt(2.0));
  for (double eps : {1e-3, 1e-6, 1e-9}) {
    const Eigen::Vector3d a = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d open_b = -Eigen::Vector3d(std::sin(eps), 0, std::cos(eps));
    const Eigen::Vector3d shut_b = -Eigen::Vector3d(-std::sin(eps), 0, std::cos(eps));
    // Rounding of the normals is ~1e-16; the optimum is a triple candidate
    // built from them, good to ~1e-16 / eps relative, i.e. well under 1e-12
    // of eps/2 absolute even at eps = 1e-9.
    EXPECT_NEAR(Cone({a, open_b, side1, side2, back}).margin().angle, eps / 2, 1e-12) << eps;
    const double shut = Cone({a, shut_b, side1, side2, back}).margin().angle;
    EXPECT_LT(shut, 0) << eps;
    // The ratio differs from its limit by a first-order term (~0.13 eps) and,
    // at eps = 1e-9, by ~1e-7 relative rounding; eps bounds both.
    EXPECT_NEAR(shut / eps, shut_ratio, std::max(eps, 1e-6)) << eps;
  }
}

TEST(Cone, OppositeHalfSpacesLeaveAPlane) {
  // z >= 0 and z <= 0: the plane z = 0, margin zero, whatever else cuts it
  // within the plane.
  EXPECT_NEAR(Cone({Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()}).margin().angle, 0, 1e-15);
  EXPECT_NEAR(
      Cone({Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ(), Eigen::Vector3d(1, 0, 0.3)})
          .margin()
          .angle,
      0, 1e-15);
}

TEST(Cone, MarginIsInvariantUnderRotationAndOrder) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Eigen::Vector3d> ns;
    for (int i = 0; i < 5; ++i) ns.emplace_back(g(rng), g(rng), g(rng));
    const double base = Cone(ns).margin().angle;
    const Eigen::Matrix3d r = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    std::vector<Eigen::Vector3d> turned;
    for (auto it = ns.rbegin(); it != ns.rend(); ++it) turned.push_back(r * *it);
    // Same optimum evaluated on rotated normals: equal to rounding.
    EXPECT_NEAR(Cone(turned).margin().angle, base, 1e-12);
  }
}

TEST(Cone, MarginIsTheOptimumAgainstSampling) {
  // No direction sampled on the sphere beats the computed optimum.
  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Eigen::Vector3d> ns;
    for (int i = 0; i < 4 + trial % 4; ++i) ns.emplace_back(g(rng), g(rng), g(rng));
    const Cone c(ns);
    const double best = c.margin().angle;
    for (int k = 0; k < 2000; ++k) {
      const Eigen::Vector3d d(g(rng), g(rng), g(rng));
      EXPECT_LE(c.margin_of(d), best + 1e-12);
    }
  }
}

// The incremental search (issue 17) against the direct one after every
// added half-space: random cones (open and shut), a thin wedge of nearly
// parallel planes down to 1e-9 rad, opposite half-spaces, repeated normals
// and four planes through one line.
void expect_incremental_as_direct(const std::vector<Eigen::Vector3d>& ns, const std::string& what) {
  IncrementalMargin inc;
  Cone direct;
  for (size_t k = 0; k < ns.size(); ++k) {
    inc.add(ns[k]);
    direct.add(ns[k]);
    const ConeMargin a = inc.margin(), b = direct.margin();
    // The same candidates evaluated in the same arithmetic: equal but for
    // the order of a min (exact) and candidates the incremental search drops
    // within 1e-12 of their tight value (see kCutSine): 1e-12 bounds it.
    EXPECT_NEAR(a.angle, b.angle, 1e-12) << what << ", " << k + 1 << " half-spaces";
    // The reported direction achieves the margin: its least dot product is
    // the margin's sine (to rounding, 1e-15; sines, as asin is steep near 1).
    EXPECT_NEAR(std::sin(direct.margin_of(a.direction)), std::sin(a.angle), 1e-12)
        << what << ", " << k + 1;
  }
}

TEST(Cone, IncrementalMarginIsTheDirectMargin) {
  std::mt19937 rng(17);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Eigen::Vector3d> ns;
    const int m = 3 + trial % 20;
    // Half the trials in a hemisphere (open cones), half anywhere (shut).
    for (int i = 0; i < m; ++i) {
      Eigen::Vector3d n(g(rng), g(rng), g(rng));
      if (trial % 2 == 0) n.z() = std::abs(n.z()) + 0.5;
      ns.push_back(n);
    }
    expect_incremental_as_direct(ns, "random " + std::to_string(trial));
  }
  // Many normals (rotation spaces have up to ~60), and normals on one great
  // circle (limit planes through one line) before others join.
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<Eigen::Vector3d> ns;
    for (int i = 0; i < 6 + trial % 3; ++i) {
      const double a = g(rng);
      ns.emplace_back(0, std::cos(a), std::sin(a));
    }
    for (int i = 0; i < 4 + 3 * trial; ++i) {
      Eigen::Vector3d n(g(rng), g(rng), g(rng));
      if (trial % 2 == 0) n.z() = std::abs(n.z()) + 0.5;
      ns.push_back(n);
    }
    expect_incremental_as_direct(ns, "great circle, then more " + std::to_string(trial));
  }
  const Eigen::Vector3d side1(-1, 1, 0), side2(-1, -1, 0), back(-1, 0, 0);
  for (double eps : {1e-3, 1e-6, 1e-9}) {
    const Eigen::Vector3d a = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d open_b = -Eigen::Vector3d(std::sin(eps), 0, std::cos(eps));
    const Eigen::Vector3d shut_b = -Eigen::Vector3d(-std::sin(eps), 0, std::cos(eps));
    expect_incremental_as_direct({a, open_b, side1, side2, back}, "open wedge");
    expect_incremental_as_direct({side1, a, back, shut_b, side2}, "shut wedge");
  }
  expect_incremental_as_direct({Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ(),
                                Eigen::Vector3d(1, 0, 0.3), Eigen::Vector3d(-1, 0.2, 0.1)},
                               "opposite");
  expect_incremental_as_direct({Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(1, 0, 1),
                                Eigen::Vector3d(0, 1, 1), Eigen::Vector3d(-1, -1, 1)},
                               "repeated");
  // Four planes through the x axis, and two more.
  expect_incremental_as_direct(
      {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 1, 1),
       Eigen::Vector3d(0, -1, 2), Eigen::Vector3d(1, 0.1, 0.1), Eigen::Vector3d(-1, 0.3, 0.2)},
      "four through a line");
}

// The active-set margin (rotation spaces, pyramids in block finiteness)
// against the direct search, open and shut cones of 7 to 40 half-spaces
// (the direct search is O(m^4): 40 keeps the test quick).
TEST(Cone, ActiveSetMarginIsTheDirectMargin) {
  std::mt19937 rng(23);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 40; ++trial) {
    Cone cone;
    const int m = 7 + trial % 34;
    for (int i = 0; i < m; ++i) {
      Eigen::Vector3d n(g(rng), g(rng), g(rng));
      if (trial % 2 == 0) n.z() = std::abs(n.z()) + 1.5;  // open
      cone.add(n);
    }
    for (size_t direct_up_to : {size_t{0}, size_t{6}}) {
      const ConeMargin a = active_set_margin(cone, direct_up_to), b = cone.margin();
      // Both are the best of the same candidates, evaluated in the same
      // arithmetic but for the order of a min (exact) and those the
      // incremental search drops within 1e-12 of their tight value.
      EXPECT_NEAR(a.angle, b.angle, 1e-12) << "trial " << trial;
      EXPECT_NEAR(a.sine, std::sin(a.angle), 1e-15) << "trial " << trial;
      // Its direction achieves it (sines: rounding, 1e-15).
      EXPECT_NEAR(std::sin(cone.margin_of(a.direction)), a.sine, 1e-12) << "trial " << trial;
    }
  }
}

TEST(Cone, FromUnitNormalsKeepsThemAndRejectsOthers) {
  const std::vector<Eigen::Vector3d> unit = {
      Eigen::Vector3d(1, 2, 2) / 3, Eigen::Vector3d(0, 0.6, 0.8), -Eigen::Vector3d::UnitX()};
  const Cone c = Cone::from_unit_normals(unit);
  ASSERT_EQ(c.normals().size(), 3u);
  for (size_t i = 0; i < unit.size(); ++i) EXPECT_EQ(c.normals()[i], unit[i]);
  EXPECT_NEAR(c.margin().angle, Cone(unit).margin().angle, 1e-15);
  EXPECT_THROW(Cone::from_unit_normals({Eigen::Vector3d(1, 1, 0)}), std::invalid_argument);
  EXPECT_THROW(Cone::from_unit_normals({Eigen::Vector3d(NAN, 0, 0)}), std::invalid_argument);
}

TEST(Cone, UnionEmptiness) {
  const Cone down({-Eigen::Vector3d::UnitZ()});
  const Cone east({Eigen::Vector3d::UnitX()});
  // A narrow cone about +z (half-angle atan(0.5)).
  const Cone narrow_up({Eigen::Vector3d(1, 0, 0.5), Eigen::Vector3d(-1, 0, 0.5),
                        Eigen::Vector3d(0, 1, 0.5), Eigen::Vector3d(0, -1, 0.5)});
  const UnionEmptiness shut = intersection_with_union_empty(narrow_up, {down});
  EXPECT_TRUE(shut.empty);
  EXPECT_GT(shut.margin, 0);
  const UnionEmptiness open = intersection_with_union_empty(narrow_up, {down, east});
  EXPECT_FALSE(open.empty);
  EXPECT_EQ(open.open_index, 1);
}

}  // namespace
}  // namespace rockface::geometry

#include "core/geometry/stereonet.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/common/units.h"

namespace rockface::geometry {
namespace {

// Closed-form projections in double precision: 1e-12.
constexpr double kClosedForm = 1e-12;

TEST(Stereonet, VerticalAxisAtCentreHorizontalOnPrimitive) {
  for (auto p : {Projection::EqualAngle, Projection::EqualArea}) {
    EXPECT_NEAR(project_direction(Eigen::Vector3d(0, 0, -1), p, Hemisphere::Lower).norm(), 0,
                kClosedForm);
    const Eigen::Vector2d east = project_direction(Eigen::Vector3d(1, 0, 0), p, Hemisphere::Lower);
    EXPECT_NEAR(east.x(), 1, kClosedForm);
    EXPECT_NEAR(east.y(), 0, kClosedForm);
  }
}

TEST(Stereonet, RadiusFollowsWulffAndSchmidt) {
  // A line plunging 30 degrees to the North: angle from the vertical 60.
  const Eigen::Vector3d d = line_direction({0, deg_to_rad(30)});
  const double theta = deg_to_rad(60);
  const Eigen::Vector2d wulff = project_direction(d, Projection::EqualAngle, Hemisphere::Lower);
  const Eigen::Vector2d schmidt = project_direction(d, Projection::EqualArea, Hemisphere::Lower);
  EXPECT_NEAR(wulff.y(), std::tan(theta / 2), kClosedForm);
  EXPECT_NEAR(schmidt.y(), std::sqrt(2.0) * std::sin(theta / 2), kClosedForm);
  EXPECT_NEAR(wulff.x(), 0, kClosedForm);
  // The same axis given upward lands on the same point; the upper
  // hemisphere folds it the other way.
  EXPECT_NEAR((project_direction(-d, Projection::EqualAngle, Hemisphere::Lower) - wulff).norm(), 0,
              kClosedForm);
  EXPECT_NEAR((project_direction(d, Projection::EqualAngle, Hemisphere::Upper) + wulff).norm(), 0,
              kClosedForm);
}

TEST(Stereonet, PoleIsOppositeTheDipDirection) {
  // The pole of a plane dipping 40 towards 090 plunges 50 towards 270.
  const Eigen::Vector2d pole =
      project_pole({deg_to_rad(40), deg_to_rad(90)}, Projection::EqualArea, Hemisphere::Lower);
  EXPECT_LT(pole.x(), 0);
  EXPECT_NEAR(pole.y(), 0, kClosedForm);
  EXPECT_NEAR(-pole.x(), std::sqrt(2.0) * std::sin(deg_to_rad(40) / 2), kClosedForm);
}

TEST(Stereonet, GreatCircleRunsFromStrikeToStrikeThroughTheDip) {
  const PlaneOrientation plane{deg_to_rad(40), deg_to_rad(90)};
  const auto pts = project_great_circle(plane, Projection::EqualAngle, Hemisphere::Lower, 91);
  ASSERT_EQ(pts.size(), 91u);
  // Ends on the primitive along the strike (North-South), middle at the dip.
  EXPECT_NEAR(pts.front().norm(), 1, kClosedForm);
  EXPECT_NEAR(pts.back().norm(), 1, kClosedForm);
  EXPECT_NEAR(std::abs(pts.front().y()), 1, kClosedForm);
  EXPECT_NEAR(pts[45].y(), 0, kClosedForm);
  EXPECT_NEAR(pts[45].x(), std::tan(deg_to_rad(90 - 40) / 2), kClosedForm);
  // Every point is a direction in the plane: inside the primitive.
  for (const auto& p : pts) EXPECT_LE(p.norm(), 1 + kClosedForm);
}

}  // namespace
}  // namespace rockface::geometry

TEST(Stereonet, DirectionAtInvertsTheProjection) {
  using namespace rockface::geometry;
  for (Projection p : {Projection::EqualArea, Projection::EqualAngle})
    for (Hemisphere h : {Hemisphere::Lower, Hemisphere::Upper})
      for (double plunge : {0.0, 0.3, 1.0, 1.5707963267948966})
        for (double trend : {0.0, 1.0, 3.0, 5.5}) {
          Eigen::Vector3d d = line_direction({trend, plunge});
          if (h == Hemisphere::Upper) d = -d;
          const auto back = direction_at(project_direction(d, p, h), p, h);
          ASSERT_TRUE(back.has_value());
          // On the primitive (plunge 0) both senses plot at the same place.
          EXPECT_LT(std::min((*back - d).norm(), plunge == 0 ? (*back + d).norm() : 1.0), 1e-12);
        }
  EXPECT_FALSE(direction_at({0.8, 0.8}, Projection::EqualArea, Hemisphere::Lower).has_value());
}

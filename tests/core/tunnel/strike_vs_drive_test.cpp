// Bieniawski's classes of joint orientation against the drive, row by row of
// the RMR89 table, the oblique band, and the margins to the boundaries.
#include "core/tunnel/strike_vs_drive.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/geometry/orientation.h"

namespace rockface::tunnel {
namespace {

constexpr double kRad = std::numbers::pi / 180;

StrikeVsDrive classify(double dip, double dipdir, double trend, double uncertainty = 5) {
  return strike_vs_drive(geometry::PlaneOrientation{dip * kRad, dipdir * kRad}, trend * kRad,
                         uncertainty);
}

// Margins are differences of degrees computed from radians and back:
// ~1e-13 degrees of rounding.
constexpr double kDegRounding = 1e-9;

TEST(StrikeVsDrive, EveryRowOfTheTable) {
  // Drive north (trend 0). Strike perpendicular: dip direction north (with)
  // or south (against).
  StrikeVsDrive r = classify(60, 10, 0);
  EXPECT_EQ(r.cls, DriveClass::very_favourable);
  EXPECT_EQ(r.rmr_adjustment, 0);
  EXPECT_EQ(r.relation, StrikeRelation::perpendicular);
  EXPECT_TRUE(r.with_dip);
  EXPECT_NEAR(r.strike_to_axis_deg, 80, kDegRounding);
  EXPECT_NE(r.words.find("drive with dip, dip 45-90: very favourable"), std::string::npos)
      << r.words;

  r = classify(30, 350, 0);
  EXPECT_EQ(r.cls, DriveClass::favourable);
  EXPECT_EQ(r.rmr_adjustment, -2);

  r = classify(60, 185, 0);
  EXPECT_EQ(r.cls, DriveClass::fair);
  EXPECT_FALSE(r.with_dip);
  EXPECT_EQ(r.rmr_adjustment, -5);

  r = classify(30, 180, 0);
  EXPECT_EQ(r.cls, DriveClass::unfavourable);
  EXPECT_EQ(r.rmr_adjustment, -10);

  // Strike parallel: dip direction east or west of a northward drive.
  r = classify(70, 95, 0);
  EXPECT_EQ(r.cls, DriveClass::very_unfavourable);
  EXPECT_EQ(r.rmr_adjustment, -12);
  EXPECT_EQ(r.relation, StrikeRelation::parallel);
  EXPECT_NEAR(r.strike_to_axis_deg, 5, kDegRounding);

  r = classify(25, 270, 0);
  EXPECT_EQ(r.cls, DriveClass::fair);
  EXPECT_EQ(r.relation, StrikeRelation::parallel);

  // Irrespective of strike.
  r = classify(12, 0, 0);
  EXPECT_EQ(r.cls, DriveClass::fair);
  EXPECT_EQ(r.relation, StrikeRelation::irrespective);
  EXPECT_NEAR(r.margin_deg, 8, kDegRounding);  // to dip 20
}

TEST(StrikeVsDrive, TheDriveDirectionDecidesWithOrAgainst) {
  // The same joints, the drive turned round: with becomes against.
  EXPECT_EQ(classify(60, 10, 0).cls, DriveClass::very_favourable);
  EXPECT_EQ(classify(60, 10, 180).cls, DriveClass::fair);
  // Dip direction 0 and 360 are one direction.
  EXPECT_EQ(classify(60, 359.999, 0.001).cls, DriveClass::very_favourable);
  // From vectors: a normal and its negative are one plane.
  const Eigen::Vector3d n = geometry::plane_normal_deg(60, 10);
  EXPECT_EQ(strike_vs_drive(n, Eigen::Vector3d(0, 1, 0.05)).cls, DriveClass::very_favourable);
  EXPECT_EQ(strike_vs_drive(-n, Eigen::Vector3d(0, 1, 0.05)).cls, DriveClass::very_favourable);
  EXPECT_EQ(strike_vs_drive(n, Eigen::Vector3d(0, -1, 0)).cls, DriveClass::fair);
}

TEST(StrikeVsDrive, ObliqueStrikeTakesTheLessFavourableNeighbour) {
  // 45 deg between strike and axis, steep, drive with dip: perpendicular
  // would be very favourable, parallel very unfavourable: the latter.
  StrikeVsDrive r = classify(60, 45, 0);
  EXPECT_EQ(r.relation, StrikeRelation::oblique);
  EXPECT_TRUE(r.oblique);
  EXPECT_EQ(r.cls, DriveClass::very_unfavourable);
  EXPECT_NEAR(r.strike_to_axis_deg, 45, kDegRounding);
  EXPECT_NEAR(r.margin_deg, 15, kDegRounding);  // to the bands at 30 and 60
  EXPECT_NE(r.words.find("oblique"), std::string::npos);
  // Gentle and against: perpendicular unfavourable (-10), parallel fair (-5).
  r = classify(30, 180 + 40, 0);
  EXPECT_EQ(r.cls, DriveClass::unfavourable);
  EXPECT_NEAR(r.strike_to_axis_deg, 50, kDegRounding);
  // Across 60 deg (perpendicular) it stays unfavourable; the nearest change
  // is at dip 20 (fair, irrespective of strike).
  EXPECT_NEAR(r.margin_deg, 10, kDegRounding);
}

TEST(StrikeVsDrive, MarginsAndMarginalCases) {
  // Strike 62 deg to the axis, dip 50 with: 2 deg from the oblique band.
  StrikeVsDrive r = classify(50, 28, 0, 5);
  EXPECT_EQ(r.cls, DriveClass::very_favourable);
  EXPECT_NEAR(r.margin_deg, 2, kDegRounding);
  EXPECT_TRUE(r.marginal);
  EXPECT_FALSE(classify(50, 28, 0, 1).marginal);
  // Dip 44 deg, perpendicular with dip: 1 deg from very favourable.
  r = classify(44, 0, 0);
  EXPECT_EQ(r.cls, DriveClass::favourable);
  EXPECT_NEAR(r.margin_deg, 1, kDegRounding);
  // A vertical joint across the drive: "with" or "against" is a matter of
  // which way its normal was written; the class hangs on it (margin 0).
  r = classify(90, 0, 0);
  EXPECT_EQ(r.margin_deg, 0);
  EXPECT_TRUE(r.marginal);
  // Steep joints parallel to the drive: the sense does not matter, and the
  // oblique band keeps the class (its less favourable neighbour is this
  // one): the nearest change is at dip 45 (fair).
  r = classify(89, 90, 0);
  EXPECT_EQ(r.cls, DriveClass::very_unfavourable);
  EXPECT_NEAR(r.margin_deg, 44, kDegRounding);
}

}  // namespace
}  // namespace rockface::tunnel

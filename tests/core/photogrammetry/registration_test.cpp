// Registration: range pole, north from a compass bearing, control points,
// base length; and the control-point file.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/photogrammetry/estimators/registration.h"

namespace rp = rockface::photogrammetry;
using rockface::deg_to_rad;

TEST(RangePole, ScalesAndMakesThePoleVertical) {
  // A pole seen from a camera tilted 10 deg down: in the camera frame "up" is
  // -y turned by the tilt. Model units: the pole is 0.37 long.
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd(deg_to_rad(10), Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d up_cam = tilt * Eigen::Vector3d(0, -1, 0);
  const Eigen::Vector3d lower(0.2, 0.5, 3.0), upper = lower + 0.37 * up_cam;
  const rp::Similarity s = rp::range_pole_registration(lower, upper, 2.0);
  EXPECT_NEAR(s.scale, 2.0 / 0.37, 1e-12);
  const Eigen::Vector3d l = s.apply(lower), u = s.apply(upper);
  // Exact arithmetic up to rounding.
  EXPECT_LT(l.norm(), 1e-12);
  EXPECT_LT((u - Eigen::Vector3d(0, 0, 2.0)).norm(), 1e-12);
  EXPECT_NEAR(s.R.determinant(), 1.0, 1e-12);
}

TEST(RangePole, RejectsAPoleUpsideDown) {
  EXPECT_THROW(rp::range_pole_registration({0, 0, 3}, {0, 1, 3}, 2.0), rockface::InputError);
  EXPECT_THROW(rp::range_pole_registration({0, 0, 3}, {0, 0, 3}, 2.0), rockface::InputError);
}

TEST(North, TurnsAboutTheVerticalOnly) {
  // A line bearing 30 deg in the model; the compass says 40 deg magnetic and
  // the declination is 3 deg east: true bearing 43 deg.
  const Eigen::Vector3d a(1, 2, 5),
      b = a + Eigen::Vector3d(std::sin(deg_to_rad(30)), std::cos(deg_to_rad(30)), 0.2);
  const rp::Similarity n = rp::north_rotation(a, b, 40.0, 3.0, a);
  EXPECT_NEAR(rp::horizontal_azimuth_deg(n.apply(a), n.apply(b)), 43.0, 1e-9);
  EXPECT_LT((n.apply(a) - a).norm(), 1e-12);  // about the pivot
  EXPECT_NEAR((n.R * Eigen::Vector3d::UnitZ()).z(), 1.0, 1e-15);
}

TEST(North, BearingAcrossNorthWrapsTo0To360) {
  EXPECT_NEAR(rp::horizontal_azimuth_deg({0, 0, 0}, {-1, 1, 0}), 315.0, 1e-12);
  const rp::Similarity n = rp::north_rotation({0, 0, 0}, {-1, 1, 0}, 355.0, 10.0);
  EXPECT_NEAR(rp::horizontal_azimuth_deg({0, 0, 0}, n.apply({-1, 1, 0})), 5.0, 1e-9);
}

TEST(North, VerticalReferenceLineIsRefused) {
  EXPECT_THROW(rp::horizontal_azimuth_deg({0, 0, 0}, {0.01, 0, 1}), rockface::InputError);
}

TEST(ControlPoints, RecoversTheSimilarityAndNamesTheWorstPoint) {
  // Survey coordinates of 10^6 m: the datum keeps them precise.
  const Eigen::Vector3d offset(512340.0, 5211870.0, 410.0);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, -0.3, 1).normalized()).toRotationMatrix();
  const double scale = 4.2;
  std::vector<Eigen::Vector3d> model{
      {0, 0, 3}, {1, 0, 3.2}, {0, 1, 2.9}, {1, 1, 3.5}, {0.5, 0.4, 3.1}};
  std::vector<rp::ControlPoint> gcp;
  for (std::size_t i = 0; i < model.size(); ++i)
    gcp.push_back({"P" + std::to_string(i + 1), {0, 0}, scale * (R * model[i]) + offset});
  gcp[3].world += Eigen::Vector3d(0.05, 0, 0);  // one point surveyed 5 cm off
  const rp::ControlPointRegistration reg = rp::register_to_control_points(model, gcp, "gcp.csv");
  EXPECT_EQ(reg.worst_id, "P4");
  ASSERT_EQ(reg.residuals.size(), 5u);
  // One 5 cm blunder among five points: least squares spreads it, the
  // blunder keeps most (~4/5 of it, ~4 cm) and the rest get ~1 cm.
  EXPECT_GT(reg.worst_m, 0.02);
  EXPECT_LT(reg.rms_m, 0.03);
  EXPECT_NEAR(reg.transform.scale, scale, 0.05);
  // Absolute coordinates are datum + transformed model.
  const Eigen::Vector3d p0 = reg.transform.apply(model[0]) + reg.datum;
  EXPECT_LT((p0 - gcp[0].world).norm(), 0.03);
}

TEST(ControlPoints, ExactPointsFitExactly) {
  std::vector<Eigen::Vector3d> model{{0, 0, 3}, {1, 0, 3.2}, {0, 1, 2.9}};
  std::vector<rp::ControlPoint> gcp;
  for (std::size_t i = 0; i < model.size(); ++i)
    gcp.push_back(
        {"G" + std::to_string(i), {0, 0}, 2.0 * model[i] + Eigen::Vector3d(1e6, 5e6, 300)});
  const auto reg = rp::register_to_control_points(model, gcp, "gcp.csv");
  // Only rounding: survey coordinates near 5e6 m in double carry ~1e-9 m.
  EXPECT_LT(reg.rms_m, 1e-6);
  EXPECT_NEAR(reg.transform.scale, 2.0, 1e-9);
}

TEST(ControlPoints, CollinearPointsAreRefused) {
  std::vector<Eigen::Vector3d> model{{0, 0, 3}, {1, 0, 3}, {2, 0, 3}};
  std::vector<rp::ControlPoint> gcp{
      {"A", {0, 0}, {0, 0, 0}}, {"B", {0, 0}, {1, 0, 0}}, {"C", {0, 0}, {2, 0, 0}}};
  try {
    rp::register_to_control_points(model, gcp, "gcp.csv");
    FAIL();
  } catch (const rockface::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos);
  }
}

TEST(ControlPointFile, ParsesHeaderCommentsAndNamesBadLines) {
  std::istringstream ok(
      "id,u,v,X,Y,Z\n# surveyed 2026-11-20\nA, 10.5, 20, 512340.1, 5211870.2, "
      "410.3\r\nB,1,2,3,4,5\n");
  const auto pts = rp::parse_control_points(ok, "gcp.csv");
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[0].id, "A");
  EXPECT_DOUBLE_EQ(pts[0].pixel.x(), 10.5);
  EXPECT_DOUBLE_EQ(pts[0].world.y(), 5211870.2);

  std::istringstream bad("A,1,2,3,4,5\nB,1,x,3,4,5\n");
  try {
    rp::parse_control_points(bad, "gcp.csv");
    FAIL();
  } catch (const rockface::InputError& e) {
    EXPECT_EQ(e.where(), "gcp.csv line 2");
  }
  std::istringstream twice("A,1,2,3,4,5\nA,1,2,3,4,5\n");
  EXPECT_THROW(rp::parse_control_points(twice, "gcp.csv"), rockface::InputError);
  std::istringstream short_line("A,1,2,3\n");
  EXPECT_THROW(rp::parse_control_points(short_line, "gcp.csv"), rockface::InputError);
}

TEST(Baseline, ScalesByTheMeasuredBase) {
  EXPECT_DOUBLE_EQ(rp::baseline_scale(1.6).scale, 1.6);
  EXPECT_THROW(rp::baseline_scale(0), rockface::InputError);
}

TEST(Similarity, ComposesInOrder) {
  rp::Similarity a{
      2.0, Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix(), {1, 2, 3}};
  rp::Similarity b{
      0.5, Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitX()).toRotationMatrix(), {-4, 0, 1}};
  const Eigen::Vector3d x(0.3, -0.7, 2.0);
  EXPECT_LT((a.then(b).apply(x) - b.apply(a.apply(x))).norm(), 1e-12);
}

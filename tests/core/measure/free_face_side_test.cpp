// The rock side of a free face (core/measure/free_face_side.h) measured
// with measure_picks on synthetic 3D images seen by a pinhole camera 0.5 m
// above the origin looking north (tests/support/folded_face.h): the
// same polygon tapped either way round gives the same record; a pick's
// rock_side the photograph contradicts is refused, or read as "behind the
// face" near vertical; a face seen edge-on takes the pick's side, marked
// marginal with its angle, or is refused where that side means nothing.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/pick_measurement.h"
#include "core/measure/tolerances.h"
#include "tests/support/folded_face.h"

namespace {

using namespace rockface;
using rockface::test::FoldedFace;

constexpr double kNoise = 0.005;  // m along the rays: a stereo model's sigma_Z at 10 m

// One plane a*x + b*y + c*z = d (the camera side first) as the whole 3D
// image, cut to x in [x_from, x_to] and z in [z_from, z_to].
FoldedFace one_plane(const Eigen::Vector3d& normal, const Eigen::Vector3d& through, double x_from,
                     double x_to, double z_from, double z_to, double noise) {
  FoldedFace f;
  geometry::Plane p;
  p.normal = normal.normalized();
  p.offset = p.normal.dot(through);
  f.facets.push_back({p, x_from, x_to});
  f.z_from = z_from;
  f.z_to = z_to;
  test::look_at_lattice(f, 800, 600, noise, 2);
  return f;
}

// A face 10 m north of the camera, y = 10 + lean * z: leaning back
// (lean > 0: its rock below it) or overhanging (lean < 0).
FoldedFace face(double lean) {
  return one_plane({0, -1, lean}, {0, 10, 0}, -4, 4, -2, 2.5, kNoise);
}

// The corners of a 2 m x 2 m patch of the face around the camera's axis,
// counter-clockwise as the camera sees them (image v grows downwards).
std::vector<Eigen::Vector2d> patch_of(const FoldedFace& f) {
  std::vector<Eigen::Vector3d> corners;
  for (const auto& xz : {Eigen::Vector2d(-1, 1.5), Eigen::Vector2d(-1, -0.5),
                         Eigen::Vector2d(1, -0.5), Eigen::Vector2d(1, 1.5)}) {
    const auto p = f.hit(f.view.pose.centre,
                         (Eigen::Vector3d(xz.x(), 10, xz.y()) - f.view.pose.centre).normalized());
    EXPECT_TRUE(p);
    corners.push_back(*p);
  }
  return test::pixels_of(f, corners);
}

std::vector<Eigen::Vector2d> reversed(std::vector<Eigen::Vector2d> v) {
  std::reverse(v.begin(), v.end());
  return v;
}

measure::MeasuredPicks measure_one(const FoldedFace& f, const measure::MeshPicker& picker,
                                   const std::vector<Eigen::Vector2d>& polygon,
                                   const std::string& rock_side) {
  measure::Picks picks;
  measure::AreaPick a;
  a.id = "F1";
  a.where = "areas[0]";
  a.photo = "left";
  a.polygon = polygon;
  a.rock_side = rock_side;
  picks.areas.push_back(a);
  measure::MeasureContext c;
  c.picker = &picker;
  c.views["left"] = f.view;
  c.settings.point_sigma = kNoise;
  c.source = "PICKS.json";
  return measure::measure_picks(picks, c, std::nullopt);
}

// The corners' Newell normal (twice the vector area).
Eigen::Vector3d newell(const std::vector<Eigen::Vector3d>& p) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) n += (p[i] - p[0]).cross(p[(i + 1) % p.size()] - p[0]);
  return n;
}

bool wound_toward_camera(const measure::AreaMeasurement& a, const FoldedFace& f) {
  return newell(a.outline_points).dot(f.view.pose.centre - a.plane.fit.centroid) > 0;
}

// `refused` throws InputError whose message names `field` and holds `words`.
template <typename F>
void expect_refused(F refused, const std::string& field, const std::string& words) {
  try {
    refused();
    ADD_FAILURE() << "accepted; expected a refusal at " << field;
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(field), std::string::npos) << m;
    EXPECT_NE(m.find(words), std::string::npos) << m;
  }
}

TEST(FreeFaceSide, EitherTapOrderGivesTheSameRecord) {
  // Leaning back 16.7 deg (dip 73.3 deg toward the camera): the rock below.
  const FoldedFace f = face(0.3);
  const measure::MeshPicker picker(f.mesh);
  const auto ccw = measure_one(f, picker, patch_of(f), "lower");
  const auto cw = measure_one(f, picker, reversed(patch_of(f)), "lower");
  ASSERT_EQ(ccw.areas.size(), 1u);
  ASSERT_EQ(cw.areas.size(), 1u);
  const auto &a = ccw.areas[0], &b = cw.areas[0];
  ASSERT_TRUE(a.m.plane.known) << a.m.plane.problem;
  // The same mesh vertices inside either way round, the same fit: equal.
  EXPECT_EQ(a.m.plane.fit.normal, b.m.plane.fit.normal);
  EXPECT_EQ(a.m.area, b.m.area);
  for (const auto* x : {&a, &b}) {
    EXPECT_EQ(x->rock_side, "lower");
    EXPECT_EQ(x->rock_side_from, "photograph");
    EXPECT_FALSE(x->marginal);
    EXPECT_TRUE(x->m.plane.problem.empty()) << x->m.plane.problem;
    EXPECT_TRUE(wound_toward_camera(x->m, f));
    // The sight lines from the patch (2 m across, 10 m off) meet the face at
    // 90 - 16.7 deg, give or take the 6 deg the corners are off the axis.
    EXPECT_GT(x->sight.least_deg, 60.0);
    EXPECT_TRUE(x->sight.told());
    EXPECT_DOUBLE_EQ(x->sight.needed_deg, measure::kMinFreeFaceViewDeg);  // sigma ~0.01 deg
  }
  // The stored corners: the same polygon in the same order (counter-
  // clockwise seen from the camera, as tapped in `ccw`).
  ASSERT_EQ(a.m.outline_points.size(), 4u);
  EXPECT_EQ(a.m.outline_points, b.m.outline_points);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(a.m.outline[i].pixel, b.m.outline[i].pixel) << i;
  // The outward normal is the plane's upward one (the air above a face
  // leaning back): the rock on its lower side.
  EXPECT_GT(a.sight.outward.dot(geometry::plane_normal(a.m.plane.orientation)), 0);
}

TEST(FreeFaceSide, AnOverhangSeenFromBelowHasItsRockAbove) {
  const FoldedFace f = face(-0.3);  // overhanging 16.7 deg
  const measure::MeshPicker picker(f.mesh);
  for (const auto& polygon : {patch_of(f), reversed(patch_of(f))}) {
    const auto m = measure_one(f, picker, polygon, "upper");
    EXPECT_EQ(m.areas[0].rock_side, "upper");
    EXPECT_EQ(m.areas[0].rock_side_from, "photograph");
    EXPECT_TRUE(wound_toward_camera(m.areas[0].m, f));
  }
}

TEST(FreeFaceSide, ARockSideThePhotographContradictsIsRefusedByName) {
  const FoldedFace f = face(0.3);  // the camera sees it from above: its rock is below
  const measure::MeshPicker picker(f.mesh);
  expect_refused([&] { measure_one(f, picker, patch_of(f), "upper"); },
                 "PICKS.json: areas[0].rock_side", "the rock behind it is on its lower side");
}

TEST(FreeFaceSide, NearVerticalTheSideBehindTheFaceHoldsAndTheNoteSaysSo) {
  // 1.1 deg from vertical, leaning back or overhanging: "upper" and "lower"
  // swap there; the photograph's side holds whatever the pick says.
  for (const double lean : {0.02, -0.02}) {
    const FoldedFace f = face(lean);
    const measure::MeshPicker picker(f.mesh);
    const std::string behind = lean > 0 ? "lower" : "upper";
    const std::string other = lean > 0 ? "upper" : "lower";
    const auto agreeing = measure_one(f, picker, patch_of(f), behind);
    EXPECT_EQ(agreeing.areas[0].rock_side, behind);
    EXPECT_TRUE(agreeing.areas[0].m.plane.problem.empty()) << agreeing.areas[0].m.plane.problem;
    const auto m = measure_one(f, picker, reversed(patch_of(f)), other);
    const auto& a = m.areas[0];
    EXPECT_EQ(a.rock_side, behind) << lean;
    EXPECT_EQ(a.rock_side_from, "photograph");
    EXPECT_FALSE(a.marginal);
    EXPECT_TRUE(wound_toward_camera(a.m, f));
    EXPECT_NE(a.m.plane.problem.find("rock_side \"" + other + "\" read as behind the face"),
              std::string::npos)
        << a.m.plane.problem;
    EXPECT_NE(a.m.plane.problem.find("from vertical"), std::string::npos) << a.m.plane.problem;
  }
}

// A plane dipping 45 deg east whose plane passes 0.2 m below-west of the
// camera centre (0, 0, 0.5): a patch 9-11 m north on it is seen at
// asin(0.2 / ~10) = 1.0-1.3 deg, edge-on. Noise-free: the plane is exact, so
// its sigma does not set the need (kMinFreeFaceViewDeg does).
TEST(FreeFaceSide, EdgeOnTakesThePicksSideMarkedMarginalWithItsAngle) {
  const Eigen::Vector3d up = Eigen::Vector3d(1, 0, 1).normalized();
  const Eigen::Vector3d centre(0, 0, 0.5);
  const FoldedFace f = one_plane(up, centre + 0.2 * up, -0.5, 1.5, -2, 2.5, 0);
  const measure::MeshPicker picker(f.mesh);
  const double c = up.dot(centre + 0.2 * up) * std::sqrt(2.0);  // x + z on the plane
  std::vector<Eigen::Vector3d> corners{
      {0.2, 9, c - 0.2}, {0.6, 9, c - 0.6}, {0.6, 11, c - 0.6}, {0.2, 11, c - 0.2}};
  const auto polygon = test::pixels_of(f, corners);
  for (const std::string side : {"upper", "lower"}) {
    std::vector<Eigen::Vector3d> stored;
    for (const auto& p : {polygon, reversed(polygon)}) {
      const auto m = measure_one(f, picker, p, side);
      const auto& a = m.areas[0];
      ASSERT_TRUE(a.m.plane.known) << a.m.plane.problem;
      // The plane measured is the one built (noise-free: to rounding).
      EXPECT_LT(std::abs(std::abs(a.m.plane.fit.normal.dot(up)) - 1), 1e-9);
      EXPECT_EQ(a.rock_side, side);
      EXPECT_EQ(a.rock_side_from, "pick");
      EXPECT_TRUE(a.marginal);
      EXPECT_FALSE(a.sight.told());
      // Its margin: 0.2 m off the plane seen from 9-11.2 m: 1.0-1.3 deg.
      EXPECT_GT(a.sight.least_deg, 0.9);
      EXPECT_LT(a.sight.least_deg, 1.4);
      EXPECT_LT(a.sight.margin_deg(), 0);
      EXPECT_NE(a.m.plane.problem.find("marginal: rock side \"" + side + "\" from the pick alone"),
                std::string::npos)
          << a.m.plane.problem;
      EXPECT_NE(a.m.plane.problem.find("edge-on"), std::string::npos) << a.m.plane.problem;
      // Wound with the air on the side the pick does not give the rock.
      const double air = newell(a.m.outline_points).dot(up);
      EXPECT_TRUE(side == "lower" ? air > 0 : air < 0) << side;
      if (stored.empty())
        stored = a.m.outline_points;
      else
        EXPECT_EQ(a.m.outline_points, stored) << "either tap order, one record";
    }
  }
}

TEST(FreeFaceSide, EdgeOnAndNearVerticalIsRefused) {
  // The vertical plane x = 0.2, 6-12 m north: seen from (0, 0, 0.5) at
  // asin(0.2 / 6-12 m) = 1.9-1.0 deg, 10 px wide in the photograph (five
  // lattice columns: a plane, not a sliver).
  const FoldedFace f = one_plane({1, 0, 0}, {0.2, 0, 0}, 0.1, 0.3, -2, 2.5, 0);
  const measure::MeshPicker picker(f.mesh);
  const auto polygon =
      test::pixels_of(f, {{0.2, 6, 1.0}, {0.2, 6, 0.0}, {0.2, 12, 0.0}, {0.2, 12, 1.0}});
  measure::MeasureSettings settings;
  settings.point_sigma = kNoise;
  const auto area = measure::measure_area(picker, f.view, "F1", polygon, settings, "areas[0]");
  ASSERT_TRUE(area.plane.known) << area.plane.problem;
  expect_refused([&] { measure_one(f, picker, polygon, "lower"); }, "PICKS.json: areas[0]",
                 "edge-on");
}

TEST(FreeFaceSide, AnAreaThatIsNoFreeFaceIsWoundTowardTheCamera) {
  const FoldedFace f = face(0.3);
  const measure::MeshPicker picker(f.mesh);
  const auto m = measure_one(f, picker, reversed(patch_of(f)), "");
  EXPECT_TRUE(m.areas[0].rock_side.empty());
  EXPECT_TRUE(m.areas[0].rock_side_from.empty());
  EXPECT_TRUE(wound_toward_camera(m.areas[0].m, f));
}

}  // namespace

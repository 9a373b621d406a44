// A trace's plane from a compass reading (issue 27) on a folded face whose
// geometry is known exactly (folded_face.h): a straight trace with no plane
// of its own takes the reading's; a trace lying in the plane read has a
// positive margin, one 15 degrees out of it is marginal and says so; a trace
// with a plane of its own keeps the reading and reports the difference; an
// impossible reading is refused by its field.
#include <algorithm>
#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/measure/compass_reading.h"
#include "core/measure/pick_measurement.h"
#include "tests/support/folded_face.h"

namespace rm = rockface::measure;
namespace rg = rockface::geometry;
using rockface::deg_to_rad;
using rockface::rad_to_deg;

namespace {

// A steep joint striking across the middle facet only: its trace is a
// straight line on one flat facet (no plane of its own).
struct StraightTrace {
  rockface::test::FoldedFace face = rockface::test::folded_face(800, 600, 0.005);
  rm::MeshPicker picker{face.mesh};
  rg::Plane joint = rockface::test::plane_through(85, 270, {0.2, 10.0, 0.0});
  rm::MeasureSettings settings;
  rm::TraceMeasurement measure() {
    settings.point_sigma = 0.005;
    const auto seg = face.trace_on(joint, 1);
    EXPECT_TRUE(seg);
    const Eigen::Vector3d a = (*seg)[0], b = (*seg)[1];
    const auto picks = rockface::test::pixels_of(face, {a + 0.05 * (b - a), b - 0.05 * (b - a)});
    return rm::measure_trace(picker, face.view, "T2", picks, settings, "traces[1]");
  }
};

}  // namespace

TEST(CompassReading, AStraightTraceTakesTheReadingItLiesIn) {
  StraightTrace s;
  rm::TraceMeasurement t = s.measure();
  ASSERT_FALSE(t.plane.known) << "the straight trace has no plane of its own";
  const rm::CompassCheck c = rm::apply_compass_reading(t, {85, 270}, "traces[1].compass");
  ASSERT_TRUE(t.plane.known);
  // The reading itself, exactly (only degrees to radians and back).
  EXPECT_NEAR(rad_to_deg(t.plane.orientation.dip), 85, 1e-9);
  EXPECT_NEAR(rad_to_deg(t.plane.orientation.dipdir), 270, 1e-9);
  EXPECT_NEAR(rad_to_deg(t.plane.sigma), rm::kCompassSigmaDeg, 1e-12);
  // Through the trace's points: the plane passes the centroid.
  EXPECT_NEAR(t.plane.fit.plane().signed_distance(t.plane.fit.centroid), 0, 1e-12);
  // The trace lies in the joint: its line leaves the plane read by the
  // direction error of ~1 m of points with 5 mm noise (a few tenths of a
  // degree); 1 degree bounds it.
  EXPECT_LT(c.trace_off_deg, 1.0);
  EXPECT_FALSE(c.fitted_off_deg) << "no plane of its own to compare";
  EXPECT_NEAR(c.margin_deg, rm::kMaxTraceOffCompassDeg - c.trace_off_deg, 1e-12);
  EXPECT_FALSE(c.marginal());
  EXPECT_NE(t.plane.problem.find("compass reading"), std::string::npos) << t.plane.problem;
  EXPECT_EQ(t.plane.problem.find("check the reading"), std::string::npos) << t.plane.problem;
}

TEST(CompassReading, ATrace15DegreesOutOfThePlaneReadIsMarginalAndSaysSo) {
  StraightTrace s;
  rm::TraceMeasurement t = s.measure();
  // The plane read turned 15 degrees about the line across the trace in
  // the joint: the trace's line then leaves it by 15 degrees.
  const Eigen::Vector3d line = t.plane.fit.line.normalized();
  const Eigen::Vector3d axis = s.joint.normal.cross(line).normalized();
  const Eigen::Vector3d turned = Eigen::AngleAxisd(deg_to_rad(15), axis) * s.joint.normal;
  const rg::PlaneOrientation o = rg::plane_orientation(turned);
  const rm::CompassCheck c =
      rm::apply_compass_reading(t, {rad_to_deg(o.dip), rad_to_deg(o.dipdir)}, "compass");
  // 15 degrees, less the trace's own direction error (as above, < 1 degree).
  EXPECT_NEAR(c.trace_off_deg, 15, 1.0);
  EXPECT_TRUE(c.marginal());
  EXPECT_NEAR(c.margin_deg, rm::kMaxTraceOffCompassDeg - c.trace_off_deg, 1e-12);
  EXPECT_LT(c.margin_deg, -4.0);
  EXPECT_NE(t.plane.problem.find("out of the compass plane: check the reading"), std::string::npos)
      << t.plane.problem;
  EXPECT_TRUE(t.plane.known) << "kept, but marked, not silently accepted";
}

TEST(CompassReading, ATraceWithAPlaneOfItsOwnKeepsTheReadingAndReportsTheDifference) {
  const auto face = rockface::test::folded_face(800, 600, 0.005);
  const rm::MeshPicker picker(face.mesh);
  const rg::Plane joint = rockface::test::plane_through(40, 60, {0.0, 10.0, 0.3});
  std::vector<Eigen::Vector3d> ends;
  for (std::size_t k = 0; k < face.facets.size(); ++k)
    if (auto seg = face.trace_on(joint, k)) {
      ends.push_back((*seg)[0] + 0.02 * ((*seg)[1] - (*seg)[0]));
      ends.push_back((*seg)[1] - 0.02 * ((*seg)[1] - (*seg)[0]));
    }
  std::sort(ends.begin(), ends.end(), [](const auto& p, const auto& q) { return p.x() < q.x(); });
  rm::MeasureSettings settings;
  settings.point_sigma = 0.005;
  rm::TraceMeasurement t = rm::measure_trace(
      picker, face.view, "T1", rockface::test::pixels_of(face, ends), settings, "traces[0]");
  ASSERT_TRUE(t.plane.known) << t.plane.problem;
  // A reading 3 degrees steeper than the joint (a compass's error and more).
  const rm::CompassCheck c = rm::apply_compass_reading(t, {43, 60}, "compass");
  ASSERT_TRUE(c.fitted_off_deg);
  // The fitted plane is within ~0.1 degree of the joint (trace_measurement_
  // test.cpp), so 3 degrees from the reading to a few tenths.
  EXPECT_NEAR(*c.fitted_off_deg, 3.0, 0.3);
  EXPECT_FALSE(c.marginal());
  EXPECT_NEAR(rad_to_deg(t.plane.orientation.dip), 43, 1e-9);
  EXPECT_NE(t.plane.problem.find("the plane fitted to the trace"), std::string::npos)
      << t.plane.problem;
}

TEST(CompassReading, AnImpossibleReadingIsRefusedByItsField) {
  StraightTrace s;
  rm::TraceMeasurement t = s.measure();
  auto where = [&](rm::CompassReading r) {
    try {
      rm::apply_compass_reading(t, r, "picks.json: traces[1].compass");
    } catch (const rockface::InputError& e) {
      return e.where();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(where({95, 120}), "picks.json: traces[1].compass.dip");
  EXPECT_EQ(where({-1, 120}), "picks.json: traces[1].compass.dip");
  EXPECT_EQ(where({std::nan(""), 120}), "picks.json: traces[1].compass.dip");
  EXPECT_EQ(where({60, 361}), "picks.json: traces[1].compass.dip_direction");
  EXPECT_EQ(where({60, -0.5}), "picks.json: traces[1].compass.dip_direction");
  EXPECT_EQ(where({60, INFINITY}), "picks.json: traces[1].compass.dip_direction");
  EXPECT_FALSE(t.plane.known) << "a refused reading leaves the trace as it was";
  // 360 is north, as 0: the plane is the same.
  rm::apply_compass_reading(t, {60, 360}, "compass");
  EXPECT_NEAR(rad_to_deg(t.plane.orientation.dipdir), 0, 1e-9);
}

namespace {

// A pick "T2" given by its points along the straight trace (5 % in from its
// ends), for measure_picks; none when the face has no such trace.
std::optional<rm::TracePick> pick_along(const StraightTrace& s, const std::string& joint) {
  const auto seg = s.face.trace_on(s.joint, 1);
  if (!seg) return std::nullopt;
  rm::TracePick pick;
  pick.id = "T2";
  pick.joint = joint;
  pick.where = "traces[0]";
  pick.points = {(*seg)[0] + 0.05 * ((*seg)[1] - (*seg)[0]),
                 (*seg)[1] - 0.05 * ((*seg)[1] - (*seg)[0])};
  return pick;
}

rm::MeasureContext context_of(const StraightTrace& s) {
  rm::MeasureContext context;
  context.picker = &s.picker;
  context.settings = s.settings;
  return context;
}

}  // namespace

TEST(CompassReading, MeasurePicksTakesTheReadingOfAPick) {
  StraightTrace s;
  s.settings.point_sigma = 0.005;
  auto pick = pick_along(s, "");
  ASSERT_TRUE(pick);
  pick->compass = rm::CompassReading{85, 270};
  rm::Picks picks;
  picks.traces.push_back(*pick);
  const rm::MeasureContext context = context_of(s);
  const auto measured = rm::measure_picks(picks, context, std::nullopt);
  ASSERT_EQ(measured.traces.size(), 1u);
  ASSERT_TRUE(measured.traces[0].compass);
  EXPECT_TRUE(measured.traces[0].m.plane.known);
  EXPECT_NEAR(rad_to_deg(measured.traces[0].m.plane.orientation.dip), 85, 1e-9);
  EXPECT_EQ(measured.poles.size(), 1u) << "the read plane is a pole of the sets";
}

// A joint marked by a straight trace (no plane from its points) takes the
// reading of its trace, as the demo's J2 does: the replay and the analysis
// read the joint's plane, not the trace's.
TEST(CompassReading, AJointMarkedByAReadTraceTakesTheReading) {
  StraightTrace s;
  s.settings.point_sigma = 0.005;
  const auto pick = pick_along(s, "J2");
  ASSERT_TRUE(pick);
  rm::Picks picks;
  picks.traces.push_back(*pick);
  const rm::MeasureContext context = context_of(s);
  {
    const auto unread = rm::measure_picks(picks, context, std::nullopt);
    ASSERT_EQ(unread.joints.size(), 1u);
    EXPECT_FALSE(unread.joints[0].plane.known) << "a straight trace alone gives no plane";
  }
  picks.traces[0].compass = rm::CompassReading{85, 270};
  const auto measured = rm::measure_picks(picks, context, std::nullopt);
  ASSERT_EQ(measured.joints.size(), 1u);
  const auto& j = measured.joints[0].plane;
  ASSERT_TRUE(j.known) << j.problem;
  // The reading itself, only turned through a unit normal and back: to
  // rounding (1e-9 deg).
  EXPECT_NEAR(rad_to_deg(j.orientation.dip), 85, 1e-9);
  EXPECT_NEAR(rad_to_deg(j.orientation.dipdir), 270, 1e-9);
  EXPECT_NEAR(rad_to_deg(j.sigma), rm::kCompassSigmaDeg, 1e-12);
  EXPECT_NE(j.problem.find("compass reading of T2"), std::string::npos) << j.problem;
}

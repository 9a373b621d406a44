// The motion's events name the axis the block turns about (issue 39,
// "motion after failure, as told"): the slope wedge of 3DEC's example
// (J1 45/105, J2 50/235, the face F1 70/180), with friction from 0 to 30
// degrees and a pull toward the face, slides on both joints, tips over
// the lip where J1 meets the face and turns about a corner. Its events
// were named after the planes that carried load ("rotates about edge
// J1-J2") while its angular velocity ran 50-58 degrees away from the
// J1-J2 line. Here every "rotates about edge X-Y" is checked against the
// angular velocity in the path between that event and the next: the line
// X-Y is computed by the test from the scene's dips and dip directions,
// not by the code under test.
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "core/analysis/scene_analysis.h"
#include "core/common/progress.h"
#include "firmware-app/analysis/scene_input.h"
#include "storage/scene/scene.h"

namespace rockface {
namespace {

// The scene's planes: dip / dip direction (DESIGN.md: x east, y north, z up).
const std::map<std::string, std::pair<double, double>> kPlanes = {
    {"J1", {45, 105}}, {"J2", {50, 235}}, {"F1", {70, 180}}, {"F2", {0, 0}}};

Eigen::Vector3d normal_of(const std::string& plane) {
  const double dip = kPlanes.at(plane).first * M_PI / 180,
               dd = kPlanes.at(plane).second * M_PI / 180;
  return {std::sin(dip) * std::sin(dd), std::sin(dip) * std::cos(dd), std::cos(dip)};
}

std::string wedge(double friction_deg, double pull_g) {
  const std::string f = std::to_string(friction_deg), a = std::to_string(-9.80665 * pull_g);
  return R"({ "format": "rockface-scene/1",
  "joints": [
    { "id": "J1", "dip": 45, "dipdir": 105, "point": [5, 5, 2], "friction": )" +
         f + R"( },
    { "id": "J2", "dip": 50, "dipdir": 235, "point": [5, 5, 2], "friction": )" +
         f + R"( } ],
  "free_faces": [
    { "id": "F1", "dip": 70, "dipdir": 180, "point": [5, 0, 0], "rock_side": "lower" },
    { "id": "F2", "dip": 0, "dipdir": 0, "point": [5, 5, 10], "rock_side": "lower" } ],
  "blocks": [ { "id": "B1", "halfspaces": { "J1": "upper", "J2": "upper", "F1": "lower", "F2": "lower" } } ],
  "effects": { "seismic": { "acceleration": [0, )" +
         a + R"(, 0] } },
  "analysis": { "pyramids": false, "blocks": true,
                "dynamics": { "duration_s": 8.0, "sample_s": 0.002, "floor": { "elevation": -100 } } } })";
}

struct Checked {
  int edge_events = 0;
  int samples = 0;
};

// Every sample between an edge event and the next event turns about the
// named edge: the rock's lip (fixed) or the block's own edge (turned with
// the block), whichever the block pivots on, within the mode's own 5
// degrees (kAxisAngleRad). The mode is decided at every step and every
// event is located by bisection to ~1e-9 s, so no sample inside the
// interval lies beyond it: 0.01 degrees covers the sample's interpolation
// within a step (a Dormand-Prince step, ~1e-7 rad).
Checked check_edges(const analysis::ReportDynamics& d, const std::string& label) {
  Checked c;
  for (size_t e = 0; e < d.events.size(); ++e) {
    const std::string& what = d.events[e].what;
    const std::string prefix = "rotates about edge ";
    if (what.rfind(prefix, 0) != 0) continue;
    ++c.edge_events;
    const std::string pivot = what.substr(prefix.size());
    const size_t dash = pivot.find('-');
    EXPECT_NE(dash, std::string::npos) << label << ": " << what;
    if (dash == std::string::npos) continue;
    const std::string a = pivot.substr(0, dash), b = pivot.substr(dash + 1);
    EXPECT_TRUE(kPlanes.count(a) && kPlanes.count(b)) << label << ": " << what;
    if (!kPlanes.count(a) || !kPlanes.count(b)) continue;
    const Eigen::Vector3d line = normal_of(a).cross(normal_of(b)).normalized();
    const double from = d.events[e].time_s;
    const double to = e + 1 < d.events.size() ? d.events[e + 1].time_s : d.end_time_s;
    for (const analysis::ReportMotionSample& s : d.path) {
      if (s.time_s <= from || s.time_s >= to) continue;
      // Below 1e-4 rad/s the direction of the angular velocity is the
      // integration's noise, not a turn.
      if (s.angular_velocity.norm() < 1e-4) continue;
      const Eigen::Quaterniond q(s.orientation(0), s.orientation(1), s.orientation(2),
                                 s.orientation(3));
      const Eigen::Vector3d w = s.angular_velocity.normalized();
      const double off_lip = std::acos(std::min(1.0, std::abs(w.dot(line))));
      const double off_edge = std::acos(std::min(1.0, std::abs(w.dot(q.normalized() * line))));
      EXPECT_LE(std::min(off_lip, off_edge) * 180 / M_PI, 5.01)
          << label << ": " << what << " at " << s.time_s << " s";
      ++c.samples;
    }
  }
  return c;
}

TEST(MotionEvents, ARotationIsNamedByTheAxisItTurnsAbout) {
  int edge_events = 0, samples = 0;
  std::set<std::string> pivots;
  for (double friction : {0.0, 10.0, 20.0, 30.0})
    for (double pull : {0.1, 0.3, 0.6}) {
      const std::string label =
          "friction " + std::to_string(friction) + ", pull " + std::to_string(pull) + " g";
      SCOPED_TRACE(label);
      const storage::Scene scene = storage::parse_scene(wedge(friction, pull), "W.json");
      NoProgress progress;
      const analysis::Report r = analysis::analyse(app::analysis_input(scene), progress);
      ASSERT_EQ(r.blocks.size(), 1u);
      if (!r.blocks[0].dynamics) continue;  // it holds: nothing to tell
      const Checked c = check_edges(*r.blocks[0].dynamics, label);
      edge_events += c.edge_events;
      samples += c.samples;
      for (const auto& ev : r.blocks[0].dynamics->events)
        if (ev.what.rfind("rotates about edge ", 0) == 0) pivots.insert(ev.what);
    }
  // The cases turn about an edge and the check ran on their motion.
  EXPECT_GE(edge_events, 3);
  EXPECT_GE(samples, 10);
  for (const auto& p : pivots) std::printf("  %s\n", p.c_str());
}

}  // namespace
}  // namespace rockface

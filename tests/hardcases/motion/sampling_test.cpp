// The reporting interval does not change the motion (issue 40, "motion
// after failure"): a frictionless wedge (the slope-wedge sample's joints,
// as 3DEC's wedge example has them) analysed over 2 s with `sample_s`
// from 1 s down to 1e-4 s takes the same steps, passes through the same
// events and ends in the same place; its path is only sampled more or less
// often.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/analysis/scene_analysis.h"
#include "core/common/progress.h"
#include "firmware-app/analysis/scene_input.h"
#include "storage/scene/scene.h"

namespace rockface {
namespace {

// The wedge of tools/samples/slope-wedge.scene.json, 3 m high, with
// frictionless joints and the dynamics sample's 0.1 g towards the face:
// within 2 s it slides on both joints, turns about their edge and a
// corner, leaves one joint, then the other, and falls.
std::string frictionless_wedge(double sample_s) {
  char buf[2048];
  std::snprintf(
      buf, sizeof buf,
      "{ \"format\": \"rockface-scene/1\",\n"
      "  \"joints\": [\n"
      "    { \"id\": \"J1\", \"dip\": 45, \"dipdir\": 105, \"point\": [5, 5, 2], \"friction\": 0 "
      "},\n"
      "    { \"id\": \"J2\", \"dip\": 50, \"dipdir\": 235, \"point\": [5, 5, 2], \"friction\": 0 "
      "} ],\n"
      "  \"free_faces\": [\n"
      "    { \"id\": \"F1\", \"dip\": 70, \"dipdir\": 180, \"point\": [5, 0, 0], \"rock_side\": "
      "\"lower\" },\n"
      "    { \"id\": \"F2\", \"dip\": 0, \"dipdir\": 0, \"point\": [5, 5, 3], \"rock_side\": "
      "\"lower\" } ],\n"
      "  \"blocks\": [ { \"id\": \"B1\", \"halfspaces\": { \"J1\": \"upper\", \"J2\": \"upper\", "
      "\"F1\": \"lower\", \"F2\": \"lower\" } } ],\n"
      "  \"effects\": { \"seismic\": { \"acceleration\": [0, -0.98, 0] } },\n"
      "  \"analysis\": { \"pyramids\": false, \"blocks\": true,\n"
      "                \"dynamics\": { \"duration_s\": 2.0, \"sample_s\": %.17g } } }\n",
      sample_s);
  return buf;
}

analysis::ReportDynamics motion_of(double sample_s) {
  const storage::Scene scene = storage::parse_scene(frictionless_wedge(sample_s), "S.json");
  NoProgress progress;
  const analysis::Report r = analysis::analyse(app::analysis_input(scene), progress);
  if (r.blocks.size() != 1 || !r.blocks[0].dynamics)
    throw std::runtime_error("the frictionless wedge's motion was not simulated");
  return *r.blocks[0].dynamics;
}

// The block's size: the largest distance between two of its corners.
double size_of(const analysis::ReportBlock& b) {
  double d = 0;
  for (const auto& p : b.vertices)
    for (const auto& q : b.vertices) d = std::max(d, (p - q).norm());
  return d;
}

std::string sequence(const analysis::ReportDynamics& d) {
  std::string s;
  for (const analysis::ReportMotionEvent& e : d.events) s += e.what + "; ";
  return s;
}

TEST(MotionSampling, TheReportingIntervalDoesNotChangeTheMotion) {
  const storage::Scene scene = storage::parse_scene(frictionless_wedge(1), "S.json");
  NoProgress progress;
  const analysis::Report first = analysis::analyse(app::analysis_input(scene), progress);
  ASSERT_EQ(first.blocks.size(), 1u);
  ASSERT_TRUE(first.blocks[0].dynamics);
  const analysis::ReportDynamics& coarse = *first.blocks[0].dynamics;
  const double size = size_of(first.blocks[0]);
  // It does something worth sampling: it leaves its joints and falls.
  ASSERT_NE(sequence(coarse).find("leaves J1"), std::string::npos) << sequence(coarse);
  ASSERT_NE(sequence(coarse).find("free fall"), std::string::npos) << sequence(coarse);
  for (double sample_s : {0.5, 0.1, 0.05, 1e-2, 1e-3, 1e-4}) {
    SCOPED_TRACE("sample_s " + std::to_string(sample_s));
    const analysis::ReportDynamics fine = motion_of(sample_s);
    // The same steps: the step sequence is chosen by the error control and
    // the events alone, never cut short to land on a sample time.
    EXPECT_EQ(fine.steps, coarse.steps);
    EXPECT_EQ(fine.rejected_steps, coarse.rejected_steps);
    EXPECT_EQ(fine.evaluations, coarse.evaluations);
    // The same events at the same times: the steps being the same, each
    // event is found by the same bisection (kEventTimeRel x T, ~1e-9 s);
    // 1e-9 s allows nothing beyond that bisection's own resolution.
    ASSERT_EQ(sequence(fine), sequence(coarse));
    for (size_t i = 0; i < coarse.events.size(); ++i) {
      EXPECT_EQ(fine.events[i].kind, coarse.events[i].kind);
      EXPECT_NEAR(fine.events[i].time_s, coarse.events[i].time_s, 1e-9) << fine.events[i].what;
    }
    // The same end: the last sample is the state where the integration
    // ended (the end of the duration), not an interpolation. 1e-9 of the
    // block's size is the drift projection's bound (kDriftBoundRel), far
    // below the integration's own error (~1e-7 of it): only a different
    // path, never the integration's error, could move it further.
    ASSERT_FALSE(fine.path.empty());
    EXPECT_DOUBLE_EQ(fine.end_time_s, coarse.end_time_s);
    EXPECT_NEAR((fine.path.back().position - coarse.path.back().position).norm(), 0, 1e-9 * size);
    // The samples are at the times asked for, 0, sample_s, 2 sample_s, ...
    // (rounding of k x sample_s only), and one more at the end.
    const int every = static_cast<int>(std::lround(coarse.duration_s / sample_s));
    ASSERT_GE(fine.path.size(), static_cast<size_t>(every) + 1);
    for (int i = 0; i <= every; i += std::max(1, every / 50))
      EXPECT_NEAR(fine.path[i].time_s, i * sample_s, 1e-12) << i;
    // Where both runs have a sample (each whole second), they agree to the
    // integration's error: a sample between step ends is a step of the same
    // Dormand-Prince method from the last step's start, so it differs from a
    // sample at a step's end only by that step's local error and by the
    // drift the projection removes (both ~1e-7 of the block's size at the
    // standard preset); 1e-6 of it is allowed, as the closed forms do.
    for (const analysis::ReportMotionSample& c : coarse.path) {
      const double k = c.time_s / sample_s;
      if (std::abs(k - std::round(k)) > 1e-9) continue;
      const analysis::ReportMotionSample& f = fine.path.at(static_cast<size_t>(std::lround(k)));
      EXPECT_NEAR((f.position - c.position).norm(), 0, 1e-6 * size) << "t = " << c.time_s;
    }
  }
}

}  // namespace
}  // namespace rockface

// The report part of rotational kinematics: what analyse_block_rotation
// writes into a ReportBlock, in the report's units and frame.
#include <cmath>

#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/analysis/analyse_rotation.h"
#include "core/common/error.h"
#include "core/common/preset.h"
#include "core/kinematics/remote_axis.h"
#include "core/kinematics/rotation_input.h"
#include "core/kinematics/rotation_tolerances.h"
#include "tests/support/quick_check_blocks.h"
#include "tests/support/rotation_blocks.h"

namespace rockface::analysis {
namespace {

using Eigen::Vector3d;

const Vector3d kDatum(512340.0, 5211870.0, 410.0);

// The lined block of remote_axis_test.cpp (short lining: a remote axis
// exists, no corner or edge rotation), placed at survey coordinates.
blocks::Polyhedron lined_block() {
  const double b = 30 * M_PI / 180, k = 70 * M_PI / 180, f = 80 * M_PI / 180;
  std::vector<test_rotation::Side> s = {{"L", true, {1, 0, 0}, {0, 0, 0}},
                                        {"F", false, {std::sin(f), 0, -std::cos(f)}, {0, 0, 0.15}},
                                        {"B", true, {-std::sin(b), 0, std::cos(b)}, {0, 0, 0}},
                                        {"K", true, {-std::sin(k), 0, -std::cos(k)}, {2, 0, 0}},
                                        {"S1", true, {0, 1, 0}, {0, -1, 0}},
                                        {"S2", true, {0, -1, 0}, {0, 1, 0}}};
  for (auto& side : s) side.point += kDatum;
  return test_rotation::convex_polyhedron("B1", s, kDatum);
}

TEST(AnalyseRotationReport, FillsCornersEdgesAndRemoteAxisInAbsoluteCoordinates) {
  const blocks::Polyhedron block = lined_block();
  SceneAnalysis options;
  options.rotation = true;
  options.remote_axis = SceneRemoteAxis{64, 1};
  ReportBlock out;
  analyse_block_rotation(block, options, out);

  ASSERT_TRUE(out.rotation.has_value());
  // Static points: corners on both a joint and the free face F (its four
  // corners); edges: F's rim.
  EXPECT_EQ(out.rotation->corners.size(), 4u);
  EXPECT_EQ(out.rotation->edges.size(), 4u);
  for (const auto& c : out.rotation->corners) {
    EXPECT_GE(c.vertex, 0);
    EXPECT_LT(c.vertex, static_cast<int>(block.vertices().size()));
    EXPECT_FALSE(c.rotatable);
    EXPECT_GE(c.margin_deg, 0);  // the verdict's margin: how firmly "not rotatable" holds
  }
  ASSERT_TRUE(out.remote_axis.has_value());
  EXPECT_TRUE(out.remote_axis->found);
  // The search stops once the axis is found and the hit rate has settled
  // (issue 17): the starts run are those of the same search in the core.
  const auto core =
      kinematics::search_remote_axis(kinematics::rotation_input(block), {64, 1, true});
  EXPECT_EQ(out.remote_axis->starts, core.starts);
  EXPECT_EQ(out.remote_axis->hits, core.hits);
  EXPECT_LE(out.remote_axis->starts, 64);
  EXPECT_GT(out.remote_axis->hits, 0);
  EXPECT_NEAR(out.remote_axis->direction.y(), -1, 1e-6);  // slumping axis, to the hit tolerance
  // Absolute: within a few metres of the block's survey position (the axis
  // passes in front of the block, above the lining).
  EXPECT_LT((out.remote_axis->point - kDatum).norm(), 5);
  EXPECT_GT(out.remote_axis->point.x(), 5e5);
}

// A block that rotates about a corner or an edge has an axis: the search
// cannot change "found" and is skipped (issue 17); the axis reported is a
// feasible one.
TEST(AnalyseRotationReport, RotatableBlocksSkipTheSearchWithAFeasibleAxis) {
  int skipped = 0;
  for (const auto& block : test_rotation::quick_check_mix(3)) {
    SceneAnalysis options;
    options.rotation = true;
    options.remote_axis = SceneRemoteAxis{16, 1};
    ReportBlock out;
    analyse_block_rotation(block, options, out);
    ASSERT_TRUE(out.remote_axis.has_value());
    if (out.remote_axis->starts > 0) continue;
    ++skipped;
    EXPECT_TRUE(out.remote_axis->found) << block.id();
    EXPECT_EQ(out.remote_axis->hits, 0);
    ASSERT_FALSE(out.notes.empty());
    EXPECT_NE(out.notes.back().find("not searched"), std::string::npos);
    // The axis moves no corner into the rock (to the search's own hit
    // tolerance).
    const auto f = kinematics::remote_axis_feasibility(kinematics::rotation_input(block),
                                                       out.remote_axis->point - block.datum(),
                                                       out.remote_axis->direction);
    EXPECT_LE(f.max_violation, kinematics::kRemoteAxisHitRad) << block.id();
  }
  EXPECT_GT(skipped, 0);  // the mix has corner- or edge-rotatable blocks
}

TEST(AnalyseRotationReport, OptionsOffLeaveTheReportAlone) {
  const blocks::Polyhedron block = lined_block();
  SceneAnalysis options;
  options.rotation = false;
  ReportBlock out;
  analyse_block_rotation(block, options, out);
  EXPECT_FALSE(out.rotation.has_value());
  EXPECT_FALSE(out.remote_axis.has_value());
}

TEST(AnalyseRotationReport, StartsFollowThePresetUnlessTheSceneGivesThem) {
  const blocks::Polyhedron block = lined_block();
  for (const auto& [preset, starts] :
       std::vector<std::pair<std::string, int>>{{"fast", 16}, {"standard", 64}, {"precise", 256}}) {
    SceneAnalysis options;
    options.rotation = false;
    options.preset = rockface::parse_preset(preset, "preset");
    options.remote_axis = SceneRemoteAxis{};
    ReportBlock out;
    analyse_block_rotation(block, options, out);
    ASSERT_TRUE(out.remote_axis.has_value());
    // The preset's starts, of which the early stop (issue 17) runs those
    // the same search in the core runs.
    const auto core =
        kinematics::search_remote_axis(kinematics::rotation_input(block), {starts, 1, true});
    EXPECT_EQ(out.remote_axis->starts, core.starts) << preset;
    EXPECT_LE(out.remote_axis->starts, starts) << preset;
  }
  SceneAnalysis options;
  options.rotation = false;
  options.preset = rockface::Preset::precise;
  options.remote_axis = SceneRemoteAxis{8, 1};  // the scene's own count wins
  ReportBlock out;
  analyse_block_rotation(block, options, out);
  EXPECT_EQ(out.remote_axis->starts, 8);
}

TEST(AnalyseRotationReport, BadStartCountNamesTheField) {
  const blocks::Polyhedron block = lined_block();
  SceneAnalysis options;
  options.remote_axis = SceneRemoteAxis{0, 1};
  ReportBlock out;
  try {
    analyse_block_rotation(block, options, out);
    FAIL() << "no error for 0 starts";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "analysis.remote_axis.starts");
  }
}

}  // namespace
}  // namespace rockface::analysis

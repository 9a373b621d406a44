// Block verdicts for the table and the colours on the model, from the
// stored columns and the block's report JSON.
#include <gtest/gtest.h>

#include "ui/blocks/block_view.h"

namespace {

using rockface::storage::BlockResult;
using rockface::ui::BlockVerdict;
using rockface::ui::make_block_view;

BlockResult block(bool finite, bool removable, const std::string& mode, std::optional<double> fos,
                  bool marginal = false) {
  BlockResult b;
  b.label = "B";
  b.finite = finite;
  b.removable = removable;
  b.mode = mode;
  b.fos = fos;
  b.marginal = marginal;
  b.report_json = R"({"id": "B", "margin_deg": 4.5, "vertices": [[11, 22, 33], [12, 22, 33]],
      "rotation": {"corners": [{"vertex": 0, "rotatable": false}],
                   "edges": [{"vertices": [0, 1], "rotatable": true}]}})";
  return b;
}

TEST(BlockView, VerdictFollowsFinitenessRemovabilityModeAndFos) {
  const Eigen::Vector3d datum(10, 20, 30);
  EXPECT_EQ(make_block_view(block(true, true, "sliding", 0.49), datum).verdict,
            BlockVerdict::moves);
  EXPECT_EQ(make_block_view(block(true, true, "sliding", 1.3), datum).verdict, BlockVerdict::holds);
  EXPECT_EQ(make_block_view(block(true, true, "falling", {}), datum).verdict, BlockVerdict::moves);
  EXPECT_EQ(make_block_view(block(true, false, "none", {}), datum).verdict, BlockVerdict::keyed);
  EXPECT_EQ(make_block_view(block(false, false, "none", {}), datum).verdict,
            BlockVerdict::infinite);
  EXPECT_EQ(make_block_view(block(true, true, "sliding", 1.3, true), datum).verdict,
            BlockVerdict::marginal);
}

TEST(BlockView, ReportGivesMarginRotatabilityAndDatumRelativeVertices) {
  const auto v = make_block_view(block(true, true, "sliding", 0.49), Eigen::Vector3d(10, 20, 30));
  ASSERT_TRUE(v.margin_deg);
  EXPECT_EQ(*v.margin_deg, 4.5);
  ASSERT_TRUE(v.rotatable);
  EXPECT_TRUE(*v.rotatable);  // the edge is, the corner is not
  ASSERT_EQ(v.vertices.size(), 2u);
  EXPECT_EQ(v.vertices[1], Eigen::Vector3d(2, 2, 3));
  EXPECT_NE(v.report_text.find("margin_deg"), std::string::npos);
}

TEST(BlockView, SummaryStatesVerdictModeDirectionSizeAndRotationInWords) {
  BlockResult b = block(true, true, "sliding", 0.49);
  b.label = "TB3";
  b.report_json = R"({"margin_deg": 4.5, "volume": 1.25, "mass": 3400,
      "mode": {"type": "sliding", "planes": ["J1", "J2"], "direction": [0, -0.5, -0.5]},
      "rotation": {"corners": [{"vertex": 0, "rotatable": true, "margin_deg": 4.1},
                               {"vertex": 1, "rotatable": false, "margin_deg": 9}],
                   "edges": [{"vertices": [0, 1], "rotatable": false}]},
      "remote_axis": {"found": true, "starts": 64, "hits": 9},
      "face_areas": {"J1": 2.5}})";
  const auto lines = make_block_view(b, Eigen::Vector3d::Zero()).summary;
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  EXPECT_NE(text.find("Block TB3: moves"), std::string::npos) << text;
  EXPECT_NE(text.find("Margin 4.5°"), std::string::npos) << text;
  // Direction (0, -1, -1)/sqrt 2: due south (trend 180), plunging 45 degrees.
  EXPECT_NE(text.find("Mode: sliding on J1, J2, towards 180.0° trend, 45.0° plunge"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("Factor of safety 0.49"), std::string::npos) << text;
  EXPECT_NE(text.find("Volume 1.25 m³, mass 3.40 t"), std::string::npos) << text;
  EXPECT_NE(text.find("1 of 2 corners and 0 of 1 edges can rotate (least corner margin 4.1°)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("Remote axis: found (9 of 64 starts)"), std::string::npos) << text;
  EXPECT_NE(text.find("Face areas: J1 2.50 m²"), std::string::npos) << text;
  // The equilibrium path, when the scene asked for it: its limit point, or why there is none.
  b.report_json = R"({"mechanics": {"fos_limit_point": 0.71, "stability": "divergence"}})";
  EXPECT_EQ(make_block_view(b, Eigen::Vector3d::Zero()).summary.back(),
            "Equilibrium path: limit point at load factor 0.71, divergence");
  b.report_json = R"({"mechanics": {"fos_limit_point": null, "outcome": "fails under its loads"}})";
  EXPECT_EQ(make_block_view(b, Eigen::Vector3d::Zero()).summary.back(),
            "Equilibrium path: fails under its loads");
  // A block that already rotates about a corner is not searched for a remote axis.
  b.report_json = R"({"remote_axis": {"found": true, "starts": 0, "hits": 0}})";
  const auto skipped = make_block_view(b, Eigen::Vector3d::Zero()).summary;
  EXPECT_EQ(skipped.back(),
            "Remote axis: not searched, the block already rotates about a corner or an edge");
}

TEST(BlockView, SummaryOfAMalformedReportKeepsWhatTheColumnsSay) {
  BlockResult b = block(false, false, "none", {});
  b.report_json = "not json";
  const auto lines = make_block_view(b, Eigen::Vector3d::Zero()).summary;
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines[0], "Block B: not finite");
  EXPECT_EQ(lines[1], "not finite, not removable");
}

}  // namespace

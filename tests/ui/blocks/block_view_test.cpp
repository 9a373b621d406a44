// Block verdicts for the table and the colours on the model, from the
// block's verdict as the store reads it back (key columns and report JSON).
#include <gtest/gtest.h>

#include "core/analysis/block_reading.h"
#include "storage/report/report.h"
#include "ui/blocks/block_view.h"

namespace {

using rockface::analysis::BlockVerdict;
using rockface::analysis::ReportBlock;
using rockface::ui::make_block_view;

constexpr const char* kReport =
    R"({"id": "B", "margin_deg": 4.5, "vertices": [[11, 22, 33], [12, 22, 33]],
      "rotation": {"corners": [{"vertex": 0, "rotatable": false}],
                   "edges": [{"vertices": [0, 1], "rotatable": true}]}})";

// The block a stored row gives: its report JSON read back, the key columns
// (verdict, mode, factor of safety) over it.
ReportBlock with_report(const ReportBlock& columns, const std::string& report_json) {
  ReportBlock b = rockface::storage::block_from_json(report_json);
  b.id = columns.id;
  b.source = columns.source;
  b.finite = columns.finite;
  b.removable = columns.removable;
  b.marginal = columns.marginal;
  b.fos = columns.fos;
  if (columns.mode) {
    if (!b.mode) b.mode = rockface::analysis::ReportMode{};
    b.mode->type = columns.mode->type;
  }
  return b;
}

ReportBlock block(bool finite, bool removable, const std::string& mode, std::optional<double> fos,
                  bool marginal = false) {
  ReportBlock b;
  b.id = "B";
  b.source = "";  // a row's source column, left empty here
  b.finite = finite;
  b.removable = removable;
  if (mode != "none") {
    b.mode = rockface::analysis::ReportMode{};
    b.mode->type = mode;
  }
  b.fos = fos;
  b.marginal = marginal;
  return with_report(b, kReport);
}

TEST(BlockView, VerdictFollowsFinitenessRemovabilityModeAndFos) {
  EXPECT_EQ(make_block_view(block(true, true, "sliding", 0.49)).verdict, BlockVerdict::moves);
  EXPECT_EQ(make_block_view(block(true, true, "sliding", 1.3)).verdict, BlockVerdict::holds);
  EXPECT_EQ(make_block_view(block(true, true, "falling", {})).verdict, BlockVerdict::moves);
  EXPECT_EQ(make_block_view(block(true, false, "none", {})).verdict, BlockVerdict::keyed);
  EXPECT_EQ(make_block_view(block(false, false, "none", {})).verdict, BlockVerdict::infinite);
  EXPECT_EQ(make_block_view(block(true, true, "sliding", 1.3, true)).verdict,
            BlockVerdict::marginal);
}

TEST(BlockView, ReportGivesMarginRotatabilityAndDatumRelativeVertices) {
  const auto v = make_block_view(block(true, true, "sliding", 0.49));
  EXPECT_EQ(v.block.margin_deg, 4.5);
  const auto rotatable = rockface::analysis::can_rotate(v.block);
  ASSERT_TRUE(rotatable);
  EXPECT_TRUE(*rotatable);  // the edge is, the corner is not
  const auto vertices = rockface::analysis::relative_to(v.block.vertices, {10, 20, 30});
  ASSERT_EQ(vertices.size(), 2u);
  EXPECT_EQ(vertices[1], Eigen::Vector3d(2, 2, 3));
}

TEST(BlockView, SummaryStatesVerdictModeDirectionSizeAndRotationInWords) {
  ReportBlock b = block(true, true, "sliding", 0.49);
  std::string report;
  b.id = "TB3";
  report = R"({"margin_deg": 4.5, "volume": 1.25, "mass": 3400,
      "mode": {"type": "sliding", "planes": ["J1", "J2"], "direction": [0, -0.5, -0.5]},
      "rotation": {"corners": [{"vertex": 0, "rotatable": true, "margin_deg": 4.1},
                               {"vertex": 1, "rotatable": false, "margin_deg": 9}],
                   "edges": [{"vertices": [0, 1], "rotatable": false}]},
      "remote_axis": {"found": true, "starts": 64, "hits": 9},
      "face_areas": {"J1": 2.5}})";
  const auto lines = make_block_view(with_report(b, report)).summary;
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
  report = R"({"mechanics": {"fos_limit_point": 0.71, "stability": "divergence"}})";
  EXPECT_EQ(make_block_view(with_report(b, report)).summary.back(),
            "Equilibrium path: limit point at load factor 0.71, divergence");
  report = R"({"mechanics": {"fos_limit_point": null, "outcome": "fails under its loads"}})";
  EXPECT_EQ(make_block_view(with_report(b, report)).summary.back(),
            "Equilibrium path: fails under its loads");
  // A block that already rotates about a corner is not searched for a remote axis.
  report = R"({"remote_axis": {"found": true, "starts": 0, "hits": 0}})";
  const auto skipped = make_block_view(with_report(b, report)).summary;
  EXPECT_EQ(skipped.back(),
            "Remote axis: not searched, the block already rotates about a corner or an edge");
}

TEST(BlockView, SummaryOfAMalformedReportKeepsWhatTheColumnsSay) {
  ReportBlock b = block(false, false, "none", {});
  std::string report;
  report = "not json";
  const auto lines = make_block_view(with_report(b, report)).summary;
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines[0], "Block B: not finite");
  EXPECT_EQ(lines[1], "not finite, not removable");
}

}  // namespace

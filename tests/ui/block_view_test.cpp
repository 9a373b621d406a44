// Block verdicts for the table and the colours on the model, from the
// stored columns and the block's report JSON.
#include <gtest/gtest.h>

#include "ui/block_view.h"

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

}  // namespace

// The reader of one block of the report (storage/report/report_block_reader.cpp)
// on rows it did not write: lenient, it never throws. The round trip through
// the project file is tests/storage/project/project_block_row_test.cpp.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "storage/report/report.h"

namespace {

using rockface::analysis::ReportBlock;
using rockface::storage::block_from_json;

// The reader on its own: a part that is not what the writer makes is left
// out whole, a field of another type left at its default; it never throws.
TEST(ReportBlockReader, MalformedPartsAreLeftOut) {
  const ReportBlock b = block_from_json(
      R"({"id": 7, "source": "scene", "finite": "yes", "volume": null, "margin_deg": 2,
          "mode": {"type": "falling", "direction": [0, 0]},
          "dynamics": {"path": [{"t": "soon"}]}, "remote_axis": [1, 2],
          "face_areas": {"J1": 1.5, "J2": "big"}, "notes": ["kept", 3]})");
  EXPECT_EQ(b.id, "");
  EXPECT_EQ(b.source, "scene");
  EXPECT_FALSE(b.finite);
  ASSERT_TRUE(b.volume);
  EXPECT_TRUE(std::isnan(*b.volume)) << "null is an unknown, written by the writer for NaN";
  EXPECT_EQ(b.margin_deg, 2);
  ASSERT_TRUE(b.mode);
  EXPECT_EQ(b.mode->type, "falling");
  EXPECT_FALSE(b.mode->direction);
  EXPECT_FALSE(b.dynamics);
  EXPECT_FALSE(b.remote_axis);
  EXPECT_EQ(b.face_areas.size(), 1u);
  EXPECT_EQ(b.notes, std::vector<std::string>{"kept"});
  EXPECT_NO_THROW(block_from_json(""));
  EXPECT_NO_THROW(block_from_json("[1, 2]"));
}

}  // namespace

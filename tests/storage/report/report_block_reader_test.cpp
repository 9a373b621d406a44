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

// A block's faces (loops of vertex indices) come back only when every loop
// indexes the vertices read: a vertex left out shifts the indices, and a
// mesh with a wrong face is worse than none.
TEST(ReportBlockReader, FacesComeBackOnlyWhenEveryLoopIndexesTheVertices) {
  const std::string tetra = R"("vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]],)"
                            R"( "faces": [[0,2,1],[0,1,3],[1,2,3],[0,3,2]])";
  ReportBlock b = block_from_json("{" + tetra + "}");
  ASSERT_EQ(b.faces.size(), 4u);
  EXPECT_EQ(b.faces[2], (std::vector<int>{1, 2, 3}));
  b = block_from_json(
      R"({"vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "faces": [[0,2,1],[0,1,4]]})");
  EXPECT_TRUE(b.faces.empty()) << "index 4 of 4 vertices";
  b = block_from_json(
      R"({"vertices": [[0,0,0],[1,0],[0,1,0],[0,0,1]], "faces": [[0,2,1],[0,1,3]]})");
  EXPECT_EQ(b.vertices.size(), 3u);
  EXPECT_TRUE(b.faces.empty()) << "a malformed vertex shifts the indices";
  b = block_from_json(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1]]})");
  EXPECT_TRUE(b.faces.empty()) << "a loop of two";
}

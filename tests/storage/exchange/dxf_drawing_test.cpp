// The DXF writer (storage/exchange/dxf_drawing.h) on what it must refuse, and
// on what it writes as the DXF reference gives it: read back here as group
// code / value pairs (the office's reader, ezdxf, reads the same files in
// tests/integration/export).
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "storage/exchange/dxf_drawing.h"

namespace {

namespace fs = std::filesystem;
using rockface::InputError;
using rockface::storage::dxf_layer_name;
using rockface::storage::DxfDrawing;

std::vector<std::pair<int, std::string>> groups(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::pair<int, std::string>> out;
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value)) {
    if (!value.empty() && value.back() == '\r') value.pop_back();
    out.emplace_back(std::stoi(code), value);
  }
  return out;
}

TEST(DxfDrawing, RefusesWhatWouldMakeABrokenFileNamingTheLayer) {
  DxfDrawing d;
  d.add_layer("TRACES_S1", 1);
  EXPECT_THROW(d.add_polyline("NOT_ADDED", {{0, 0, 0}, {1, 0, 0}}, false), InputError);
  EXPECT_THROW(d.add_polyline("TRACES_S1", {{0, 0, 0}}, false), InputError);
  try {
    d.add_polyline("TRACES_S1", {{0, 0, 0}, {std::nan(""), 0, 0}}, false);
    ADD_FAILURE() << "a NaN point was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("TRACES_S1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("point 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(d.add_mesh("TRACES_S1", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}}), InputError);
  EXPECT_THROW(d.add_mesh("TRACES_S1", {{0, 0, 0}}, {}), InputError);
  EXPECT_EQ(d.entity_count(), 0u);
}

TEST(DxfDrawing, LayerNamesAreOnesAutoCadAccepts) {
  EXPECT_EQ(dxf_layer_name("blocks_not finite"), "BLOCKS_NOT_FINITE");
  EXPECT_EQ(dxf_layer_name("joints/S<2>"), "JOINTS_S_2_");
  EXPECT_EQ(dxf_layer_name(""), "UNNAMED");
}

TEST(DxfDrawing, WritesThreeDPolylinesAndClosedPolyfacesAtSurveyCoordinates) {
  const fs::path file =
      fs::temp_directory_path() / ("rockface-dxf-" + std::to_string(::getpid()) + ".dxf");
  DxfDrawing d;
  d.add_layer("TRACES_S1", 1);
  d.add_layer("BLOCKS_MOVES", 1);
  // Survey coordinates: 0.1 mm must survive at 5 x 10^6 m.
  const Eigen::Vector3d e0{512340.1234, 5211870.5678, 410.0001};
  d.add_polyline("TRACES_S1", {e0, e0 + Eigen::Vector3d(1, 0, 0.5)}, false);
  const std::vector<Eigen::Vector3d> tetra{e0, e0 + Eigen::Vector3d(1, 0, 0),
                                           e0 + Eigen::Vector3d(0, 1, 0),
                                           e0 + Eigen::Vector3d(0, 0, 1)};
  d.add_mesh("BLOCKS_MOVES", tetra, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  d.write(file);
  const auto g = groups(file);
  fs::remove(file);
  int polylines = 0, vertices = 0, face_records = 0, seqends = 0;
  std::vector<double> xs;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (g[i].first == 0 && g[i].second == "POLYLINE") ++polylines;
    if (g[i].first == 0 && g[i].second == "SEQEND") ++seqends;
    if (g[i].first == 0 && g[i].second == "VERTEX") ++vertices;
    if (g[i].first == 100 && g[i].second == "AcDbFaceRecord") ++face_records;
    if (g[i].first == 10 && std::stod(g[i].second) > 1e5) xs.push_back(std::stod(g[i].second));
  }
  EXPECT_EQ(polylines, 2);
  EXPECT_EQ(seqends, 2);
  EXPECT_EQ(vertices, 2 + 4 + 4);  // the polyline's points, the mesh's vertices and faces
  EXPECT_EQ(face_records, 4);
  ASSERT_FALSE(xs.empty());
  // dxflib writes 16 decimals: the first easting comes back to far below 0.1 mm.
  EXPECT_NEAR(xs.front(), 512340.1234, 1e-6);
  ASSERT_FALSE(g.empty());
  EXPECT_EQ(g.back(), (std::pair<int, std::string>{0, "EOF"}));
}

}  // namespace

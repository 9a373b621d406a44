// The PLY reader (storage/exchange/ply_reader.h): what the one PLY writer writes
// comes back (binary and ascii, absolute and datum-relative), files of
// other programs are read (big-endian, quads, other elements, float
// colours), and damaged files are refused naming the file and the place.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "storage/exchange/mesh_export.h"
#include "storage/exchange/ply_reader.h"
#include "storage/exchange/ply_writer.h"

namespace rockface::storage {
namespace {

namespace fs = std::filesystem;

photogrammetry::SurfaceMesh sample_mesh() {
  photogrammetry::SurfaceMesh m;
  m.vertices = {{0.0012, -0.5, 1.25}, {1.5, 0.25, 0.75}, {0.125, 1.0, -0.3}, {2.0, 2.0, 0.0}};
  m.colours = {{{10, 20, 30}}, {{40, 50, 60}}, {{70, 80, 90}}, {{255, 0, 128}}};
  m.texcoords = {{0.1f, 0.9f}, {0.5f, 0.5f}, {0.25f, 0.75f}, {1.0f, 0.0f}};
  m.triangles = {{{0, 1, 2}}, {{1, 3, 2}}};
  return m;
}

void expect_same(const Mesh& read, const photogrammetry::SurfaceMesh& want, double tolerance) {
  ASSERT_EQ(read.vertices.size(), want.vertices.size());
  for (std::size_t i = 0; i < want.vertices.size(); ++i)
    EXPECT_LT((read.vertices[i] - want.vertices[i]).norm(), tolerance) << "vertex " << i;
  EXPECT_EQ(read.colours, want.colours);
  ASSERT_EQ(read.texcoords.size(), want.texcoords.size());
  for (std::size_t i = 0; i < want.texcoords.size(); ++i)
    for (int k = 0; k < 2; ++k)
      // ascii texture coordinates have 6 decimals.
      EXPECT_NEAR(read.texcoords[i][static_cast<std::size_t>(k)], want.texcoords[i][k], 1e-6)
          << "texcoord " << i;
  EXPECT_EQ(read.faces, want.triangles);
}

std::string ply_text(const photogrammetry::SurfaceMesh& m, const Eigen::Vector3d& datum,
                     const PlyOptions& options) {
  PlyMeshView view;
  view.vertices = m.size();
  view.position = [&](std::size_t i) { return m.vertices[i]; };
  view.colour = [&](std::size_t i) { return m.colours[i]; };
  view.texcoord = [&](std::size_t i) { return m.texcoords[i]; };
  view.triangles = m.triangles.size();
  view.triangle = [&](std::size_t f) { return m.triangles[f]; };
  std::ostringstream out;
  write_ply_mesh(out, view, datum, options);
  return out.str();
}

std::string refusal(const std::string& bytes) {
  try {
    parse_ply(bytes, "m.ply");
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "m.ply");
    return e.reason();
  }
  ADD_FAILURE() << "accepted:\n" << bytes;
  return "";
}

}  // namespace

TEST(PlyReader, TheWritersSurveyCoordinatesComeBackWithTheirMillimetres) {
  const Eigen::Vector3d datum(512340.0, 5211870.0, 410.0);
  const fs::path file = fs::temp_directory_path() / "rockface-ply-reader-test.ply";
  MeshExportOptions options;
  options.datum = datum;
  options.texture_file = "left.jpg";
  write_ply(file, sample_mesh(), options);
  const PlyModel read = read_ply_mesh(file);
  fs::remove(file);
  EXPECT_EQ(read.datum, datum);
  EXPECT_EQ(read.texture_file, "left.jpg");
  // Written absolute as double: 10^6 m + a relative coordinate and back is
  // exact to ~1e-10 m.
  expect_same(read.mesh, sample_mesh(), 1e-9);
}

TEST(PlyReader, AsciiAndDatumRelativeFilesRoundTrip) {
  const Eigen::Vector3d datum(1000.5, -20.25, 3.0);
  PlyOptions ascii;
  ascii.binary = false;
  const PlyModel a = parse_ply(ply_text(sample_mesh(), datum, ascii), "a.ply");
  EXPECT_EQ(a.datum, datum);
  expect_same(a.mesh, sample_mesh(), 1e-4);  // %.4f: half of 0.1 mm per axis
  PlyOptions relative;
  relative.absolute = false;
  const PlyModel r = parse_ply(ply_text(sample_mesh(), datum, relative), "r.ply");
  EXPECT_EQ(r.datum, datum);
  expect_same(r.mesh, sample_mesh(), 1e-6);  // float: ~1e-7 relative at 2 m
}

TEST(PlyReader, OtherProgramsFilesBigEndianQuadsAndExtraElements) {
  // Big-endian float coordinates, float colours 0..1, a quad and a
  // triangle (vertex_index, ushort count), an edge element to skip.
  std::string ply =
      "ply\r\nformat binary_big_endian 1.0\r\ncomment made elsewhere\r\n"
      "element vertex 4\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
      "property float red\r\nproperty float green\r\nproperty float blue\r\n"
      "property uchar quality\r\n"
      "element face 2\r\nproperty list ushort uint vertex_index\r\n"
      "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\nend_header\r\n";
  auto put_big = [&](auto v) {
    unsigned char raw[sizeof(v)];
    std::memcpy(raw, &v, sizeof(v));
    if constexpr (std::endian::native == std::endian::little) std::reverse(raw, raw + sizeof(v));
    ply.append(reinterpret_cast<const char*>(raw), sizeof(v));
  };
  const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const auto& p : xyz) {
    for (float c : p) put_big(c);
    for (float c : {1.0f, 0.5f, 0.0f}) put_big(c);
    put_big(std::uint8_t{7});
  }
  put_big(std::uint16_t{4});
  for (std::uint32_t i : {0u, 1u, 2u, 3u}) put_big(i);
  put_big(std::uint16_t{3});
  for (std::uint32_t i : {0u, 2u, 3u}) put_big(i);
  put_big(std::int32_t{0});
  put_big(std::int32_t{1});
  const PlyModel m = parse_ply(ply, "meshlab.ply");
  ASSERT_EQ(m.mesh.vertices.size(), 4u);
  EXPECT_EQ(m.mesh.vertices[2], Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(m.mesh.colours[0], (std::array<std::uint8_t, 3>{255, 128, 0}));
  EXPECT_TRUE(m.mesh.texcoords.empty());
  // The quad fanned into two triangles, then the triangle.
  const std::vector<std::array<int, 3>> triangles{{{0, 1, 2}}, {{0, 2, 3}}, {{0, 2, 3}}};
  EXPECT_EQ(m.mesh.faces, triangles);
  EXPECT_EQ(m.datum, Eigen::Vector3d::Zero());
}

TEST(PlyReader, SurveyCoordinatesWithoutADatumGetTheFirstVertexRounded) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
      "property double z\nend_header\n512340.4567 5211870.1234 410.0009\n512341.0 5211871.0 "
      "411.0\n";
  const PlyModel m = parse_ply(ply, "survey.ply");
  EXPECT_EQ(m.datum, Eigen::Vector3d(512340, 5211870, 410));
  // Parsed as double and shifted by whole metres: exact to ~1e-9 m.
  EXPECT_LT((m.mesh.vertices[0] - Eigen::Vector3d(0.4567, 0.1234, 0.0009)).norm(), 1e-9);
}

TEST(PlyReader, DamagedFilesAreRefusedNamingThePlace) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_NE(refusal("PK\x03\x04").find("not a PLY file"), std::string::npos);
  EXPECT_NE(refusal("ply\nformat ascii 1.0\nelement vertex 1\n").find("end_header"),
            std::string::npos);
  EXPECT_NE(refusal("ply\nformat ascii 2.0\nend_header\n").find("version"), std::string::npos);
  EXPECT_NE(refusal("ply\nformat ascii 1.0\nproperty float x\nend_header\n").find("before any"),
            std::string::npos);
  EXPECT_NE(refusal(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n").find("face 0: vertex_indices"),
            std::string::npos);
  EXPECT_NE(refusal(head + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n").find("vertex 1: y is not"),
            std::string::npos);
  EXPECT_NE(refusal(head + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n").find("three vertices"),
            std::string::npos);
  EXPECT_NE(refusal(head + "0 0 0\n1 0 0\n").find("the file ends here"), std::string::npos);
  EXPECT_NE(refusal(head + "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n").find("out of its type's range"),
            std::string::npos);
  // A count the file cannot hold is refused before anything is allocated.
  EXPECT_NE(refusal("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                    "property float x\nproperty float y\nproperty float z\nend_header\n\x01")
                .find("too large"),
            std::string::npos);
  EXPECT_NE(refusal("ply\nformat binary_little_endian 1.0\nelement vertex 1000000\n"
                    "property float x\nproperty float y\nproperty float z\nend_header\n\x01")
                .find("do not fit"),
            std::string::npos);
  EXPECT_THROW(read_ply_mesh("/nonexistent/model.ply"), InputError);
}

}  // namespace rockface::storage

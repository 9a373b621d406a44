// The import readers of `rockface import` (storage/exchange: las_reader.h,
// xyz_reader.h, ptx_reader.h, pcd_reader.h, obj_reader.h, import_reader.h):
// what each reads as meant, survey coordinates to 0.1 mm, and every class of
// malformation refused naming the file and the place.
#include <unistd.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "core/common/error.h"
#include "storage/exchange/import_reader.h"
#include "storage/exchange/las_reader.h"
#include "storage/exchange/obj_reader.h"
#include "storage/exchange/pcd_reader.h"
#include "storage/exchange/ptx_reader.h"
#include "storage/exchange/xyz_reader.h"

namespace {

using namespace rockface::storage;
using rockface::InputError;
namespace fs = std::filesystem;

// A UTM point with millimetres and tenths of them.
const Eigen::Vector3d kUtm(276771.2345, 5151636.7891, 2385.4321);

// The message of the InputError `f` throws ("" when it throws none).
template <typename F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// ------------------------------------------------------------------- LAS

template <typename T>
void put(std::string& b, std::size_t at, T v) {
  std::memcpy(b.data() + at, &v, sizeof(T));
}

struct LasPoint {
  Eigen::Vector3d p;
  std::array<std::uint16_t, 3> rgb{};
  std::uint16_t intensity = 0;
};

// A LAS file written from the specification (ASPRS LAS 1.4 R15), not by
// the reader's code: version 1.minor, point format `format`.
std::string las_file(const std::vector<LasPoint>& points, int minor, int format,
                     double scale = 1e-4) {
  const std::size_t header = minor == 4 ? 375 : 227;
  const std::size_t length = format == 0 ? 20 : format == 3 ? 34 : format == 7 ? 36 : 30;
  std::string b(header + points.size() * length, '\0');
  std::memcpy(b.data(), "LASF", 4);
  b[24] = 1;
  b[25] = static_cast<char>(minor);
  put<std::uint16_t>(b, 94, static_cast<std::uint16_t>(header));
  put<std::uint32_t>(b, 96, static_cast<std::uint32_t>(header));
  b[104] = static_cast<char>(format);
  put<std::uint16_t>(b, 105, static_cast<std::uint16_t>(length));
  put<std::uint32_t>(b, 107, minor == 4 ? 0u : static_cast<std::uint32_t>(points.size()));
  Eigen::Vector3d lo = points.front().p, hi = lo;
  for (const auto& q : points) lo = lo.cwiseMin(q.p), hi = hi.cwiseMax(q.p);
  const Eigen::Vector3d offset = kUtm.array().floor();
  for (int k = 0; k < 3; ++k) {
    put<double>(b, 131 + 8 * k, scale);
    put<double>(b, 155 + 8 * k, offset[k]);
    put<double>(b, 179 + 16 * k, hi[k]);
    put<double>(b, 187 + 16 * k, lo[k]);
  }
  if (minor == 4) put<std::uint64_t>(b, 247, points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t at = header + i * length;
    for (int k = 0; k < 3; ++k)
      put<std::int32_t>(
          b, at + 4 * k,
          static_cast<std::int32_t>(std::lround((points[i].p[k] - offset[k]) / scale)));
    put<std::uint16_t>(b, at + 12, points[i].intensity);  // every format: byte 12
    const std::size_t rgb_at = format == 3 ? 28 : format == 7 ? 30 : 0;
    if (rgb_at)
      for (int k = 0; k < 3; ++k) put<std::uint16_t>(b, at + rgb_at + 2 * k, points[i].rgb[k]);
  }
  return b;
}

std::vector<LasPoint> utm_points() {
  return {{kUtm, {65535, 0, 32768}},
          {kUtm + Eigen::Vector3d(1.0001, 0.5, -0.2), {256, 512, 1024}},
          {kUtm + Eigen::Vector3d(-0.3, 2.0, 0.7), {0, 65535, 0}}};
}

TEST(LasReader, Format7KeepsATenthOfAMillimetreAndColours) {
  const auto pts = utm_points();
  const ImportedSurface s = parse_las(las_file(pts, 4, 7), "scan.las");
  ASSERT_EQ(s.mesh.vertices.size(), 3u);
  EXPECT_EQ(s.format, "LAS 1.4 point format 7");
  for (std::size_t i = 0; i < pts.size(); ++i)
    // 1e-6 m: the file holds 0.1 mm steps exactly (scale 1e-4 and these
    // points on them); the double sum of a datum of 5e6 m and a metre
    // rounds at 1e-9 m.
    EXPECT_LT((s.mesh.vertices[i] + s.datum - pts[i].p).norm(), 1e-6) << i;
  EXPECT_GT(s.datum.norm(), 1e6);  // survey coordinates took a datum
  ASSERT_EQ(s.mesh.colours.size(), 3u);
  EXPECT_EQ(s.mesh.colours[0][0], 255);  // 16-bit colours to 8 bits
  EXPECT_EQ(s.mesh.colours[0][2], 128);
  EXPECT_EQ(s.mesh.colours[1][2], 4);
}

TEST(LasReader, Formats0And3OfLas12) {
  const auto pts = utm_points();
  const ImportedSurface plain = parse_las(las_file(pts, 2, 0), "plain.las");
  EXPECT_EQ(plain.mesh.vertices.size(), 3u);
  EXPECT_TRUE(plain.mesh.colours.empty());
  const ImportedSurface rgb = parse_las(las_file(pts, 2, 3), "rgb.las");
  ASSERT_EQ(rgb.mesh.colours.size(), 3u);
  EXPECT_EQ(rgb.mesh.colours[2][1], 255);
}

// Point formats 2 (LAS 1.2: RGB, no GPS time) and 8 (LAS 1.4: GPS time, RGB
// and NIR) laid out byte by byte from the specification's record tables
// (ASPRS LAS 1.4 R15, tables 9 and 15), every field filled with its own
// value so that a colour read from the wrong offset reads something else.
// `record_length` may exceed the format's own (26, 38): the specification
// lets a writer append extra bytes to every record, which the reader must
// step over.
std::string las_rgb_file(const std::vector<LasPoint>& points, int format,
                         std::size_t record_length) {
  const bool wide = format == 8;
  const std::size_t header = wide ? 375 : 227;
  std::string b(header + points.size() * record_length, '\0');
  std::memcpy(b.data(), "LASF", 4);
  b[24] = 1;
  b[25] = wide ? 4 : 2;
  put<std::uint16_t>(b, 94, static_cast<std::uint16_t>(header));  // header size
  put<std::uint32_t>(b, 96, static_cast<std::uint32_t>(header));  // offset to point data
  b[104] = static_cast<char>(format);                             // point data record format
  put<std::uint16_t>(b, 105, static_cast<std::uint16_t>(record_length));
  put<std::uint32_t>(b, 107, wide ? 0u : static_cast<std::uint32_t>(points.size()));
  const Eigen::Vector3d offset = kUtm.array().floor();
  Eigen::Vector3d lo = points.front().p, hi = lo;
  for (const auto& q : points) lo = lo.cwiseMin(q.p), hi = hi.cwiseMax(q.p);
  for (int k = 0; k < 3; ++k) {
    put<double>(b, 131 + 8 * k, 1e-4);  // 0.1 mm steps
    put<double>(b, 155 + 8 * k, offset[k]);
    put<double>(b, 179 + 16 * k, hi[k]);
    put<double>(b, 187 + 16 * k, lo[k]);
  }
  if (wide) put<std::uint64_t>(b, 247, points.size());  // 1.4's 64-bit point count
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t at = header + i * record_length;
    for (int k = 0; k < 3; ++k)
      put<std::int32_t>(
          b, at + 4 * k,
          static_cast<std::int32_t>(std::lround((points[i].p[k] - offset[k]) / 1e-4)));
    put<std::uint16_t>(b, at + 12, 0x7777);  // intensity
    if (!wide) {
      b[at + 14] = 0x11;                       // return 1 of 1
      b[at + 15] = 2;                          // classification: ground
      b[at + 16] = static_cast<char>(-12);     // scan angle rank, deg
      b[at + 17] = 0x5A;                       // user data
      put<std::uint16_t>(b, at + 18, 0xABCD);  // point source ID
      for (int k = 0; k < 3; ++k) put<std::uint16_t>(b, at + 20 + 2 * k, points[i].rgb[k]);
    } else {
      b[at + 14] = 0x11;                                              // return 1 of 1
      b[at + 15] = 0x40;                                              // scanner channel 1, no flags
      b[at + 16] = 2;                                                 // classification
      b[at + 17] = 0x5A;                                              // user data
      put<std::int16_t>(b, at + 18, -2000);                           // scan angle, 0.006 deg units
      put<std::uint16_t>(b, at + 20, 0xABCD);                         // point source ID
      put<double>(b, at + 22, 3.2e8 + 0.5 * static_cast<double>(i));  // GPS time, s
      for (int k = 0; k < 3; ++k) put<std::uint16_t>(b, at + 30 + 2 * k, points[i].rgb[k]);
      put<std::uint16_t>(b, at + 36, 0xEEEE);  // NIR
    }
    // Extra bytes past the format's own record: a pattern no field holds.
    for (std::size_t e = wide ? 38 : 26; e < record_length; ++e) b[at + e] = '\x99';
  }
  return b;
}

// The points' coordinates to 0.1 mm and their colours, as written.
void expect_points_and_colours(const ImportedSurface& s, const std::vector<LasPoint>& pts,
                               const std::string& what) {
  ASSERT_EQ(s.mesh.vertices.size(), pts.size()) << what;
  for (std::size_t i = 0; i < pts.size(); ++i)
    // 1e-6 m: the file holds 0.1 mm steps exactly (scale 1e-4 and these
    // points on them); the double sum of a datum of 5e6 m and a metre
    // rounds at 1e-9 m. A record misread by a byte is metres off.
    EXPECT_LT((s.mesh.vertices[i] + s.datum - pts[i].p).norm(), 1e-6) << what << " point " << i;
  ASSERT_EQ(s.mesh.colours.size(), pts.size()) << what;
  // 16-bit colours to 8 bits (the brightest channel is above 255): the
  // writer's values shifted by 8, nothing of intensity, source ID or NIR.
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_EQ(s.mesh.colours[i][k], pts[i].rgb[k] >> 8)
          << what << " point " << i << " channel " << k;
}

TEST(LasReader, Format2OfLas12ColoursWithoutGpsTime) {
  const auto pts = utm_points();
  const ImportedSurface s = parse_las(las_rgb_file(pts, 2, 26), "rgb2.las");
  EXPECT_EQ(s.format, "LAS 1.2 point format 2");
  expect_points_and_colours(s, pts, "format 2, 26-byte records");
  // Four extra bytes a record: the records stride 30 bytes, read the same.
  expect_points_and_colours(parse_las(las_rgb_file(pts, 2, 30), "rgb2x.las"), pts,
                            "format 2, 30-byte records");
  // A record length shorter than the format's 26 bytes is refused by name.
  const std::string why = refusal([&] { parse_las(las_rgb_file(pts, 2, 25), "short2.las"); });
  EXPECT_NE(why.find("short2.las"), std::string::npos) << why;
  EXPECT_NE(why.find("takes 26 bytes"), std::string::npos) << why;
}

TEST(LasReader, Format8GpsTimeColoursAndNir) {
  const auto pts = utm_points();
  const ImportedSurface s = parse_las(las_rgb_file(pts, 8, 38), "rgbn8.las");
  EXPECT_EQ(s.format, "LAS 1.4 point format 8");
  expect_points_and_colours(s, pts, "format 8, 38-byte records");
  expect_points_and_colours(parse_las(las_rgb_file(pts, 8, 44), "rgbn8x.las"), pts,
                            "format 8, 44-byte records");
  const std::string why = refusal([&] { parse_las(las_rgb_file(pts, 8, 37), "short8.las"); });
  EXPECT_NE(why.find("short8.las"), std::string::npos) << why;
  EXPECT_NE(why.find("takes 38 bytes"), std::string::npos) << why;
  // Format 8 needs LAS 1.4: the same records under a 1.2 header are refused.
  std::string old = las_rgb_file(pts, 8, 38);
  old[25] = 2;
  EXPECT_NE(refusal([&] { parse_las(old, "old8.las"); }).find("needs LAS 1.4"), std::string::npos);
}

// Issue 43's peak: a LAS file is read from disk in chunks of 8 MiB of
// records, never whole. Read so, a file of several chunks (300,000 points of
// 36 bytes: 10.8 MB, a chunk boundary inside it) gives exactly what the
// bytes in memory give, and a file cut short or whose header lies is refused
// in the same words, the lie found in a later chunk too.
TEST(LasReader, AFileReadInChunksIsTheFileReadWhole) {
  std::vector<LasPoint> pts;
  for (int i = 0; i < 300000; ++i)
    pts.push_back(
        {kUtm + Eigen::Vector3d(0.0001 * (i % 1000), 0.0001 * (i / 1000), 0.001 * (i % 7)),
         {static_cast<std::uint16_t>(i % 65536), 256, 0}});
  const std::string bytes = las_file(pts, 4, 7);
  const fs::path dir = fs::temp_directory_path() / ("las-chunks-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto write = [&](const std::string& name, const std::string& b) {
    std::ofstream(dir / name, std::ios::binary) << b;
    return dir / name;
  };
  const ImportedSurface whole = parse_las(bytes, "scan.las");
  const ImportedSurface chunked = read_las_file(write("scan.las", bytes));
  ASSERT_EQ(chunked.mesh.vertices.size(), pts.size());
  EXPECT_EQ(chunked.datum, whole.datum);
  EXPECT_EQ(chunked.mesh.vertices, whole.mesh.vertices);  // bit for bit
  EXPECT_EQ(chunked.mesh.colours, whole.mesh.colours);
  EXPECT_EQ(chunked.format, whole.format);

  std::string cut = bytes;
  cut.resize(cut.size() - 10);
  EXPECT_EQ(refusal([&] { read_las_file(write("cut.las", cut)); }),
            refusal([&] { parse_las(cut, (dir / "cut.las").string()); }));
  std::string lies = bytes;
  // Point 290,000 (in the second chunk) 200 km east of the header's bounds.
  put<std::int32_t>(lies, 375 + 290000 * 36, 2'000'000'000);
  const std::string why = refusal([&] { read_las_file(write("lies.las", lies)); });
  EXPECT_NE(why.find("outside the header's bounds"), std::string::npos) << why;
  EXPECT_EQ(why, refusal([&] { parse_las(lies, (dir / "lies.las").string()); }));
  fs::remove_all(dir);
}

TEST(LasReader, RefusesTruncatedFiles) {
  std::string b = las_file(utm_points(), 4, 7);
  b.resize(b.size() - 10);
  EXPECT_NE(refusal([&] { parse_las(b, "cut.las"); }).find("do not fit"), std::string::npos);
  EXPECT_NE(refusal([&] { parse_las(b.substr(0, 100), "cut.las"); }).find("cut short"),
            std::string::npos);
}

TEST(LasReader, RefusesATwoGigabyteClaimBeforeAllocating) {
  std::string b = las_file(utm_points(), 4, 7);
  put<std::uint64_t>(b, 247, 2'000'000'000ull);  // 72 GB of records in a 483-byte file
  const std::string why = refusal([&] { parse_las(b, "huge.las"); });
  EXPECT_NE(why.find("huge.las"), std::string::npos) << why;
  EXPECT_NE(why.find("2000000000 points"), std::string::npos) << why;
}

TEST(LasReader, RefusesAHeaderThatLies) {
  std::string b = las_file(utm_points(), 4, 7);
  put<double>(b, 179, kUtm.x() + 0.5);  // max X below the second point's
  EXPECT_NE(refusal([&] { parse_las(b, "lies.las"); }).find("outside the header's bounds"),
            std::string::npos);
  std::string counts = las_file(utm_points(), 4, 7);
  put<std::uint32_t>(counts, 107, 2);  // legacy count 2, 64-bit count 3
  EXPECT_NE(refusal([&] { parse_las(counts, "counts.las"); }).find("disagree"), std::string::npos);
  std::string scale = las_file(utm_points(), 4, 7);
  put<double>(scale, 139, std::nan(""));
  EXPECT_NE(refusal([&] { parse_las(scale, "nan.las"); }).find("Y scale"), std::string::npos);
}

TEST(LasReader, RefusesLazAndFormatsItDoesNotRead) {
  std::string laz = las_file(utm_points(), 4, 7);
  laz[104] = static_cast<char>(7 | 0x80);
  const std::string why = refusal([&] { parse_las(laz, "scan.las"); });
  EXPECT_NE(why.find("LAZ"), std::string::npos) << why;
  EXPECT_NE(why.find("laszip"), std::string::npos) << why;
  std::string waveform = las_file(utm_points(), 4, 7);
  waveform[104] = 4;
  EXPECT_NE(refusal([&] { parse_las(waveform, "w.las"); }).find("format 4"), std::string::npos);
  EXPECT_NE(refusal([&] { parse_las("PK\3\4", "zip.las"); }).find("not a LAS file"),
            std::string::npos);
}

// ------------------------------------------------------------------- text

TEST(XyzReader, HeaderNamesTheColumnsAndSurveyCoordinatesKeepATenthOfAMillimetre) {
  const std::string csv =
      "E;N;H;red;green;blue\n"
      "276771.2345;5151636.7891;2385.4321;10;20;30\n"
      "276772.2346;5151637.7892;2385.4322;40;50;60\n"
      "276771.2347;5151638.7893;2386.4323;70;80;90\n";
  const ImportedSurface s = parse_xyz(csv, "face.csv", {}, false);
  ASSERT_EQ(s.mesh.vertices.size(), 3u);
  // 1e-6 m: the text's 0.1 mm digits parse exactly to the nearest double
  // (1e-9 m at 5e6 m), the datum is whole metres.
  EXPECT_LT((s.mesh.vertices[0] + s.datum - kUtm).norm(), 1e-6);
  EXPECT_LT(
      (s.mesh.vertices[2] + s.datum - Eigen::Vector3d(276771.2347, 5151638.7893, 2386.4323)).norm(),
      1e-6);
  ASSERT_EQ(s.mesh.colours.size(), 3u);
  EXPECT_EQ(s.mesh.colours[1][1], 50);
}

TEST(XyzReader, ColumnsFromTheCountOrGiven) {
  const ImportedSurface six =
      parse_xyz("0 0 0 1 2 3\n1 0 0 4 5 6\n0 1 0 7 8 9\n", "a.xyz", {}, false);
  EXPECT_EQ(six.mesh.colours.size(), 3u);
  EXPECT_TRUE(six.datum.isZero());  // a local frame keeps its coordinates
  const std::string five = "0 0 0 7 1\n1 0 0 7 1\n";
  EXPECT_NE(refusal([&] { parse_xyz(five, "b.xyz", {}, false); }).find("--columns"),
            std::string::npos);
  const ImportedSurface given =
      parse_xyz(five, "b.xyz", parse_point_columns("x,y,z,-,skip", "--columns"), false);
  EXPECT_EQ(given.mesh.vertices.size(), 2u);
  EXPECT_NE(refusal([&] { parse_point_columns("x,y,q", "--columns"); }).find("'q'"),
            std::string::npos);
  // CloudCompare's ASC header is a comment: "//X,Y,Z,R,G,B".
  const ImportedSurface cc = parse_xyz("//X,Y,Z,R,G,B\n0,0,0,1,2,3\n", "cc.asc", {}, false);
  EXPECT_EQ(cc.mesh.colours.size(), 1u);
}

TEST(XyzReader, RefusesNanWrongCountsAndText) {
  EXPECT_NE(refusal([&] {
              parse_xyz("0 0 0\n1 nan 0\n", "n.xyz", {}, false);
            }).find("n.xyz: line 2: y is not a finite number"),
            std::string::npos);
  EXPECT_NE(
      refusal([&] { parse_xyz("0 0 0\n1 0\n", "c.xyz", {}, false); }).find("line 2: 2 values"),
      std::string::npos);
  EXPECT_NE(refusal([&] {
              parse_xyz("0 0 0\n1 0 zero\n", "t.xyz", {}, false);
            }).find("'zero' is not a number"),
            std::string::npos);
  EXPECT_NE(refusal([&] { parse_xyz("", "e.xyz", {}, false); }).find("no points"),
            std::string::npos);
}

TEST(XyzReader, PtsCountMustBeTheLines) {
  const std::string pts = "2\n0 0 0 5 1 2 3\n1 0 0 5 4 5 6\n";
  const ImportedSurface s = parse_xyz(pts, "s.pts", {}, true);
  EXPECT_EQ(s.mesh.vertices.size(), 2u);
  EXPECT_EQ(s.mesh.colours[1][0], 4);
  EXPECT_NE(refusal([&] {
              parse_xyz("3\n0 0 0 5 1 2 3\n", "l.pts", {}, true);
            }).find("says 3 points and holds 1"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              parse_xyz("2000000000\n0 0 0 5 1 2 3\n", "g.pts", {}, true);
            }).find("do not fit"),
            std::string::npos);
}

// ------------------------------------------------------------------- PTX

std::string ptx_scan(const std::string& points, int columns, int rows) {
  return std::to_string(columns) + "\n" + std::to_string(rows) +
         "\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
         // A quarter turn about z and the station in survey coordinates.
         "0 1 0 0\n-1 0 0 0\n0 0 1 0\n276771.2345 5151636.7891 2385.4321 1\n" +
         points;
}

TEST(PtxReader, RegistersPointsAndLeavesOutNoReturns) {
  const std::string ptx = ptx_scan("1 0 0 0.5\n0 0 0 0\n0 2 0 0.5\n0 0 3 0.5\n", 2, 2);
  const ImportedSurface s = parse_ptx(ptx, "scan.ptx");
  ASSERT_EQ(s.mesh.vertices.size(), 3u);
  EXPECT_EQ(s.skipped_points, 1u);
  // The scanner's x (1 0 0) turned a quarter about z is north: (0, 1, 0).
  // 1e-6 m: exact decimal inputs, a datum of whole metres.
  EXPECT_LT((s.mesh.vertices[0] + s.datum - (kUtm + Eigen::Vector3d(0, 1, 0))).norm(), 1e-6);
  EXPECT_LT((s.mesh.vertices[1] + s.datum - (kUtm + Eigen::Vector3d(-2, 0, 0))).norm(), 1e-6);
}

TEST(PtxReader, RefusesTruncatedClaimsAndNan) {
  EXPECT_NE(refusal([&] {
              parse_ptx(ptx_scan("1 0 0 0.5\n", 2, 2), "cut.ptx");
            }).find("the file ends before scan 1 point 1"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              parse_ptx(ptx_scan("1 0 0 0.5\n", 100000, 100000), "big.ptx");
            }).find("do not fit"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              parse_ptx(ptx_scan("1 nan 0 0.5\n", 1, 1), "nan.ptx");
            }).find("not a finite number"),
            std::string::npos);
}

// ------------------------------------------------------------------- PCD

std::string pcd_header(const std::string& data, int width, int height, int points) {
  return "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\n"
         "COUNT 1 1 1 1\nWIDTH " +
         std::to_string(width) + "\nHEIGHT " + std::to_string(height) +
         "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(points) + "\nDATA " + data + "\n";
}

TEST(PcdReader, AsciiAndBinaryWithPackedColours) {
  const std::string ascii =
      pcd_header("ascii", 2, 1, 2) + "0 0 0 " + std::to_string(0x00FF8001) + "\n1 2 3 0\n";
  const ImportedSurface a = parse_pcd(ascii, "a.pcd");
  ASSERT_EQ(a.mesh.vertices.size(), 2u);
  EXPECT_EQ(a.mesh.colours[0], (std::array<std::uint8_t, 3>{255, 128, 1}));
  const std::uint32_t rgb = 0x00010203;
  // Records x y z rgb, little-endian as PCL writes on x86.
  std::string binary = pcd_header("binary", 2, 1, 2);
  for (int i = 0; i < 2; ++i) {
    for (float v : {float(i), float(2 * i), float(3 * i)})
      binary.append(reinterpret_cast<char*>(&v), 4);
    binary.append(reinterpret_cast<const char*>(&rgb), 4);
  }
  const ImportedSurface b = parse_pcd(binary, "b.pcd");
  ASSERT_EQ(b.mesh.vertices.size(), 2u);
  EXPECT_EQ(b.mesh.vertices[1], Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(b.mesh.colours[1], (std::array<std::uint8_t, 3>{1, 2, 3}));
}

TEST(PcdReader, OrganisedNanIsNoReturnUnorganisedNanIsAnError) {
  const std::string organised = pcd_header("ascii", 1, 2, 2) + "nan nan nan 0\n1 2 3 0\n";
  const ImportedSurface s = parse_pcd(organised, "o.pcd");
  EXPECT_EQ(s.mesh.vertices.size(), 1u);
  EXPECT_EQ(s.skipped_points, 1u);
  const std::string loose = pcd_header("ascii", 2, 1, 2) + "nan nan nan 0\n1 2 3 0\n";
  EXPECT_NE(refusal([&] { parse_pcd(loose, "u.pcd"); }).find("point 0: x is not a finite number"),
            std::string::npos);
}

TEST(PcdReader, RefusesLiesClaimsAndCompression) {
  EXPECT_NE(refusal([&] {
              parse_pcd(pcd_header("ascii", 2, 1, 2) + "0 0 0 0\n", "cut.pcd");
            }).find("do not fit"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              parse_pcd(pcd_header("binary", 2000000000, 1, 2000000000), "g.pcd");
            }).find("do not fit"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              parse_pcd(pcd_header("ascii", 3, 1, 2) + "0 0 0 0\n", "w.pcd");
            }).find("is not its POINTS"),
            std::string::npos);
  const std::string why =
      refusal([&] { parse_pcd(pcd_header("binary_compressed", 1, 1, 1), "c.pcd"); });
  EXPECT_NE(why.find("pcl_convert_pcd_ascii_binary"), std::string::npos) << why;
}

// ------------------------------------------------------------------- OBJ

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("import-readers-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(ObjReader, TexturedMeshSplitsVerticesByTextureCoordinate) {
  const fs::path dir = scratch("obj");
  std::ofstream(dir / "m.mtl") << "newmtl rock\nmap_Kd tex.png\n";
  std::ofstream(dir / "tex.png") << "not read here";
  std::ofstream(dir / "m.obj") << "mtllib m.mtl\nusemtl rock\n"
                                  "v 276771.2345 5151636.7891 2385.4321\n"
                                  "v 276772.2345 5151636.7891 2385.4321\n"
                                  "v 276771.2345 5151637.7891 2385.4321\n"
                                  "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\n"
                                  "f 1/1 2/2 3/3\nf 3/4 2/2 1/1\n";
  const ImportedSurface s = read_obj(dir / "m.obj");
  EXPECT_EQ(s.mesh.faces.size(), 2u);
  EXPECT_EQ(s.mesh.vertices.size(), 4u);  // vertex 3 with two texture coordinates
  ASSERT_EQ(s.mesh.texcoords.size(), 4u);
  EXPECT_FLOAT_EQ(s.mesh.texcoords[2][1], 0.f);  // OBJ's v = 1 is the image's top row
  EXPECT_EQ(fs::path(s.texture_file).filename(), "tex.png");
  // 1e-6 m: the double-precision build of tinyobjloader.
  EXPECT_LT((s.mesh.vertices[0] + s.datum - kUtm).norm(), 1e-6);
  fs::remove_all(dir);
}

TEST(ObjReader, RefusesBadIndicesNanAndAMissingTexture) {
  EXPECT_NE(refusal([] {
              parse_obj("v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n", "n.obj", {});
            }).find("n.obj: line 3"),
            std::string::npos);
  const std::string bad_index =
      refusal([] { parse_obj("v 0 0 0\nv 1 0 0\nf 1 2 9\n", "i.obj", {}); });
  EXPECT_FALSE(bad_index.empty());
  EXPECT_NE(bad_index.find("i.obj"), std::string::npos) << bad_index;
  const fs::path dir = scratch("obj-missing");
  std::ofstream(dir / "m.mtl") << "newmtl rock\nmap_Kd gone.jpg\n";
  std::ofstream(dir / "m.obj") << "mtllib m.mtl\nusemtl rock\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_NE(refusal([&] { read_obj(dir / "m.obj"); }).find("gone.jpg"), std::string::npos);
  fs::remove_all(dir);
}

// ------------------------------------------------------------------- by name

TEST(ImportReader, RefusesLazE57AndUnknownNamesNamingTheTools) {
  const fs::path dir = scratch("names");
  for (const char* name : {"a.laz", "a.e57", "a.dwg"}) std::ofstream(dir / name) << "x";
  const std::string laz = refusal([&] { read_imported_surface(dir / "a.laz"); });
  EXPECT_NE(laz.find("laszip"), std::string::npos) << laz;
  EXPECT_NE(laz.find("pdal"), std::string::npos) << laz;
  const std::string e57 = refusal([&] { read_imported_surface(dir / "a.e57"); });
  EXPECT_NE(e57.find("E57"), std::string::npos) << e57;
  EXPECT_NE(e57.find("CloudCompare"), std::string::npos) << e57;
  EXPECT_NE(refusal([&] { read_imported_surface(dir / "a.dwg"); }).find(".las"), std::string::npos);
  EXPECT_NE(refusal([&] { read_imported_surface(dir / "none.ply"); }).find("no such file"),
            std::string::npos);
  fs::remove_all(dir);
}

TEST(ImportReader, OffsetIsAddedToTheDatum) {
  const fs::path dir = scratch("offset");
  std::ofstream(dir / "c.xyz") << "0.1234 0.5 0\n1 0 0\n0 1 0\n";
  ImportFileOptions o;
  o.offset = Eigen::Vector3d(276771, 5151636, 2385);
  const ImportedSurface s = read_imported_surface(dir / "c.xyz", o);
  // 1e-9 m: a whole-metre offset and a four-decimal coordinate add exactly
  // to the double's resolution at 5e6 m.
  EXPECT_LT((s.mesh.vertices[0] + s.datum - Eigen::Vector3d(276771.1234, 5151636.5, 2385)).norm(),
            1e-9);
  fs::remove_all(dir);
}

// A scanner's cloud without colours (issue 43): its intensity becomes its
// colours, a grey scaled from the file's own range (least black, greatest
// white), from a text cloud's intensity column (by the count or named), a PTX
// without RGB and LAS point formats 0, 1 and 6; a file with colours keeps
// them and says nothing of its intensity. Expected greys are worked by hand.
TEST(ImportReader, AScannersIntensityIsTheGreyOfACloudWithoutColours) {
  const fs::path dir = scratch("intensity");
  auto greys = [](const ImportedSurface& s) {
    std::vector<int> g;
    for (const auto& c : s.mesh.colours) {
      EXPECT_TRUE(c[0] == c[1] && c[1] == c[2]);  // grey
      g.push_back(c[0]);
    }
    return g;
  };
  // 12-bit counts: (1100 - 100) / (4195 - 100) of 255 is 62.3.
  std::ofstream(dir / "count.xyz") << "0 0 0 100\n1 0 0 1100\n0 1 0 4195\n";
  std::ofstream(dir / "named.csv") << "x,y,z,intensity\n0,0,0,-5\n1,0,0,5\n0,1,0,0\n";
  const ImportedSurface count = read_imported_surface(dir / "count.xyz");
  EXPECT_EQ(greys(count), (std::vector<int>{0, 62, 255}));
  ASSERT_TRUE(count.intensity_as_grey);
  EXPECT_EQ((*count.intensity_as_grey)[0], 100);
  EXPECT_EQ((*count.intensity_as_grey)[1], 4195);
  EXPECT_TRUE(count.intensities.empty());  // freed once drawn
  // A signed intensity (dB): -5 black, 5 white, 0 half way (127.5 rounds up).
  EXPECT_EQ(greys(read_imported_surface(dir / "named.csv")), (std::vector<int>{0, 255, 128}));
  // PTS with colours: they are the colours, the intensity is not.
  std::ofstream(dir / "rgb.pts") << "2\n0 0 0 5 1 2 3\n1 0 0 9 4 5 6\n";
  const ImportedSurface rgb = read_imported_surface(dir / "rgb.pts");
  EXPECT_FALSE(rgb.intensity_as_grey);
  EXPECT_EQ(rgb.mesh.colours[1][0], 4);
  // One intensity everywhere says nothing: mid grey.
  std::ofstream(dir / "flat.xyz") << "0 0 0 7\n1 0 0 7\n0 1 0 7\n";
  EXPECT_EQ(greys(read_imported_surface(dir / "flat.xyz")), (std::vector<int>{128, 128, 128}));
  // PTX without colours, Leica's 0..1; the no-return point has no grey.
  // (0.35 - 0.2) / 0.6 of 255 is 63.75.
  std::ofstream(dir / "scan.ptx") << ptx_scan("1 0 0 0.2\n0 0 0 0\n0 2 0 0.8\n0 0 3 0.35\n", 2, 2);
  EXPECT_EQ(greys(read_imported_surface(dir / "scan.ptx")), (std::vector<int>{0, 255, 64}));
  // LAS without RGB: formats 0 and 1 (LAS 1.2) and 6 (LAS 1.4), 16-bit.
  auto pts = utm_points();
  pts[0].intensity = 60000, pts[1].intensity = 0, pts[2].intensity = 30000;
  for (const auto& [minor, format] : {std::pair{2, 0}, std::pair{2, 1}, std::pair{4, 6}}) {
    SCOPED_TRACE(format);
    const fs::path las = dir / ("f" + std::to_string(format) + ".las");
    const std::string bytes = las_file(pts, minor, format);
    std::ofstream(las, std::ios::binary)
        .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    EXPECT_EQ(greys(read_imported_surface(las)), (std::vector<int>{255, 0, 128}));
  }
  // With RGB (format 7) the colours are the file's.
  const std::string bytes = las_file(pts, 4, 7);
  std::ofstream(dir / "f7.las", std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  const ImportedSurface f7 = read_imported_surface(dir / "f7.las");
  EXPECT_FALSE(f7.intensity_as_grey);
  EXPECT_EQ(f7.mesh.colours[0][0], 255);
  EXPECT_EQ(f7.mesh.colours[0][1], 0);
  // A text intensity that is no number is refused by line and column.
  std::ofstream(dir / "nan.xyz") << "0 0 0 1\n1 0 0 nan\n";
  EXPECT_NE(refusal([&] { read_imported_surface(dir / "nan.xyz"); }).find("line 2"),
            std::string::npos);
  fs::remove_all(dir);
}

}  // namespace

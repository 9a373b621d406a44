// The tunnel's files: the surveyor's alignment table (CSV, elements or a
// dense polyline) and the design profile (JSON and CSV). Good files read and
// round-trip; every bad one is refused naming the file, the line (CSV) or
// field path (JSON), and the field.
#include "storage/tunnel/tunnel_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>

#include "core/common/error.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

// A straight 100 m north, then a right-hand arc of radius 200 m sweeping
// 0.5 rad (100 m), at survey coordinates of 10^6 m.
const char* kElements =
    "# Gotthard access tunnel, alignment of 2026-03\n"
    "chainage,easting,northing,elevation,radius\n"
    "1000,2690000,1170000,1100,0\n"
    "1100,2690000,1170100,1101,200\n"
    "1200,2690024.483487,1170195.885108,1102,\n";

TEST(TunnelFiles, AlignmentTableOfElements) {
  const AlignmentTable t = parse_alignment_csv(kElements, "align.csv");
  ASSERT_EQ(t.stations.size(), 3u);
  EXPECT_FALSE(t.polyline);
  ASSERT_EQ(t.radii.size(), 2u);
  EXPECT_EQ(t.radii[1], 200);
  EXPECT_EQ(t.line_of[0], 3);  // after the comment and the header
  const tunnel::Alignment al = t.build({2690000, 1170000, 1100}, tunnel::Drive::ascending);
  // The arc's end: 200 (1 - cos 0.5), 200 sin 0.5 from its start, given to
  // the micrometre in the file.
  EXPECT_NEAR(
      (al.survey_point_at(1200) - Eigen::Vector3d(2690024.483487, 1170195.885108, 1102)).norm(), 0,
      1e-5);
  // Round trip through the writer.
  const AlignmentTable again = parse_alignment_csv(alignment_csv_text(t), "again.csv");
  EXPECT_EQ(again.radii, t.radii);
  EXPECT_EQ(again.stations.back().survey, t.stations.back().survey);
}

TEST(TunnelFiles, AlignmentPolylineSemicolonsAndExtraColumns) {
  const AlignmentTable t = parse_alignment_csv(
      "Point;Chainage;Easting;Northing;Elevation\r\n"
      "P1;0;100;200;10\r\n"
      "P2;10;100;210;10.1\r\n"
      "P3;20;100.5;219.99;10.2\r\n",
      "poly.csv");
  EXPECT_TRUE(t.polyline);
  EXPECT_TRUE(t.radii.empty());
  ASSERT_EQ(t.stations.size(), 3u);
  EXPECT_EQ(t.stations[2].survey.x(), 100.5);
}

TEST(TunnelFiles, BadAlignmentFilesNameFileLineAndField) {
  auto bad = [](const std::string& text) {
    return refusal([&] { parse_alignment_csv(text, "a.csv"); });
  };
  std::string m = bad("chainage,easting,northing\n0,1,2\n");
  EXPECT_NE(m.find("a.csv:1"), std::string::npos) << m;
  EXPECT_NE(m.find("'elevation'"), std::string::npos) << m;

  m = bad("chainage,easting,northing,elevation\n0,1,2,3\n10,1,x2,3\n");
  EXPECT_NE(m.find("a.csv:3, field 'northing'"), std::string::npos) << m;
  EXPECT_NE(m.find("'x2' is not a number"), std::string::npos) << m;

  m = bad("chainage,easting,northing,elevation\n0,1,2,3\n10,1,12\n");
  EXPECT_NE(m.find("a.csv:3"), std::string::npos) << m;
  EXPECT_NE(m.find("expected 4 fields"), std::string::npos) << m;

  m = bad("chainage,easting,northing,elevation\n0,1,2,3\n10,1,12,\n");
  EXPECT_NE(m.find("a.csv:3, field 'elevation': is empty"), std::string::npos) << m;

  // Out of order: the line of the offending station.
  m = bad("chainage,easting,northing,elevation\n0,0,0,0\n20,0,20,0\n10,0,10,0\n");
  EXPECT_NE(m.find("a.csv:4"), std::string::npos) << m;
  EXPECT_NE(m.find("ascending chainage"), std::string::npos) << m;

  // Duplicate chainage.
  m = bad("chainage,easting,northing,elevation\n0,0,0,0\n10,0,10,0\n10,0,20,0\n");
  EXPECT_NE(m.find("a.csv:4"), std::string::npos) << m;
  EXPECT_NE(m.find("duplicate chainage"), std::string::npos) << m;

  // Zero-length element; a radius below half the chord; a radius on the last row.
  m = bad("chainage,easting,northing,elevation,radius\n0,0,0,0,0\n10,0,0,0,\n");
  EXPECT_NE(m.find("a.csv:2"), std::string::npos) << m;
  EXPECT_NE(m.find("zero-length element"), std::string::npos) << m;
  m = bad("chainage,easting,northing,elevation,radius\n0,0,0,0,40\n100,0,100,0,\n");
  EXPECT_NE(m.find("smaller than half the chord"), std::string::npos) << m;
  m = bad("chainage,easting,northing,elevation,radius\n0,0,0,0,0\n100,0,100,0,300\n");
  EXPECT_NE(m.find("a.csv:3, field 'radius'"), std::string::npos) << m;

  // The chainage does not match the length of a line.
  m = bad("chainage,easting,northing,elevation,radius\n0,0,0,0,0\n100,0,90,0,\n");
  EXPECT_NE(m.find("a.csv:2"), std::string::npos) << m;
  EXPECT_NE(m.find("90 m long"), std::string::npos) << m;

  EXPECT_NE(bad("").find("no header"), std::string::npos);
  EXPECT_NE(bad("chainage,easting,northing,elevation\n0,0,0,0\n").find("at least two"),
            std::string::npos);
  m = bad("chainage,easting,northing,elevation,Chainage\n");
  EXPECT_NE(m.find("given twice"), std::string::npos) << m;
  m = refusal([] { read_alignment_csv("/nonexistent/align.csv"); });
  EXPECT_NE(m.find("/nonexistent/align.csv: cannot be read"), std::string::npos) << m;
}

// A horseshoe: crown radius 5 about (0, 1.5), walls of radius 10, flat invert at -2.5.
std::string horseshoe_json() {
  const tunnel::DesignProfile p = tunnel::horseshoe_profile(5, 1.5, 10, -2.5);
  return profile_json_text(p);
}

TEST(TunnelFiles, ProfileJsonBothArcFormsAndRoundTrip) {
  const tunnel::DesignProfile h = parse_profile_json(horseshoe_json(), "h.json");
  const tunnel::DesignProfile ref = tunnel::horseshoe_profile(5, 1.5, 10, -2.5);
  ASSERT_EQ(h.segments().size(), ref.segments().size());
  // JSON keeps doubles to 17 digits: the same numbers back.
  EXPECT_EQ(h.perimeter(), ref.perimeter());
  EXPECT_EQ(h.ray_centre(), ref.ray_centre());
  // A circle from the polar form: centre, radius, start and end angles.
  const tunnel::DesignProfile c = parse_profile_json(
      R"({"format": "rockface-tunnel-profile/1", "name": "TBM",
          "segments": [{"arc": {"centre": [0, 0], "radius": 4.5, "start_deg": -90, "end_deg": 90}},
                       {"arc": {"centre": [0, 0], "radius": 4.5, "start_deg": 90, "end_deg": 270}}]})",
      "c.json");
  EXPECT_EQ(c.name(), "TBM");
  // The arcs' ends come from cos / sin of the angles: ulps of 4.5 m.
  EXPECT_NEAR(c.perimeter(), 2 * std::numbers::pi * 4.5, 1e-12);
  EXPECT_NEAR(c.radius_toward(1.0), 4.5, 1e-12);
}

TEST(TunnelFiles, BadProfileJsonNamesTheField) {
  auto bad = [](const std::string& text) {
    return refusal([&] { parse_profile_json(text, "p.json"); });
  };
  std::string m = bad("{");
  EXPECT_NE(m.find("p.json: is not valid JSON"), std::string::npos) << m;
  m = bad(R"({"segments": []})");
  EXPECT_NE(m.find("p.json: segments"), std::string::npos) << m;
  m = bad(R"({"format": "other/2", "segments": []})");
  EXPECT_NE(m.find("p.json: format"), std::string::npos) << m;
  m = bad(R"({"segments": [{"line": {"from": [0, 0], "to": [1]}}]})");
  EXPECT_NE(m.find("p.json: segments[0].line.to"), std::string::npos) << m;
  m = bad(R"({"segments": [{"line": {"from": [0, 0], "to": [1, "a"]}}]})");
  EXPECT_NE(m.find("segments[0].line.to[1]"), std::string::npos) << m;
  m = bad(R"({"segments": [{"spline": {}}]})");
  EXPECT_NE(m.find("segments[0]"), std::string::npos) << m;
  m = bad(
      R"({"segments": [{"arc": {"centre": [0, 0], "radius": -1, "start_deg": 0, "end_deg": 90}}]})");
  EXPECT_NE(m.find("segments[0].arc.radius"), std::string::npos) << m;
  m = bad(
      R"({"segments": [{"arc": {"from": [1, 0], "to": [-1, 0], "centre": [0, 0], "sense": "left"}}]})");
  EXPECT_NE(m.find("segments[0].arc.sense"), std::string::npos) << m;
  // Well-formed but not a closed outline: validation names the segment.
  m = bad(R"({"segments": [{"line": {"from": [0, 0], "to": [2, 0]}},
                           {"line": {"from": [2, 0], "to": [2, 2]}},
                           {"line": {"from": [2, 2.5], "to": [0, 0]}}]})");
  EXPECT_NE(m.find("p.json: segments[1]"), std::string::npos) << m;
  EXPECT_NE(m.find("not closed"), std::string::npos) << m;
}

TEST(TunnelFiles, ProfileCsvRowsAndRoundTrip) {
  const tunnel::DesignProfile ref = tunnel::horseshoe_profile(5, 1.5, 10, -2.5);
  const std::string text = profile_csv_text(ref);
  const tunnel::DesignProfile p = parse_profile_csv(text, "h.csv");
  EXPECT_EQ(p.perimeter(), ref.perimeter());
  EXPECT_EQ(p.ray_centre(), ref.ray_centre());
  EXPECT_TRUE(p.ray_centre_given());
  // A rectangle written by hand, clockwise, without a sense column.
  const tunnel::DesignProfile r = parse_profile_csv(
      "kind,from_u,from_v,to_u,to_v,centre_u,centre_v\n"
      "line,-3,0,-3,4,,\n"
      "line,-3,4,3,4,,\n"
      "line,3,4,3,0,,\n"
      "line,3,0,-3,0,,\n",
      "r.csv");
  EXPECT_NEAR(r.area(), 24, 1e-12);
  // Files are read through the extension.
  test::TempDir dir("tunnel-files");
  const auto file = dir / "profile.csv";
  std::ofstream(file) << text;
  EXPECT_EQ(read_profile_file(file).perimeter(), ref.perimeter());
  std::ofstream(dir / "profile.json") << horseshoe_json();
  EXPECT_EQ(read_profile_file(dir / "profile.json").perimeter(), ref.perimeter());
  EXPECT_NE(refusal([&] { read_profile_file(dir / "profile.txt"); }).find(".json or a .csv"),
            std::string::npos);
}

TEST(TunnelFiles, BadProfileCsvNamesLineAndField) {
  auto bad = [](const std::string& text) {
    return refusal([&] { parse_profile_csv(text, "p.csv"); });
  };
  const std::string head = "kind,from_u,from_v,to_u,to_v,centre_u,centre_v,sense\n";
  std::string m = bad("kind,from_u,from_v,to_u,to_v\n");
  EXPECT_NE(m.find("p.csv:1"), std::string::npos) << m;
  EXPECT_NE(m.find("'centre_u'"), std::string::npos) << m;
  m = bad(head + "line,0,0,1,0,,,\nspline,1,0,0,0,,,\n");
  EXPECT_NE(m.find("p.csv:3, field 'kind'"), std::string::npos) << m;
  m = bad(head + "arc,1,0,-1,0,0,,ccw\n");
  EXPECT_NE(m.find("p.csv:2, field 'centre_v': is empty"), std::string::npos) << m;
  m = bad(head + "arc,1,0,-1,0,0,0,up\n");
  EXPECT_NE(m.find("p.csv:2, field 'sense'"), std::string::npos) << m;
  m = bad(head + "line,0,0,1,0,5,5,\n");
  EXPECT_NE(m.find("p.csv:2, field 'centre_u'"), std::string::npos) << m;
  m = bad(head + "line,0,0,1,0,,\n");
  EXPECT_NE(m.find("expected 8 fields"), std::string::npos) << m;
  // Not closed: the line of the segment.
  m = bad(head + "line,0,0,2,0,,,\nline,2,0,2,2,,,\nline,2,2.5,0,0,,,\n");
  EXPECT_NE(m.find("p.csv:3 (segments[1])"), std::string::npos) << m;
  m = bad(head + "ray_centre,,,,,1,1,\nray_centre,,,,,1,1,\n");
  EXPECT_NE(m.find("p.csv:3, field 'kind'"), std::string::npos) << m;
  EXPECT_NE(bad(head).find("no segments"), std::string::npos);
}

}  // namespace
}  // namespace rockface::storage

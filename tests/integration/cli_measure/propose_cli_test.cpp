// `rockface propose` as a user runs it: the real binary on the demo face
// replayed into a project at the fast preset. The demo face is two nearly
// coplanar walls (FACE_W, FACE_E, 12 deg apart) with joints drawn on them
// but no joint faces exposed: facets are found, but no joint set; the
// joints' dark lines are proposed as traces.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/cli_run.h"
#include "tests/support/demo_projects.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rockface::test::CliRun;
using rockface::test::run_rockface;

TEST(ProposeCli, FacetsOfTheDemoFaceNoSetPictureReportAndBadVisitByName) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-propose-cli-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path project = dir / "site.rockface";
  // The demo face without its picks at the fast preset (the fixture's
  // "bare" replay under CTest).
  ASSERT_NO_THROW(rockface::test::copy_of_shared_demo_project("bare", project));
  CliRun r;

  const fs::path out = dir / "proposals.json", report = dir / "report.pdf";
  r = run_rockface("propose " + project.string() + " --visit 1 --out " + out.string() +
                   " --png --preset fast --report " + report.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "proposals.png"));
  EXPECT_GT(fs::file_size(report), 1000u);
  std::ifstream in(out);
  const json p = json::parse(in);
  EXPECT_EQ(p.at("format"), "rockface-proposals/1");
  EXPECT_EQ(p.at("visit"), 1);
  EXPECT_EQ(p.at("preset"), "fast");
  EXPECT_GT(p.at("knobs").at("point_sigma_m").get<double>(), 0);
  ASSERT_FALSE(p.at("facets").empty());
  for (const auto& f : p.at("facets")) {
    // On the walls: steep (the walls dip 88 deg), and with an outline of
    // absolute points near the face (northing 5211880 +- 1 m).
    EXPECT_GT(f.at("dip").get<double>(), 75.0) << f.at("id");
    ASSERT_GE(f.at("outline").size(), 3u);
    EXPECT_NEAR(f.at("outline")[0][1].get<double>(), 5211880.0, 1.0);
    EXPECT_GT(f.at("area_m2").get<double>(), 0.0);
    EXPECT_TRUE(f.at("set").is_null());
  }
  // No joint face is exposed: the walls are one surface, not a set.
  EXPECT_TRUE(p.at("sets").empty());
  EXPECT_FALSE(p.at("not_sets").empty());
  // The joints drawn on the walls are proposed as traces, each measured on
  // the 3D image (points absolute, on the face) with its confidence.
  const json& t = p.at("trace_proposals");
  ASSERT_TRUE(t.is_object()) << t.dump();
  ASSERT_FALSE(t.at("proposals").empty()) << t.dump();
  for (const auto& q : t.at("proposals")) {
    EXPECT_GE(q.at("confidence").get<double>(), 0.0) << q.at("id");
    EXPECT_LE(q.at("confidence").get<double>(), 1.0) << q.at("id");
    EXPECT_GT(q.at("length_m").get<double>(), 0.0) << q.at("id");
    ASSERT_GE(q.at("points").size(), 2u) << q.at("id");
    EXPECT_NEAR(q.at("points")[0][1].get<double>(), 5211880.0, 1.0) << q.at("id");
  }

  r = run_rockface("propose " + project.string() + " --visit 7 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--visit"), std::string::npos) << r.err;
  r = run_rockface("propose " + project.string() + " --out " + out.string() + " --preset quick");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--preset"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

}  // namespace

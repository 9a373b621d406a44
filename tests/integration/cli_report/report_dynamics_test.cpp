// `rockface report` of a visit whose stored analysis set a block moving
// (analysis.dynamics): the PDF has the section "Motion after failure" with
// the block's events and landing from the store, and the picture of its
// positions (coloured outlines on the page).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::run_rockface;

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ReportDynamics, FieldReportShowsTheMotionAfterFailure) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-dyn-report-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // The analysis of the failing road-cut wedge, stored as a visit's analysis.
  const auto analysed = run_rockface("analyse " + std::string(ROCKFACE_SOURCE_DIR) +
                                     "/tools/samples/slope-wedge-dynamics.scene.json --out " +
                                     (dir / "wedge.json").string());
  ASSERT_EQ(analysed.exit_code, 0) << analysed.err;
  const nlohmann::json report = nlohmann::json::parse(read_all(dir / "wedge.json"));
  const nlohmann::json& block = report.at("blocks").at(0);
  ASSERT_TRUE(block.contains("dynamics"));
  const fs::path project = dir / "road-cut.rockface";
  {
    rockface::storage::ProjectInfo info;
    info.name = "road cut km 4.2";
    info.datum = Eigen::Vector3d(512340.0, 5211870.0, 410.0);
    auto store = rockface::storage::ProjectStore::create(project, info);
    rockface::storage::AnalysisRun run;
    run.visit_id = store.begin_visit("test");
    run.preset = "standard";
    run.effects = report.at("effects_simulated").get<std::vector<std::string>>();
    rockface::storage::BlockResult b;
    b.label = "B1";
    b.source = "scene";
    b.code = block.at("code");
    b.volume_m3 = block.at("volume");
    b.finite = b.removable = true;
    b.mode = "sliding";
    b.fos = block.at("fos").get<double>();
    b.report_json = block.dump();
    run.blocks.push_back(b);
    store.save_analysis(run);
  }
  const fs::path pdf = dir / "report.pdf";
  const auto r = run_rockface("report " + project.string() + " --visit 1 --out " + pdf.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(
      std::system(("pdftotext -layout " + pdf.string() + " " + (dir / "r.txt").string()).c_str()),
      0);
  const std::string text = read_all(dir / "r.txt");
  EXPECT_NE(text.find("Motion after failure"), std::string::npos) << text;
  EXPECT_NE(text.find("slides on J1 and J2 at 0.00 s"), std::string::npos) << text;
  const auto& landing = block.at("dynamics").at("landing");
  char speed[32];
  std::snprintf(speed, sizeof speed, "%.1f m/s", landing.at("speed").get<double>());
  EXPECT_NE(text.find(std::string("lands at ")), std::string::npos) << text;
  EXPECT_NE(text.find(speed), std::string::npos) << speed << "\n" << text;
  // The picture: the last page carries the coloured outlines.
  ASSERT_EQ(
      std::system(("pdftoppm -r 50 -png " + pdf.string() + " " + (dir / "page").string()).c_str()),
      0);
  int coloured = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().filename().string().rfind("page", 0) != 0) continue;  // the PDF's pages
    const cv::Mat img = cv::imread(entry.path().string());
    for (int y = 0; y < img.rows; ++y)
      for (int x = 0; x < img.cols; ++x) {
        const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
        if (std::abs(p[0] - p[2]) > 60) ++coloured;
      }
  }
  EXPECT_GT(coloured, 300);
  if (!std::getenv("KEEP")) fs::remove_all(dir);
}

}  // namespace

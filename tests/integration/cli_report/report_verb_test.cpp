// `rockface report` on the demo project (`rockface replay` of the demo
// tunnel face): the PDF's text, read back with pdftotext, holds the stored
// analysis' numbers, and its pages, rendered with pdftoppm, show the face
// with its traces and blocks and the stereonet.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "storage/field_report/field_report.h"
#include "storage/field_report/field_report_pictures.h"
#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::run_rockface;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Independent of the report's own formatting: printf's fixed decimals.
std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// Whitespace-separated words of a line.
std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

class ReportVerb : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ =
        new fs::path(fs::temp_directory_path() / ("rockface-report-" + std::to_string(::getpid())));
    fs::remove_all(*dir_);
    fs::create_directories(*dir_);
    const auto replay =
        run_rockface("replay " + std::string(ROCKFACE_SOURCE_DIR) +
                     "/tools/samples/tunnel-face-demo.scene.json --project " + project().string() +
                     // Issue 46: the geologist who maps the visit.
                     " --geologist 'Anna Berger'");
    ASSERT_EQ(replay.exit_code, 0) << replay.err;
    const auto report =
        run_rockface("report " + project().string() + " --visit 1 --out " + pdf().string());
    ASSERT_EQ(report.exit_code, 0) << report.err;
    ASSERT_EQ(
        std::system(("pdftotext -layout " + pdf().string() + " " + (*dir_ / "report.txt").string())
                        .c_str()),
        0);
    ASSERT_EQ(
        std::system(
            ("pdftoppm -r 60 -png " + pdf().string() + " " + (*dir_ / "page").string()).c_str()),
        0);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static fs::path project() { return *dir_ / "demo.rockface"; }
  static rockface::storage::ProjectStore open_read_only() {
    rockface::storage::OpenOptions options;
    options.read_only = true;
    return rockface::storage::ProjectStore::open(project(), options);
  }
  static fs::path pdf() { return *dir_ / "report.pdf"; }
  static std::string text() { return slurp(*dir_ / "report.txt"); }
  static fs::path* dir_;
};
fs::path* ReportVerb::dir_ = nullptr;

}  // namespace

TEST_F(ReportVerb, BlockTableHoldsTheStoredAnalysis) {
  auto store = open_read_only();
  const auto runs = store.list_analyses(1);
  ASSERT_EQ(runs.size(), 1u);
  const auto run = store.load_analysis(runs[0].id);
  ASSERT_FALSE(run.blocks.empty());
  const std::string pdf_text = text();
  std::istringstream lines(pdf_text);
  std::map<std::string, std::vector<std::string>> rows;  // block label -> its table line's words
  for (std::string line; std::getline(lines, line);) {
    const auto w = words(line);
    if (w.size() > 2 && (w[1] == "traces" || w[1] == "scene")) rows[w[0]] = w;
  }
  bool some_fos = false;
  for (const auto& b : run.blocks) {
    ASSERT_TRUE(rows.count(b.id)) << b.id << " missing from\n" << pdf_text;
    const std::string row = [&] {
      std::string s;
      for (const auto& w : rows[b.id]) s += w + " ";
      return s;
    }();
    // Margin (2 decimals, degrees), volume (3, m3), FoS (2), verdict, mode.
    EXPECT_NE(row.find(" " + fixed(b.margin_deg, 2) + " "), std::string::npos) << row;
    if (b.volume) {
      EXPECT_NE(row.find(" " + fixed(*b.volume, 3) + " "), std::string::npos) << row;
    }
    if (b.fos) {
      some_fos = true;
      EXPECT_NE(row.find(" " + fixed(*b.fos, 2) + " "), std::string::npos) << row;
    }
    const std::string verdict =
        !b.finite ? "infinite" : (b.removable ? "removable" : "finite, keyed");
    EXPECT_NE(row.find(" " + verdict), std::string::npos) << row;
    EXPECT_NE(row.find(" " + (b.mode ? b.mode->type : std::string("none"))), std::string::npos)
        << row;
    if (b.rotation) {
      int corners = 0, rotatable = 0;
      for (const auto& c : b.rotation->corners) {
        ++corners;
        rotatable += c.rotatable;
      }
      EXPECT_NE(row.find(std::to_string(rotatable) + "/" + std::to_string(corners) + " corners"),
                std::string::npos)
          << row;
    }
  }
  // The demo's keyblock slides: at least one factor of safety was compared.
  EXPECT_TRUE(some_fos);
  // The effects in words (issue 39): the analysis's first, then what the
  // demo's synthetic camera simulated, none of them as its stored key.
  EXPECT_NE(pdf_text.find("effects simulated: gravity; simulated camera: "), std::string::npos)
      << pdf_text;
  for (const auto& [key, words] :
       std::map<std::string, std::string>{{"imaging.distortion", "lens distortion"},
                                          {"imaging.noise_sigma", "sensor noise"},
                                          {"imaging.blur_px", "blur"}}) {
    ASSERT_NE(std::find(run.effects.begin(), run.effects.end(), key), run.effects.end()) << key;
    EXPECT_NE(pdf_text.find(words), std::string::npos) << words;
    EXPECT_EQ(pdf_text.find(key), std::string::npos) << key;
  }
}

TEST_F(ReportVerb, JointsAccuracyCameraAndPresetAreTheStoredOnes) {
  auto store = open_read_only();
  const std::string pdf_text = text();
  for (const auto& j : store.list_joints(1)) {
    bool found = false;
    std::istringstream lines(pdf_text);
    for (std::string line; std::getline(lines, line);) {
      const auto w = words(line);
      if (w.size() >= 3 && w[0] == j.label && w[1] == fixed(j.dip_deg, 1) &&
          w[2] == fixed(j.dipdir_deg, 1))
        found = true;
    }
    EXPECT_TRUE(found) << j.label;
  }
  const auto captures = store.list_captures(1);
  ASSERT_FALSE(captures.empty());
  const auto model = store.load_model(store.list_models(captures[0].id).at(0).id);
  const auto accuracy = nlohmann::json::parse(model.registration.parameters_json);
  const auto& reg = accuracy["registration"];
  EXPECT_NE(pdf_text.find("scale: " + reg["scale_source"].get<std::string>()), std::string::npos);
  EXPECT_NE(pdf_text.find("model scale " + fixed(reg["scale"].get<double>(), 4)),
            std::string::npos);
  EXPECT_NE(pdf_text.find("north: " + reg["north_source"].get<std::string>()), std::string::npos);
  EXPECT_NE(pdf_text.find("turned " +
                          fixed(reg["north"]["rotation_about_vertical_deg"].get<double>(), 2)),
            std::string::npos);
  EXPECT_NE(
      pdf_text.find("precision " + fixed(accuracy["sigma_z"].get<double>() * 1000, 1) + " mm"),
      std::string::npos);
  EXPECT_NE(pdf_text.find("ground control: none"), std::string::npos);
  const auto calibration = store.load_calibration(*captures[0].calibration_id);
  EXPECT_NE(pdf_text.find("fx " + fixed(calibration.intrinsics.fx, 1)), std::string::npos);
  EXPECT_NE(pdf_text.find("preset: " + model.preset), std::string::npos);
}

TEST_F(ReportVerb, PicturesRenderWithTracesAndBlocks) {
  // The face picture as embedded: the photograph with the traces drawn
  // exactly where the stored traces project.
  auto store = open_read_only();
  const auto report = rockface::storage::collect_field_report(store, 1);
  const cv::Mat face = rockface::storage::face_picture(report);
  ASSERT_FALSE(face.empty());
  int on_trace = 0, checked = 0;
  for (const auto& [label, points] : report.traces) {
    const auto at = rockface::storage::photograph_pixel(report, 0.5 * (points[0] + points[1]));
    if (!at) continue;
    const Eigen::Vector2d mid = *at;
    if (mid.x() < 0 || mid.y() < 0 || mid.x() >= face.cols || mid.y() >= face.rows) continue;
    ++checked;
    const cv::Vec3b c = face.at<cv::Vec3b>(static_cast<int>(mid.y()), static_cast<int>(mid.x()));
    // Yellow (BGR 0, 230, 255) drawn over the photograph: the line is 3 px
    // wide and follows the projected trace to within its sampling (1/32 of
    // the segment, well under a pixel of bend), so its centre is pure.
    if (c[2] > 200 && c[1] > 180 && c[0] < 90) ++on_trace;
  }
  ASSERT_GT(checked, 0);
  EXPECT_EQ(on_trace, checked);
  // And the photograph is there: textured rock, not a blank.
  cv::Scalar mean, sd;
  cv::meanStdDev(report.photograph, mean, sd);
  EXPECT_GT(sd[0], 10);

  // The printed pages: page 1 shows the face with yellow traces and the
  // red (removable) keyblock; the stereonet's circle is drawn on a page.
  const cv::Mat page1 = cv::imread((*dir_ / "page-1.png").string());
  ASSERT_FALSE(page1.empty());
  cv::Mat yellow, red;
  cv::inRange(page1, cv::Scalar(0, 170, 190), cv::Scalar(110, 255, 255), yellow);
  cv::inRange(page1, cv::Scalar(0, 0, 120), cv::Scalar(120, 110, 255), red);
  EXPECT_GT(cv::countNonZero(yellow), 50);
  EXPECT_GT(cv::countNonZero(red), 200);
  bool circle = false;
  for (const auto& entry : fs::directory_iterator(*dir_)) {
    if (entry.path().extension() != ".png") continue;
    cv::Mat grey;
    cv::cvtColor(cv::imread(entry.path().string()), grey, cv::COLOR_BGR2GRAY);
    cv::medianBlur(grey, grey, 3);
    std::vector<cv::Vec3f> circles;
    cv::HoughCircles(grey, circles, cv::HOUGH_GRADIENT, 2, 200, 100, 60, 60, 300);
    circle = circle || !circles.empty();
  }
  EXPECT_TRUE(circle) << "no stereonet circle on any page";
}

TEST_F(ReportVerb, AVisitTheProjectDoesNotHaveIsBadInput) {
  const auto r = run_rockface("report " + project().string() + " --visit 99 --out " +
                              (*dir_ / "x.pdf").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--visit"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(*dir_ / "x.pdf"));
  const auto missing = run_rockface("report " + (*dir_ / "none.rockface").string() + " --out " +
                                    (*dir_ / "y.pdf").string());
  EXPECT_EQ(missing.exit_code, 2);
}

// Issue 41: a visit made by `rockface measure` (the demo picks measured on
// the replayed visit's 3D image) has no photographs, calibration or
// reconstruction of its own. Its report said "0 x 0 px, fx 0.0", "model
// scale 1.0000", "predicted depth precision 0.0 mm at 0.00 m" and "0 tie
// points": unknowns shown as zeros. They are said to be not known.
TEST_F(ReportVerb, AVisitMadeByMeasureSaysWhatItDoesNotKnow) {
  const fs::path copy = *dir_ / "measured.rockface";
  fs::copy_file(project(), copy, fs::copy_options::overwrite_existing);
  const auto measured = run_rockface(
      "measure " + copy.string() + " --traces " + std::string(ROCKFACE_SOURCE_DIR) +
      "/tools/samples/tunnel-face-demo.picks.json --out " + (*dir_ / "measures.json").string());
  ASSERT_EQ(measured.exit_code, 0) << measured.err;
  const fs::path pdf = *dir_ / "measured.pdf";
  const auto report = run_rockface("report " + copy.string() + " --visit 2 --out " + pdf.string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const fs::path txt = *dir_ / "measured.txt";
  ASSERT_EQ(std::system(("pdftotext -layout " + pdf.string() + " " + txt.string()).c_str()), 0);
  const std::string t = slurp(txt);
  EXPECT_NE(t.find("calibration: not known (no photographs in this visit)"), std::string::npos)
      << t;
  EXPECT_NE(t.find("scale: not known"), std::string::npos) << t;
  EXPECT_NE(t.find("vertical: not known"), std::string::npos) << t;
  EXPECT_NE(t.find("north: not known"), std::string::npos) << t;
  EXPECT_NE(t.find("predicted depth precision, point spacing and tie points: not known"),
            std::string::npos)
      << t;
  for (const char* zero :
       {"0 x 0 px", "fx 0.0", "model scale", "0.0 mm at 0.00 m", "0 tie points", "rms 0.00 px"})
    EXPECT_EQ(t.find(zero), std::string::npos) << "\"" << zero << "\" in\n" << t;
  // The visit's own report keeps every figure it has (the same project).
  EXPECT_NE(text().find("model scale "), std::string::npos);
  EXPECT_NE(text().find(" tie points, reprojection rms "), std::string::npos);
}

// Issue 46: the report names the geologist who mapped the visit: the one
// `replay --geologist` gave; "not recorded" once `place --geologist ""`
// took the name away; the one `measure --geologist` gave its new visit.
TEST_F(ReportVerb, NamesTheGeologistWhoMappedTheVisit) {
  EXPECT_NE(text().find("geologist: Anna Berger"), std::string::npos) << text();
  const fs::path copy = *dir_ / "geologist.rockface";
  fs::copy_file(project(), copy, fs::copy_options::overwrite_existing);
  const auto unnamed = run_rockface("place " + copy.string() + " --visit 1 --geologist ''");
  ASSERT_EQ(unnamed.exit_code, 0) << unnamed.err;
  EXPECT_NE(unnamed.out.find("visit 1 geologist: not recorded"), std::string::npos) << unnamed.out;
  const auto measured =
      run_rockface("measure " + copy.string() + " --traces " + std::string(ROCKFACE_SOURCE_DIR) +
                   "/tools/samples/tunnel-face-demo.picks.json --out " +
                   (*dir_ / "g-measures.json").string() + " --geologist \"O'Brien <b>\"");
  ASSERT_EQ(measured.exit_code, 0) << measured.err;
  auto report_text = [&](int visit) {
    const fs::path pdf = *dir_ / ("geologist-" + std::to_string(visit) + ".pdf");
    const fs::path txt = *dir_ / ("geologist-" + std::to_string(visit) + ".txt");
    const auto report = run_rockface("report " + copy.string() + " --visit " +
                                     std::to_string(visit) + " --out " + pdf.string());
    EXPECT_EQ(report.exit_code, 0) << report.err;
    EXPECT_EQ(std::system(("pdftotext -layout " + pdf.string() + " " + txt.string()).c_str()), 0);
    return slurp(txt);
  };
  const std::string first = report_text(1);
  EXPECT_NE(first.find("geologist: not recorded"), std::string::npos) << first;
  EXPECT_EQ(first.find("Anna Berger"), std::string::npos) << first;
  const std::string second = report_text(2);
  EXPECT_NE(second.find("geologist: O'Brien <b>"), std::string::npos) << second;
}

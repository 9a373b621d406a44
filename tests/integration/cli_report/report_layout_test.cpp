// The field report as printed (issue 39): every page of the PDF of the demo,
// the tunnel drive and the wedges around a drive, read back word by word
// with their boxes (poppler's `pdftotext -bbox-layout`): no two words of a
// line overlap, no word leaves its page, no key of a file or a program
// (snake_case, dotted) stands where a word should, no absolute path of the
// machine that wrote it, and no line printed twice.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_files.h"
#include "tests/support/cli_run.h"
#include "tests/support/pdf_word_boxes.h"
#include "tests/support/test_paths.h"
#include "tests/support/tunnel_drive_scene.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::PdfPage;
using rockface::test::run_rockface;

const fs::path kSamples = fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples";

// Two words of one line may touch: poppler's boxes are the glyphs' advance
// boxes, computed from the same font metrics cairo laid them out with, so
// neighbours meet to within rounding of the PDF's coordinates (3 decimals);
// 0.1 pt (1/30 mm) is far below a character's width and above that rounding.
constexpr double kOverlapPt = 0.1;

// Words that look like keys but are words: a file name the report names on
// purpose (the project's), and Latin abbreviations.
bool genuine_word(const std::string& w) {
  static const std::regex file_name(R"([A-Za-z0-9_.-]+\.(rockface|json|csv|pdf))");
  static const std::set<std::string> words{"e.g", "i.e"};
  return std::regex_match(w, file_name) || words.count(w) > 0;
}

// A word with its quotes, brackets and trailing punctuation taken off.
std::string bare(std::string w) {
  const std::string strip = "()[]{}'\",;:";
  while (!w.empty() && strip.find(w.front()) != std::string::npos) w.erase(0, 1);
  while (!w.empty() && (strip + ".").find(w.back()) != std::string::npos) w.pop_back();
  return w;
}

// Every fault of the printed pages, one line each ("page 2: ...").
std::vector<std::string> layout_faults(const std::vector<PdfPage>& pages) {
  static const std::regex key_like(R"([a-z]+(\.|_)[a-z_]+)");
  static const std::regex absolute_path(R"(/[^/\s]+/[^/\s]+.*)");
  std::vector<std::string> faults;
  std::map<std::string, int> seen;  // a line's text -> the page it was first printed on
  for (std::size_t p = 0; p < pages.size(); ++p) {
    const PdfPage& page = pages[p];
    const std::string where = "page " + std::to_string(p + 1) + ": ";
    for (const auto& line : page.lines) {
      std::vector<rockface::test::PdfWord> words = line.words;
      std::sort(words.begin(), words.end(),
                [](const auto& a, const auto& b) { return a.x_min < b.x_min; });
      for (std::size_t i = 0; i < words.size(); ++i) {
        const auto& w = words[i];
        if (w.x_min < 0 || w.y_min < 0 || w.x_max > page.width || w.y_max > page.height)
          faults.push_back(where + "'" + w.text + "' outside the page");
        for (std::size_t k = i + 1; k < words.size(); ++k)
          if (w.x_max - words[k].x_min > kOverlapPt)
            faults.push_back(where + "'" + w.text + "' overlaps '" + words[k].text + "' in \"" +
                             line.text() + "\"");
        const std::string b = bare(w.text);
        if (std::regex_search(b, key_like) && !genuine_word(b))
          faults.push_back(where + "key-like word '" + b + "' in \"" + line.text() + "\"");
        if (std::regex_match(b, absolute_path))
          faults.push_back(where + "absolute path '" + b + "'");
      }
      // A sentence (eight words or more) said twice; table cells ("clustered
      // from 15 measured planes" of each set) and short labels may repeat.
      const std::string text = line.text();
      if (line.words.size() >= 8 && !seen.emplace(text, static_cast<int>(p + 1)).second)
        faults.push_back(where + "printed again (first on page " + std::to_string(seen[text]) +
                         "): \"" + text + "\"");
    }
  }
  return faults;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

class ReportLayout : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("rockface-report-layout-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  // `rockface report` of the project's latest visit; its pages' words.
  static std::vector<PdfPage> report_pages(const fs::path& project) {
    const fs::path pdf = project.string() + ".pdf";
    const auto report = run_rockface("report " + project.string() + " --out " + pdf.string());
    EXPECT_EQ(report.exit_code, 0) << report.err;
    return rockface::test::pdf_word_boxes(pdf);
  }
  static inline fs::path dir_;
};

TEST_F(ReportLayout, TheDemoReportReadsAsPrinted) {
  const fs::path project = dir_ / "demo.rockface";
  const auto replay = run_rockface("replay " + (kSamples / "tunnel-face-demo.scene.json").string() +
                                   " --preset fast --project " + project.string());
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  const auto pages = report_pages(project);
  ASSERT_FALSE(pages.empty());
  const auto faults = layout_faults(pages);
  EXPECT_TRUE(faults.empty()) << joined(faults);
  // The demo's five face outlines, each one flat piece, in one line.
  int outline_lines = 0;
  for (const auto& page : pages)
    for (const auto& line : page.lines)
      outline_lines += line.text().rfind("face outline", 0) == 0 ||
                       line.text().find(" face outlines, each one flat piece") != std::string::npos;
  EXPECT_EQ(outline_lines, 1);
}

TEST_F(ReportLayout, TheTunnelDriveReportReadsAsPrinted) {
  // The sample's round, its tunnel files by absolute path (the scene is
  // written here), at 900 x 600 with the same field of view to be quick.
  nlohmann::json s = rockface::test::tunnel_drive_scene();
  rockface::test::at_900_by_600(s);
  const fs::path scene = dir_ / "drive.scene.json", project = dir_ / "drive.rockface";
  std::ofstream(scene) << s.dump(2);
  const auto replay =
      run_rockface("replay " + scene.string() + " --preset fast --project " + project.string());
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  const auto pages = report_pages(project);
  ASSERT_FALSE(pages.empty());
  const auto faults = layout_faults(pages);
  EXPECT_TRUE(faults.empty()) << joined(faults);
  // The visit's place in the tunnel is told once (the tunnel section's
  // line), not again at the head of the round's summary.
  int told = 0;
  std::string where;
  for (const auto& page : pages)
    for (const auto& line : page.lines)
      if (line.text().find("face at chainage") != std::string::npos) {
        ++told;
        where += line.text() + "\n";
      }
  EXPECT_EQ(told, 1) << where;
}

TEST_F(ReportLayout, TheWedgesReportReadsAsPrinted) {
  // A visit of the sample drive at chainage 105 with three sets of planes
  // (as tests/firmware-app/wedges builds it): the report's wedges section.
  namespace st = rockface::storage;
  const fs::path project = dir_ / "wedges.rockface";
  {
    st::ProjectInfo info;
    info.name = "drive";
    info.datum = {512340.0, 5211870.0, 410.0};
    st::ProjectStore store = st::ProjectStore::create(project, info);
    st::TunnelRecord tunnel;
    tunnel.name = "Main drive";
    const auto table = st::read_alignment_csv(kSamples / "tunnel-drive.alignment.csv");
    tunnel.stations = table.stations;
    tunnel.radii = table.radii;
    tunnel.polyline = table.polyline;
    tunnel.profile = st::read_profile_file(kSamples / "tunnel-drive.profile.json");
    store.save_tunnel(tunnel);
    const st::RecordId visit = store.begin_visit("face at 105");
    const std::array<double, 5> ddip{-2, -1, 0, 1, 2}, ddir{1, -2, 2, -1, 0};
    std::vector<st::Measurement> planes;
    for (auto [dip, dipdir] :
         {std::pair{65.0, 20.0}, std::pair{60.0, 145.0}, std::pair{55.0, 260.0}})
      for (std::size_t i = 0; i < ddip.size(); ++i) {
        st::Measurement m;
        m.visit_id = visit;
        m.kind = st::Measurement::Kind::trace;
        m.label = "T" + std::to_string(planes.size() + 1);
        m.points = {{0, 35, 0}, {1, 35, 1}};
        m.dip_deg = dip + ddip[i];
        m.dipdir_deg = dipdir + ddir[i];
        planes.push_back(m);
      }
    store.save_measurements(visit, planes);
    st::VisitPlacement p;
    p.visit_id = visit;
    p.chainage = 105;
    p.note = "typed";
    store.save_visit_placement(p);
  }
  const auto pages = report_pages(project);
  ASSERT_FALSE(pages.empty());
  bool wedges = false;
  for (const auto& page : pages)
    for (const auto& line : page.lines)
      wedges = wedges || line.text() == "Wedges around the excavation";
  EXPECT_TRUE(wedges) << "the report has no wedges section";
  const auto faults = layout_faults(pages);
  EXPECT_TRUE(faults.empty()) << joined(faults);
}

}  // namespace

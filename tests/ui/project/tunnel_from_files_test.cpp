// Issue 42: Project → Tunnel from files. A project made from a camera's card
// (the tunnel-drive sample rendered, its pair replayed with the pole and the
// compass line: no scene, no tunnel) gets its tunnel on the tablet from the
// alignment CSV and the design profile on a USB stick, chosen from the
// stick's own file list, by the workflow `rockface tunnel` runs: the tunnel
// stored is the one the command line stores from the same files, and the
// visit is then placed by the pole's typed chainage. A broken alignment CSV
// is refused with the command line's own message, shown on the tablet, and
// the project's bytes are unchanged.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"
#include "storage/tunnel/visit_heading.h"
#include "tests/support/card_folder.h"
#include "tests/support/cli_run.h"
#include "tests/ui/demo_project.h"
#include "tests/ui/drive_tablet.h"
#include "ui/app/app_state.h"
#include "ui/app/text_check.h"
#include "ui/widgets/format.h"
#include "ui/widgets/widgets_text.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using nlohmann::json;

// The project as it lies on the card: the database and its write-ahead log.
std::string project_bytes(const fs::path& project) {
  std::string bytes;
  for (const fs::path& f : {project, fs::path(project.string() + "-wal")}) {
    std::ifstream in(f, std::ios::binary);
    bytes.append(std::istreambuf_iterator<char>(in), {});
    bytes += '\0';  // a missing log differs from an empty one
  }
  return bytes;
}

bool drawn(const std::string& text) {
  for (const ui::DrawnText& d : ui::drawn_text())
    if (d.text == text) return true;
  return false;
}

// The stick the tablet finds (ROCKFACE_USB_DIR, firmware-app's
// StoreExportRunner), unplugged when the test ends however it ends: the
// other tests of this process have no stick.
struct StickPlugged {
  explicit StickPlugged(const fs::path& folder) { ::setenv("ROCKFACE_USB_DIR", folder.c_str(), 1); }
  ~StickPlugged() { ::unsetenv("ROCKFACE_USB_DIR"); }
  StickPlugged(const StickPlugged&) = delete;
  StickPlugged& operator=(const StickPlugged&) = delete;
};

// The drive sample's pair on a card, replayed into a project with no tunnel
// (card_tunnel_visit_test.cpp's route).
fs::path card_project(const fs::path& root) {
  const json truth = test::render_sample("tunnel-drive.scene.json", root);
  const fs::path card = root / "DCIM";
  test::write_card(root / "render", card, "DSC_0417.JPG", "DSC_0418.JPG");
  const json& line = truth.at("reference_line");
  std::ofstream(card / "visit.json") << json{
      {"format", "rockface-visit/1"},
      {"range_pole_m", truth.at("range_pole").at("length")},
      {"compass",
       {{"reference_line_px", line.at("left")}, {"azimuth_deg", line.at("azimuth_deg")}}},
      {"preset", "fast"},
      // Issue 46: the face the visit was taken at, noted on site.
      {"heading", "North portal"},
      // And who mapped it.
      {"geologist", "Anna Berger"}}.dump(2);
  const fs::path project = root / "card.rockface";
  const test::CliRun r =
      test::run_rockface("replay " + card.string() + " --project " + project.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return project;
}

TEST(TunnelFromFiles, TheTabletGivesTheProjectItsTunnelFromAStickAndPlacesTheVisit) {
  const fs::path root = test::ui_test_dir() / "tunnel-from-files";
  fs::create_directories(root);
  const fs::path project = card_project(root);
  ASSERT_FALSE(HasFailure());
  const fs::path cli_project = root / "cli.rockface";
  fs::copy_file(project, cli_project);

  // The stick: the surveyor's and designer's files in a folder of their
  // own, a broken alignment and a profile at its top.
  const fs::path samples = fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples";
  const fs::path stick = root / "stick";
  fs::create_directories(stick / "survey");
  fs::copy_file(samples / "tunnel-drive.alignment.csv", stick / "survey/main-drive.csv");
  fs::copy_file(samples / "tunnel-drive.profile.json", stick / "survey/design.json");
  fs::copy_file(samples / "tunnel-drive.profile.json", stick / "design.json");
  std::ofstream(stick / "broken.csv") << "chainage,easting,northing,elevation,radius\n"
                                         "0.000,512340.000,5211800.000,410.000,0\n"
                                         "100.000,512340.000\n";
  const StickPlugged plugged(stick);

  test::DriveTablet tablet(project);
  ui::HeadlessSession& s = tablet.session;
  ui::AppState& app = s.state();
  s.tap("Project");
  ASSERT_FALSE(app.project.tunnel.record);
  s.tap("Tunnel from files");
  const auto& picker = app.project.tunnel.picker;
  ASSERT_TRUE(picker.open);

  // The broken alignment: refused as the command line refuses it.
  s.tap("broken.csv");
  s.tap("design.json");
  const std::string before = project_bytes(project);
  s.tap("Give the project this tunnel");
  s.settle();
  s.frame();
  const test::CliRun refused = test::run_rockface(
      "tunnel " + cli_project.string() + " --alignment " + (stick / "broken.csv").string() +
      " --profile " + (stick / "design.json").string());
  EXPECT_EQ(refused.exit_code, 2);
  const std::string prefix = "rockface: ";
  ASSERT_EQ(refused.err.rfind(prefix, 0), 0u) << refused.err;
  std::string message = refused.err.substr(prefix.size());
  while (!message.empty() && message.back() == '\n') message.pop_back();
  ASSERT_EQ(picker.lines.size(), 1u);
  EXPECT_EQ(picker.lines.front(), message);
  // Shown as every paragraph is, without the machine's folders.
  EXPECT_TRUE(drawn(ui::format::without_folders(message)))
      << "the tablet does not show: " << message;
  EXPECT_FALSE(app.project.tunnel.record);
  EXPECT_EQ(project_bytes(project), before) << "a refused file changed the project";

  // The surveyor's files from their folder.
  s.tap("Another alignment");
  s.tap("survey/");
  s.tap("main-drive.csv");
  s.tap("design.json");
  s.tap("Give the project this tunnel");
  s.settle();
  s.frame();
  ASSERT_TRUE(app.project.tunnel.record) << (picker.lines.empty() ? "" : picker.lines.front());
  EXPECT_FALSE(picker.open);

  // The command line's tunnel from the same files: the same record.
  const test::CliRun given =
      test::run_rockface("tunnel " + cli_project.string() + " --alignment " +
                         (stick / "survey/main-drive.csv").string() + " --profile " +
                         (stick / "survey/design.json").string());
  ASSERT_EQ(given.exit_code, 0) << given.err;
  const storage::TunnelRecord& tablet_tunnel = *app.project.tunnel.record;
  storage::TunnelRecord cli_tunnel;
  {
    storage::ProjectStore cli = storage::ProjectStore::open(cli_project);
    cli_tunnel = *cli.load_tunnel();
  }
  EXPECT_EQ(tablet_tunnel.name, "main-drive");
  EXPECT_EQ(tablet_tunnel.name, cli_tunnel.name);
  EXPECT_EQ(tablet_tunnel.alignment_source, cli_tunnel.alignment_source);
  EXPECT_EQ(tablet_tunnel.profile_source, cli_tunnel.profile_source);
  ASSERT_EQ(tablet_tunnel.stations.size(), cli_tunnel.stations.size());
  for (std::size_t k = 0; k < cli_tunnel.stations.size(); ++k) {
    // Both read from the same text into the same REAL columns: equal.
    EXPECT_EQ(tablet_tunnel.stations[k].chainage, cli_tunnel.stations[k].chainage);
    EXPECT_EQ(tablet_tunnel.stations[k].survey, cli_tunnel.stations[k].survey);
  }
  EXPECT_EQ(tablet_tunnel.profile.area(), cli_tunnel.profile.area());

  // The visit placed where the geologist stood the pole (the scene's
  // tunnel.placement), typed into the panel's fields.
  auto& t = app.project.tunnel;
  t.typed_chainage = 110.6;
  t.typed_offset = 1.3;
  t.typed_height = -1.05;
  s.tap("Place this visit");
  s.settle();
  s.frame();
  ASSERT_TRUE(t.placement);
  EXPECT_EQ(t.placement->method, storage::VisitPlacement::Method::chainage_compass);
  // As in card_tunnel_visit_test.cpp: the face bulges from chainage 111.6
  // (its centre) to 112.0; the median of the rays along the axis lies
  // between, with the fast preset's depth error (~3 cm at 8 m).
  EXPECT_GT(t.placement->chainage, 111.6);
  EXPECT_LT(t.placement->chainage, 112.0);

  // Issue 46: the heading the card's visit file named, shown, and named
  // anew on the tablet (the office lists and filters visits by it).
  EXPECT_EQ(t.visit_heading, "North portal");
  t.typed_heading = "South portal";
  s.frame();  // the button is drawn enabled once the typed name differs
  s.tap("Name the heading");
  s.settle();
  s.frame();
  EXPECT_EQ(t.visit_heading, "South portal");
  storage::ProjectStore stored = storage::ProjectStore::open(project);
  const auto visits = stored.list_visits();
  ASSERT_EQ(visits.size(), 1u);
  EXPECT_EQ(storage::load_visit_heading(stored, visits.front().id), "South portal");
  // The card's visit file named its geologist; the tablet shows it.
  EXPECT_EQ(visits.front().geologist, std::optional<std::string>("Anna Berger"));
  EXPECT_EQ(s.state().session->visit_geologist(), std::optional<std::string>("Anna Berger"));
}

}  // namespace

// Issue 43: "Import a 3D image" on the tablet's Project screen
// (ui/project/import_picker.h), headless with the program's own runners: the
// files on a USB stick are listed by the format their names say, a cloud
// written by an independent writer (write_face_cloud.py) becomes a new visit
// that the screen then shows, and a file cut short is refused with the words
// `rockface import` prints, the project's bytes untouched.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_folders.h"
#include "tests/ui/field_tablet.h"
#include "ui/app/app_state.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using namespace rockface::ui;

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The project's file and its journal as they are on disk.
std::string project_bytes(const fs::path& project) {
  std::string out = bytes_of(project);
  if (fs::exists(project.string() + "-wal")) out += bytes_of(project.string() + "-wal");
  return out;
}

const ImportPickerFile* listed(const AppState& app, const std::string& shown) {
  for (const auto& place : app.project.import.places)
    for (const auto& f : place.files)
      if (f.shown == shown) return &f;
  return nullptr;
}

TEST(ImportPicker, ACloudOnAStickBecomesAVisitAndACutFileIsRefusedWithNothingStored) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-import-picker-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const fs::path stick = dir / "stick", tablet = dir / "tablet";
  fs::create_directories(stick / "scans");
  fs::create_directories(tablet);
  test::remove_when_passed(dir);
  // The sample cloud: 20,000 points of a face at UTM coordinates, as PLY,
  // LAS, CSV and PTS, with its truth.
  const std::string write = "python3 " + std::string(ROCKFACE_SOURCE_DIR) +
                            "/tests/integration/import/write_face_cloud.py " +
                            (stick / "scans").string() + " --points 20000";
  ASSERT_EQ(std::system(write.c_str()), 0) << write;
  std::ifstream truth_in(stick / "scans" / "truth.json");
  const nlohmann::json truth = nlohmann::json::parse(truth_in);
  // The binary PLY cut in the middle of its points, and a file of no 3D
  // format, which is not listed.
  const std::string ply = bytes_of(stick / "scans" / "face.ply");
  std::ofstream(stick / "cut.ply", std::ios::binary) << ply.substr(0, ply.size() / 2);
  std::ofstream(stick / "notes.docx") << "not a cloud";
  ::setenv("ROCKFACE_USB_DIR", stick.c_str(), 1);

  const fs::path project = tablet / "site.rockface";
  {
    storage::ProjectInfo info;
    info.name = "site";
    storage::ProjectStore::create(project, info);
  }
  UiOptions options = test::field_tablet_options(project);
  options.projects_folder = tablet;
  test::FieldTablet on_the_tablet(options);
  HeadlessSession& s = on_the_tablet.session;
  AppState& app = s.state();
  ASSERT_TRUE(app.session);
  const std::size_t visits_before = app.session->visits().size();

  s.tap("Project");
  s.frame();
  s.tap("Import a 3D image");
  s.frame();
  ASSERT_TRUE(app.project.import.open);
  ASSERT_EQ(app.project.import.places.size(), 2u);          // the tablet and the stick
  EXPECT_TRUE(app.project.import.places[0].files.empty());  // the project is no 3D image
  const std::string scans = (fs::path("scans") / "face.").string();
  ASSERT_TRUE(listed(app, scans + "las"));
  EXPECT_EQ(listed(app, scans + "las")->format, "LAS");
  EXPECT_EQ(listed(app, scans + "ply")->format, "PLY");
  EXPECT_EQ(listed(app, scans + "csv")->format, "text cloud");
  EXPECT_EQ(listed(app, scans + "pts")->format, "PTS");
  ASSERT_TRUE(listed(app, "cut.ply"));
  EXPECT_FALSE(listed(app, "notes.docx"));

  // Refused: the status line says what `rockface import` says of the file
  // (after its "rockface: "), and nothing of the project changed.
  const std::string before = project_bytes(project);
  s.tap("Import cut.ply");
  s.settle();
  const fs::path copy = dir / "copy.rockface";
  fs::copy_file(project, copy);
  const test::CliRun cli =
      test::run_rockface("import " + copy.string() + " " + (stick / "cut.ply").string());
  ASSERT_EQ(cli.exit_code, 2) << cli.out;
  std::string words = cli.err.substr(cli.err.find(": ") + 2);
  while (!words.empty() && words.back() == '\n') words.pop_back();
  const auto screen = static_cast<std::size_t>(Screen::project);
  const std::string status = app.statuses.line(screen);
  EXPECT_NE(status.find(words), std::string::npos) << status << "\nCLI: " << words;
  EXPECT_EQ(project_bytes(project), before);
  EXPECT_EQ(app.session->visits().size(), visits_before);

  // The sample cloud: a new visit, chosen and shown with its 3D image.
  s.tap("Import " + scans + "las");
  s.settle();
  ASSERT_EQ(app.session->visits().size(), visits_before + 1) << app.statuses.line(screen);
  ASSERT_TRUE(app.session->visit());
  EXPECT_EQ(*app.session->visit(), app.session->visits().back().id);
  ASSERT_FALSE(app.session->pairs().empty());
  ASSERT_TRUE(app.session->model());
  EXPECT_EQ(app.session->model()->vertex_count, truth.at("points").get<std::int64_t>());
  EXPECT_EQ(app.session->model()->registration_kind, "scanner");
  EXPECT_NE(app.statuses.line(screen).find("face.las, LAS"), std::string::npos)
      << app.statuses.line(screen);
  EXPECT_FALSE(app.project.import.open) << "the list closes once the visit is imported";
  // The model on display is the imported one.
  EXPECT_EQ(app.model_view.model_id(), app.session->model()->id);
}

}  // namespace

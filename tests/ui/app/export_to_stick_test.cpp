// Issue 43: "Export to USB stick" on the tablet's Blocks and Project screens
// (ui/app/export_to_stick.h), through `rockface ui --headless --script` with
// the program's own services: the visit's exports land in a folder on the
// stick; without a stick nothing is written and the status line says so.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/ui/demo_project.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface::test;

int run_with_stick(const fs::path& project, const fs::path& stick, const std::string& steps,
                   const std::string& name) {
  const fs::path script = ui_test_dir() / (name + ".json");
  std::ofstream(script) << R"({"viewport": [800, 500], "steps": )" << steps << "}";
  return run_rockface_logged(
      "ui --project " + project.string() + " --camera " + demo_scene() +
          " --scale 0.6 --max-triangles 20000 --headless --script " + script.string(),
      ui_test_dir() / (name + ".txt"), "env ROCKFACE_USB_DIR=" + stick.string() + " ");
}

TEST(ExportToStick, TheVisitsExportsLandOnTheStickFromBothScreens) {
  const fs::path project = copy_of_demo("export");
  const fs::path stick = ui_test_dir() / "stick";
  fs::create_directories(stick);
  ASSERT_EQ(
      run_with_stick(project, stick,
                     R"([{"tap": "Blocks"}, {"tap": "Export to USB stick"}, {"wait": "task"}])",
                     "export-blocks"),
      0)
      << slurp(ui_test_dir() / "export-blocks.txt");
  const fs::path folder = stick / "export-visit-1";
  ASSERT_TRUE(fs::is_directory(folder)) << slurp(ui_test_dir() / "export-blocks.txt");
  EXPECT_TRUE(fs::exists(folder / "visit-1.dxf"));
  EXPECT_TRUE(fs::exists(folder / "visit-1-joints.csv"));
  bool obj = false;
  for (const auto& e : fs::directory_iterator(folder)) obj |= e.path().extension() == ".obj";
  EXPECT_TRUE(obj);

  // The Project screen's button writes the same folder again.
  fs::remove_all(folder);
  ASSERT_EQ(
      run_with_stick(project, stick,
                     R"([{"tap": "Project"}, {"tap": "Export to USB stick"}, {"wait": "task"}])",
                     "export-project"),
      0)
      << slurp(ui_test_dir() / "export-project.txt");
  EXPECT_TRUE(fs::exists(folder / "visit-1.dxf")) << slurp(ui_test_dir() / "export-project.txt");
}

TEST(ExportToStick, WithoutAStickNothingIsWrittenAndTheTabletSaysSo) {
  const fs::path project = copy_of_demo("export-none");
  const fs::path missing = ui_test_dir() / "no-stick-here";
  ASSERT_EQ(run_with_stick(project, missing,
                           R"([{"tap": "Blocks"}, {"tap": "Export to USB stick"}, {"frames": 2}])",
                           "export-none"),
            0)
      << slurp(ui_test_dir() / "export-none.txt");
  EXPECT_FALSE(fs::exists(missing));
  const std::string log = slurp(ui_test_dir() / "export-none.txt");
  EXPECT_NE(log.find("No USB stick found"), std::string::npos) << log;
}

}  // namespace

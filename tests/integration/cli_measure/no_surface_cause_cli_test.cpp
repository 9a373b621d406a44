// A pick with no surface under it says why (issue 39, "Light"): on the
// tunnel-bad-day sample (flash, a lamp, dust), registered at the fast
// preset, a tap on the unlit strip left of the face is "too dark to
// match", and a tap at the photograph's right edge is a spot the two
// photographs did not match. The measurement
// is refused by name and nothing is stored.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;
using rockface::test::CliRun;
using rockface::test::run_rockface;

TEST(MeasureCli, APickWithNoSurfaceSaysWhy) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-no-surface-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path project = dir / "bad-day.rockface";
  CliRun r = run_rockface("replay " + std::string(ROCKFACE_SOURCE_DIR) +
                          "/tools/samples/tunnel-bad-day.scene.json --preset fast --project " +
                          project.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto visits_before = rockface::storage::ProjectStore::open(project).list_visits().size();

  struct Case {
    const char* name;
    const char* pixel;  // on the left photograph (1200 x 800)
    const char* cause;
  };
  // x = 12: the sample's photographs are black left of x ~ 35 (the unlit
  // tunnel wall beyond the lamp's reach); x = 1190: a well-lit, textured
  // spot 10 px from the right edge, where the 3D image stops short of the
  // photograph's border (the matcher's window and disparity search need
  // room around each pixel): a hole that is not the light's.
  const Case cases[] = {
      {"dark", "[12, 400]", "left photograph is too dark to match"},
      {"unmatched", "[1190, 400]", "the two photographs were not matched there"},
  };
  for (const Case& c : cases) {
    const fs::path picks = dir / (std::string(c.name) + ".json");
    std::ofstream(picks)
        << R"({"format": "rockface-picks/1", "points": [{"id": "P1", "photo": "left", "pixel": )"
        << c.pixel << "}]}";
    const fs::path out = dir / (std::string(c.name) + "-out.json");
    r = run_rockface("measure " + project.string() + " --traces " + picks.string() + " --out " +
                     out.string());
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find("points[0].pixel: no surface of the 3D image under this pick: "),
              std::string::npos)
        << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.cause), std::string::npos) << c.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.name;
  }
  EXPECT_EQ(rockface::storage::ProjectStore::open(project).list_visits().size(), visits_before);
  fs::remove_all(dir);
}

// `rockface measure --add-to-visit N` (issue 42): the traces mapped at a
// desk go into the visit whose 3D image they were measured on, so that one
// visit (and one report) carries its camera, scale, north and traces. A
// visit without a 3D image, or a label the visit already holds, is refused
// by name with nothing stored.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/support/json_file.h"
#include "tests/support/temp_folders.h"
#include "tests/support/truth_picks.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rockface::test::CliRun;
using rockface::test::run_rockface;
using rockface::test::write_json;

TEST(MeasureAddToVisitCli, StoresInTheVisitMeasuredOnAndRefusesByName) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-measure-add-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  rockface::test::remove_when_passed(dir);
  write_json(dir / "face.scene.json", rockface::test::demo_scene());
  CliRun r = run_rockface("render " + (dir / "face.scene.json").string() + " --out " +
                          (dir / "render").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path project = dir / "site.rockface";
  r = run_rockface("replay " + (dir / "face.scene.json").string() + " --project " +
                   project.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;

  rockface::storage::RecordId visit = 0, empty = 0;
  std::size_t measurements = 0, joints = 0;
  {
    auto store = rockface::storage::ProjectStore::open(project);
    const auto visits = store.list_visits();
    ASSERT_EQ(visits.size(), 1u);
    visit = visits[0].id;
    measurements = store.list_measurements(visit).size();
    joints = store.list_joints(visit).size();
    // A visit with notes and no photographs: nothing to measure on.
    empty = store.begin_visit("notes on the crown");
  }
  // A point picked on the face, under an id the replay's visit lacks.
  write_json(dir / "picks.json",
             json{{"format", "rockface-picks/1"},
                  {"points",
                   {{{"id", "Q1"}, {"photo", "left"}, {"pixel", {1100, 700}}, {"radius", 0.3}}}}});
  const std::string measure = "measure " + project.string() + " --traces " +
                              (dir / "picks.json").string() + " --out " +
                              (dir / "out.json").string();
  r = run_rockface(measure + " --add-to-visit " + std::to_string(visit));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("added to " + project.string() + ", visit " + std::to_string(visit)),
            std::string::npos)
      << r.out;
  {
    auto store = rockface::storage::ProjectStore::open(project);
    EXPECT_EQ(store.list_visits().size(), 2u) << "a new visit was started";
    const auto ms = store.list_measurements(visit);
    EXPECT_EQ(ms.size(), measurements + 1);  // the replay's, and Q1
    EXPECT_TRUE(std::any_of(ms.begin(), ms.end(), [](const auto& m) { return m.label == "Q1"; }));
    EXPECT_GT(store.list_joints(visit).size(), joints);
  }

  // Refused, exit 2, nothing stored and no output: Q1 again (the visit holds
  // it), a visit without a 3D image (named by what started it), a visit
  // that is not there, and --add-to-visit beside --visit.
  struct Refused {
    std::string args, says;
  };
  const std::vector<Refused> refused{
      {" --add-to-visit " + std::to_string(visit),
       "visit " + std::to_string(visit) + " already holds a measurement Q1"},
      {" --add-to-visit " + std::to_string(empty),
       "--add-to-visit: visit " + std::to_string(empty) + " (notes on the crown) of " +
           project.string() + " has no 3D image to measure on"},
      {" --add-to-visit 99", "--add-to-visit: no visit 99 in " + project.string()},
      {" --add-to-visit " + std::to_string(visit) + " --visit " + std::to_string(visit),
       "--add-to-visit: it names the visit measured on and stored in"},
  };
  fs::remove(dir / "out.json");
  for (const auto& x : refused) {
    r = run_rockface(measure + x.args);
    EXPECT_EQ(r.exit_code, 2) << x.args << ": " << r.err;
    EXPECT_NE(r.err.find(x.says), std::string::npos) << x.args << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.json")) << x.args;
  }
  auto store = rockface::storage::ProjectStore::open(project);
  EXPECT_EQ(store.list_visits().size(), 2u);
  EXPECT_EQ(store.list_measurements(visit).size(), measurements + 1);
  EXPECT_TRUE(store.list_measurements(empty).empty());
}

}  // namespace

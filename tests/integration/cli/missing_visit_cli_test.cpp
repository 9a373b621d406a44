// Issue 41: `profile --visit 99` and `wedges --visit 99` on a project
// without visit 99 said it "is not placed" or "has 0 measured joint sets";
// they say the project has no visit 99 and list the visits it has.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "core/tunnel/design_profile.h"
#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_records.h"
#include "tests/support/cli_run.h"

namespace {

namespace fs = std::filesystem;

// A project with a tunnel (100 m straight north) and visits 1 and 2.
fs::path project_with_two_visits(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("missing-visit-cli-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  rockface::storage::ProjectInfo info;
  info.name = "missing visit";
  info.datum = {2690123.25, 1170456.5, 1105.125};
  info.datum_crs = "EPSG:2056 LV95 / LN02";
  const fs::path file = dir / "p.rockface";
  auto store = rockface::storage::ProjectStore::create(file, info);
  rockface::storage::TunnelRecord t;
  t.name = "north drive";
  t.stations = {{1000, info.datum}, {1100, info.datum + Eigen::Vector3d(0, 100, 1)}};
  t.polyline = true;
  t.profile = rockface::tunnel::horseshoe_profile(5, 1.5, 10, -2.5);
  store.save_tunnel(t);
  store.begin_visit("test");
  store.begin_visit("test");
  return file;
}

void expect_no_visit_99(const rockface::test::CliRun& r, const fs::path& project) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("--visit: the project " + project.string() +
                       " has no visit 99 (its visits: 1, 2)"),
            std::string::npos)
      << r.err;
}

}  // namespace

TEST(MissingVisitCli, ProfileSaysTheProjectHasNoSuchVisit) {
  const fs::path p = project_with_two_visits("profile");
  const auto r = rockface::test::run_rockface("profile " + p.string() + " --visit 99 --out " +
                                              (p.parent_path() / "dev.png").string());
  expect_no_visit_99(r, p);
  EXPECT_FALSE(fs::exists(p.parent_path() / "dev.png"));
  fs::remove_all(p.parent_path());
}

TEST(MissingVisitCli, WedgesSaysTheProjectHasNoSuchVisit) {
  const fs::path p = project_with_two_visits("wedges");
  expect_no_visit_99(rockface::test::run_rockface("wedges " + p.string() + " --visit 99 --out " +
                                                  (p.parent_path() / "w.json").string()),
                     p);
  expect_no_visit_99(
      rockface::test::run_rockface("wedges " + p.string() + " --visit 99 --axis 0/0 --out " +
                                   (p.parent_path() / "w.json").string()),
      p);
  fs::remove_all(p.parent_path());
}

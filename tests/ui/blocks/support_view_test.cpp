// Issue 44 on the tablet: the Blocks screen's Support view on the
// tunnel-drive sample's project with a classification form and the
// designer's classes: the three proposals side by side, a class chosen on
// the tablet with who decided, why and a change to the class (with its
// reason), stored with the visit, checked with the change beside the class
// unchanged, and read back
// by `rockface support` (a separate process) from the project.
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/support/support_form.h"
#include "tests/ui/drive_project.h"
#include "tests/ui/drive_tablet.h"
#include "ui/app/app_state.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using nlohmann::json;

// Classes by RMR only (every RMR has one), lightest first.
const char* kClasses = R"({
  "format": "rockface-support-classes/1", "tunnel": "Main drive",
  "classes": [
    {"name": "SC1", "round_length_m": 4, "bolts": {"length_m": 3, "spacing_m": 2.5, "capacity_kn": 150},
     "criteria": {"rmr": [60, null]}},
    {"name": "SC2", "round_length_m": 3, "bolts": {"length_m": 4, "spacing_m": 1.5, "capacity_kn": 150},
     "shotcrete_m": 0.1, "shotcrete_shear_mpa": 1.0, "criteria": {"rmr": [40, 60]}},
    {"name": "SC3", "round_length_m": 1.5, "bolts": {"length_m": 6, "spacing_m": 1.0, "capacity_kn": 250},
     "shotcrete_m": 0.2, "shotcrete_shear_mpa": 1.0, "criteria": {"rmr": [null, 40]}}
  ]})";

TEST(SupportView, AClassChosenOnTheTabletIsStoredAndReadBack) {
  const fs::path project = test::drive_project_copy("support");
  storage::RecordId visit = 0;
  {
    storage::ProjectStore store = storage::ProjectStore::open(project);
    visit = *store.latest_visit();
    // A complete form (RMR89 and Q both known).
    rockmass::ClassificationForm f = test::sample_support_form();
    // The joints form no sets to derive it from: the geologist's reading.
    f.orientation = rockmass::OrientationClass::fair;
    store.save_rockmass_form(visit, f);
  }
  const fs::path classes = test::ui_test_dir() / "support-classes.json";
  std::ofstream(classes) << kClasses;
  const fs::path first = test::ui_test_dir() / "support-before.json";
  const test::CliRun stored =
      test::run_rockface("support " + project.string() + " --visit " + std::to_string(visit) +
                         " --classes " + classes.string() + " --out " + first.string());
  ASSERT_EQ(stored.exit_code, 0) << stored.err;
  std::string proposed;
  {
    std::ifstream in(first);
    const json j = json::parse(in);
    ASSERT_TRUE(j.at("classes").at("proposed").is_string()) << j.dump(2);
    proposed = j["classes"]["proposed"].get<std::string>();
  }

  test::DriveTablet tablet(project);
  ui::HeadlessSession& s = tablet.session;
  ui::AppState& app = s.state();
  tablet.show("Blocks", "Support view");
  const auto& v = app.blocks.support;
  ASSERT_TRUE(v.proposals) << v.message;
  // The three proposals side by side, the proposed class named.
  EXPECT_FALSE(v.proposals->from_q.empty());
  EXPECT_FALSE(v.proposals->from_rmr.empty());
  EXPECT_EQ(v.proposals->proposed, proposed);
  EXPECT_EQ(v.proposals->classes.size(), 3u);
  EXPECT_FALSE(v.proposals->decision);
  s.screenshot();

  // A heavier class than proposed: refused until the reason is given.
  const std::string chosen = proposed == "SC3" ? "SC2" : "SC3";
  s.tap(chosen);
  app.blocks.support.by = "A. Geologist";  // as typed in the field
  s.frame();
  EXPECT_THROW(s.tap("Decide"), InputError) << "no reason yet: Decide is disabled";
  app.blocks.support.reason = "water at the face";
  s.frame();
  // A change to the class for this round: refused until it says why.
  s.tap("Add a change");
  ASSERT_EQ(app.blocks.support.changes.size(), 1u);
  // FROM is what the chosen class gives (SC2 1.5 m, SC3 1 m).
  const std::string spacing_from = chosen == "SC3" ? "1 m" : "1.5 m";
  app.blocks.support.changes[0] = {"bolt spacing", spacing_from, "1.2 m", ""};  // as typed
  s.frame();
  EXPECT_THROW(s.tap("Decide"), InputError) << "the change has no reason: Decide is disabled";
  app.blocks.support.changes[0].reason = "wedge W3 below FoS 1.5";
  s.frame();
  s.tap("Decide");
  s.settle();
  ASSERT_TRUE(v.proposals && v.proposals->decision) << v.message;
  EXPECT_EQ(v.proposals->decision->class_name, chosen);
  ASSERT_EQ(v.proposals->decision->changes.size(), 1u);
  EXPECT_EQ(v.proposals->decision->changes[0].to, "1.2 m");
  EXPECT_TRUE(app.blocks.support.changes.empty()) << "the form is cleared once decided";
  // The pattern as decided checked, beside the class unchanged.
  ASSERT_FALSE(v.proposals->decided_check.empty());
  EXPECT_EQ(v.proposals->decided_check[0].rfind(chosen + " as changed: ", 0), 0u)
      << v.proposals->decided_check[0];
  bool unchanged = false;
  for (const auto& c : v.proposals->checks) unchanged = unchanged || c.rfind(chosen + ": ", 0) == 0;
  EXPECT_TRUE(unchanged);
  EXPECT_NE(v.proposals->decision->checks.find("the class unchanged: " + chosen + ": "),
            std::string::npos)
      << v.proposals->decision->checks;
  s.screenshot();

  // Read back by the command line from the project.
  const fs::path after = test::ui_test_dir() / "support-after.json";
  const test::CliRun read = test::run_rockface("support " + project.string() + " --visit " +
                                               std::to_string(visit) + " --out " + after.string());
  ASSERT_EQ(read.exit_code, 0) << read.err;
  std::ifstream in(after);
  const json j = json::parse(in);
  ASSERT_TRUE(j.at("decision").is_object()) << j.dump(2);
  const json& d = j.at("decision");
  EXPECT_EQ(d.at("class"), chosen);
  EXPECT_EQ(d.at("decided_by"), "A. Geologist");
  EXPECT_EQ(d.at("reason"), "water at the face");
  EXPECT_EQ(d.at("proposed"), proposed);
  ASSERT_EQ(d.at("changes").size(), 1u);
  EXPECT_EQ(d["changes"][0].at("what"), "bolt spacing");
  EXPECT_EQ(d["changes"][0].at("from"), spacing_from);
  EXPECT_EQ(d["changes"][0].at("to"), "1.2 m");
  EXPECT_EQ(d["changes"][0].at("reason"), "wedge W3 below FoS 1.5");
  EXPECT_FALSE(d.at("decided_at").get<std::string>().empty());
}

}  // namespace

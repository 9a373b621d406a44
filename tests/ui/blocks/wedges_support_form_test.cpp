// Issue 39: the Wedges view's form for friction and support, typed on the
// keypad: the wedges are recomputed with it, and the supported factors of
// safety shown are those `rockface wedges --friction --bolts --shotcrete`
// gives with the same values (the command line, a separate process, is the
// reference).
#include <cmath>
#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/cli_run.h"
#include "tests/ui/drive_project.h"
#include "tests/ui/drive_tablet.h"
#include "ui/app/app_state.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using nlohmann::json;

void type(ui::HeadlessSession& s, const std::string& field, const std::string& digits) {
  s.tap(field);
  for (char c : digits) s.tap(std::string(1, c));
}

std::size_t column(const ui::WedgeTable& t, const std::string& name) {
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (t.columns[c] == name) return c;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

TEST(WedgesSupportForm, TypedSupportGivesTheFactorsOfSafetyTheCommandLineGives) {
  test::DriveTablet tablet(test::drive_project());
  ui::HeadlessSession& s = tablet.session;
  ui::AppState& app = s.state();
  tablet.find_wedges();
  const auto& w = app.blocks.wedges;
  ASSERT_TRUE(w.table) << w.message;
  const std::size_t fos_col = column(*w.table, "Factor of safety");
  const std::size_t supported_col = column(*w.table, "With support");
  const auto before = *w.table;
  for (const auto& row : before.rows) EXPECT_EQ(row[supported_col], "-");

  s.tap("Friction and support");
  type(s, "Friction", "35");
  type(s, "Bolt length", "3");
  type(s, "Bolt spacing", "1.5");
  // Half the bolts typed: nothing is run until all three are.
  EXPECT_FALSE(app.blocks.wedges.form.problem().empty());
  type(s, "Bolt capacity", "100");
  type(s, "Shotcrete thickness", "50");
  type(s, "Shotcrete shear strength", "1");
  ASSERT_TRUE(app.blocks.wedges.form.problem().empty()) << app.blocks.wedges.form.problem();
  s.tap("Find wedges");
  s.settle();
  ASSERT_TRUE(w.table) << w.message;
  s.screenshot();

  // The same options on the command line: 35 deg, bolts 3 m long, 1.5 m
  // apart, 100 kN; shotcrete 50 mm thick, 1 MPa in shear.
  const fs::path out = test::ui_test_dir() / "drive-wedges-supported.json";
  const test::CliRun r = test::run_rockface(
      "wedges " + test::drive_project().string() +
      " --friction 35 --bolts 3,1.5,100000 --shotcrete 0.05,1000000 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out);
  const json j = json::parse(in);
  ASSERT_EQ(w.table->rows.size(), j.at("wedges").size());
  bool changed = false;
  for (std::size_t k = 0; k < w.table->rows.size(); ++k) {
    const auto& row = w.table->rows[k];
    const json& cli = j["wedges"][k];
    EXPECT_EQ(row[0], cli.at("id"));
    ASSERT_TRUE(cli.contains("fos_supported")) << cli.at("id");
    const std::string shown = row[supported_col];
    if (cli["fos_supported"].is_null() || !cli.contains("mode")) continue;
    const double expected = cli["fos_supported"].get<double>();
    if (shown == "stable") {
      EXPECT_FALSE(std::isfinite(expected)) << row[0];
      continue;
    }
    // Shown to 2 decimals (±0.005), the JSON to 0.001 (±0.0005).
    EXPECT_NEAR(std::strtod(shown.c_str(), nullptr), expected, 0.005 + 0.0005 + 1e-9) << row[0];
    changed = changed || shown != before.rows[k][fos_col];
  }
  EXPECT_TRUE(changed) << "the support shown changes some wedge's factor of safety";
  bool support_line = false;
  for (const auto& line : w.table->lines)
    support_line =
        support_line || line ==
                            "Support: bolts 3.0 m long, 1.5 m apart, 100 kN each; shotcrete 50 mm, "
                            "shear strength 1.0 MPa";
  EXPECT_TRUE(support_line);
}

}  // namespace

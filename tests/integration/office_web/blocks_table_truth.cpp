// The blocks table against the tablet's project (blocks_table_truth.h).
#include "tests/integration/office_web/blocks_table_truth.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

#include "storage/project/project_sqlite.h"

namespace rockface::office_web_test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A block of the visit's latest analysis as the tablet stored it: its
// columns and the report it wrote beside them (storage/report/report_json.cpp).
struct StoredBlock {
  std::string label, mode;
  bool finite = false, removable = false, marginal = false;
  std::optional<double> fos;
  json report;
};

std::vector<StoredBlock> latest_blocks(const fs::path& project, std::int64_t visit_id) {
  storage::sqlite::Connection db(project, storage::sqlite::Connection::Access::read_only);
  storage::sqlite::Statement st(
      db,
      "SELECT label, mode, finite, removable, marginal, fos, report_json FROM block "
      "WHERE analysis_id = (SELECT max(id) FROM analysis WHERE visit_id = ?) ORDER BY id",
      "reading the tablet's blocks");
  st.bind(1, visit_id);
  std::vector<StoredBlock> out;
  while (st.step()) {
    StoredBlock b;
    b.label = st.column_text(0);
    b.mode = st.column_text(1);
    b.finite = st.column_int(2) != 0;
    b.removable = st.column_int(3) != 0;
    b.marginal = st.column_int(4) != 0;
    if (!st.is_null(5)) b.fos = st.column_double(5);
    b.report = json::parse(st.column_text(6));
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace

void expect_blocks_table(const json& rows, const fs::path& project, std::int64_t visit_id,
                         const std::string& name) {
  const auto stored = latest_blocks(project, visit_id);
  ASSERT_FALSE(stored.empty()) << name << ": the visit has no blocks in its tablet";
  EXPECT_EQ(rows.size(), stored.size()) << name << ": " << rows.dump();
  for (const auto& b : stored) {
    const auto row =
        std::find_if(rows.begin(), rows.end(), [&](const json& r) { return r[0] == b.label; });
    ASSERT_NE(row, rows.end()) << name << ": block " << b.label << " is not in the table";
    ASSERT_EQ(row->size(), 9u) << name << ": " << row->dump();
    const std::string at = name + ": block " + b.label + " ";
    const std::string verdict = std::string(!b.finite     ? "infinite"
                                            : b.removable ? "removable"
                                                          : "finite, keyed") +
                                (b.marginal ? "?" : "");
    EXPECT_EQ((*row)[1], verdict) << at << "verdict";
    // The margin is shown to a tenth of a degree: half of it is the rounding.
    const std::string margin = (*row)[2];
    double shown_margin = 0;
    ASSERT_EQ(std::sscanf(margin.c_str(), "%lf", &shown_margin), 1) << at << margin;
    EXPECT_EQ(margin.substr(margin.size() - std::strlen("°")), "°") << at << "margin's unit";
    EXPECT_NEAR(shown_margin, b.report.at("margin_deg").get<double>(), 0.05 + 1e-9)
        << at << "margin";
    std::string mode = b.mode.empty() ? "none" : b.mode;
    if (mode == "sliding" && b.report.contains("mode") && !b.report["mode"]["planes"].empty()) {
      mode = "sliding on ";
      for (std::size_t i = 0; i < b.report["mode"]["planes"].size(); ++i)
        mode += (i ? "+" : "") + b.report["mode"]["planes"][i].get<std::string>();
    }
    EXPECT_EQ((*row)[3], mode) << at << "mode";
    const std::string fos = (*row)[4];
    if (!b.fos) {
      EXPECT_EQ(fos, "–") << at << "FoS of a block without one";
    } else {
      double shown_fos = 0;
      ASSERT_EQ(std::sscanf(fos.c_str(), "%lf", &shown_fos), 1) << at << fos;
      // Two decimals: half a hundredth is the rounding.
      EXPECT_NEAR(shown_fos, *b.fos, 0.005 + 1e-9) << at << "FoS";
    }
    const std::string volume = (*row)[5];
    if (!b.report.contains("volume")) {
      EXPECT_EQ(volume, "–") << at << "volume of a block without one";
    } else {
      const double truth_volume = b.report["volume"].get<double>();
      double shown_volume = 0;
      ASSERT_EQ(std::sscanf(volume.c_str(), "%lf", &shown_volume), 1) << at << volume;
      EXPECT_NE(volume.find(" m³"), std::string::npos) << at << "volume's unit: " << volume;
      // Three significant digits: half a unit of the third is the rounding.
      EXPECT_NEAR(shown_volume, truth_volume,
                  0.5 * std::pow(10.0, std::floor(std::log10(truth_volume)) - 2) + 1e-12)
          << at << "volume";
    }
    const std::string motion =
        b.report.contains("dynamics") ? b.report["dynamics"].value("outcome", "") : "–";
    EXPECT_EQ((*row)[8], motion) << at << "motion after failure";
  }
}

}  // namespace rockface::office_web_test

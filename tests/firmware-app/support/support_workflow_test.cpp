// `rockface support` on a sample project: the sample tunnel, a visit placed
// at chainage 105 with three measured sets (the wedges' sample planes) and
// a classification form. The designer's classes file stored and matched,
// the proposed class checked on the visit's wedges, a decision refused
// without a reason and stored with one, the field report's section, the
// drive's support CSV; a form with Q's lines open proposes nothing from Q
// and names them; a classes file with overlapping ranges is refused by name
// and nothing is stored.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/number_format.h"
#include "firmware-app/support/report_support.h"
#include "firmware-app/support/visit_support.h"
#include "firmware-app/wedges/wedges_workflow.h"
#include "storage/field_report/field_report.h"
#include "storage/field_report/field_report_pdf.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_files.h"
#include "tests/support/run_in_dir.h"
#include "tests/support/support_form.h"
#include "tests/support/temp_folders.h"
#include "tests/support/test_paths.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kSamples = fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples";

fs::path temp_dir(const std::string& name) {
  return test::fresh_test_dir("rockface-support-" + name);
}

int run(const std::string& args, const fs::path& dir) {
  return test::run_rockface_in(args, dir);
}

std::string read(const fs::path& f) {
  return test::read_text(f);
}

// Classes by RMR only (every RMR has one), lightest first, with pattern
// bolts long enough for a 1 m wedge and shotcrete.
const char* kRmrClasses = R"({
  "format": "rockface-support-classes/1", "tunnel": "Main drive",
  "classes": [
    {"name": "SC1", "round_length_m": 4, "bolts": {"length_m": 3, "spacing_m": 2.5, "capacity_kn": 150},
     "criteria": {"rmr": [60, null]}},
    {"name": "SC2", "round_length_m": 3, "bolts": {"length_m": 4, "spacing_m": 1.5, "capacity_kn": 150},
     "shotcrete_m": 0.1, "shotcrete_shear_mpa": 1.0, "criteria": {"rmr": [40, 60]}},
    {"name": "SC3", "round_length_m": 1.5, "bolts": {"length_m": 6, "spacing_m": 1.0, "capacity_kn": 250},
     "shotcrete_m": 0.2, "shotcrete_shear_mpa": 1.0, "steel_sets": "TH 29 at 1.5 m",
     "face": {"bolts": {"length_m": 12, "spacing_m": 1.5, "capacity_kn": 200}},
     "criteria": {"rmr": [null, 40]}}
  ]})";

// A project with the sample tunnel and one visit at chainage 105: three
// sets of five traces each (the wedges' sample planes, a few degrees of
// scatter) spread over a 6 x 4 m window, and the form.
storage::RecordId make_project(const fs::path& project, bool q_complete) {
  storage::ProjectInfo info;
  info.name = "drive";
  info.datum = {512340.0, 5211870.0, 410.0};
  storage::ProjectStore store = storage::ProjectStore::create(project, info);
  storage::TunnelRecord tunnel;
  tunnel.name = "Main drive";
  const auto table = storage::read_alignment_csv(kSamples / "tunnel-drive.alignment.csv");
  tunnel.stations = table.stations;
  tunnel.radii = table.radii;
  tunnel.polyline = table.polyline;
  tunnel.profile = storage::read_profile_file(kSamples / "tunnel-drive.profile.json");
  store.save_tunnel(tunnel);
  const storage::RecordId visit = store.begin_visit("face at 105");
  const std::array<double, 5> ddip{-2, -1, 0, 1, 2}, ddir{1, -2, 2, -1, 0};
  std::vector<storage::Measurement> traces;
  for (auto [dip, dipdir] : {std::pair{65.0, 20.0}, std::pair{60.0, 145.0}, std::pair{55.0, 260.0}})
    for (std::size_t i = 0; i < ddip.size(); ++i) {
      storage::Measurement m;
      m.visit_id = visit;
      m.kind = storage::Measurement::Kind::trace;
      m.label = "T" + std::to_string(traces.size() + 1);
      const double x = 1.2 * static_cast<double>(i), z = 0.25 * static_cast<double>(traces.size());
      m.points = {{x, 35, z}, {x + 0.8, 35, z + 0.6}};
      m.dip_deg = dip + ddip[i];
      m.dipdir_deg = dipdir + ddir[i];
      traces.push_back(m);
    }
  store.save_measurements(visit, traces);
  storage::VisitPlacement p;
  p.visit_id = visit;
  p.chainage = 105;
  p.note = "typed";
  store.save_visit_placement(p);
  rockmass::ClassificationForm f = test::sample_support_form();
  if (!q_complete) f.jr.reset();  // Q's Jr left open
  store.save_rockmass_form(visit, f);
  return visit;
}

TEST(SupportVerb, ClassesProposedCheckedDecidedReportedAndAlongTheDrive) {
  const fs::path dir = temp_dir("decide");
  const fs::path project = dir / "drive.rockface";
  const storage::RecordId visit = make_project(project, true);
  std::ofstream(dir / "classes.json") << kRmrClasses;
  const std::string base = "support " + project.string() + " --visit " + std::to_string(visit);
  ASSERT_EQ(run(base + " --classes " + (dir / "classes.json").string() + " --out " +
                    (dir / "s.json").string() + " --png " + (dir / "s.png").string(),
                dir),
            0)
      << read(dir / "err.txt");
  const json j = json::parse(read(dir / "s.json"));
  EXPECT_EQ(j["format"], "rockface-support/1");
  EXPECT_EQ(j["chainage"], "105.00 m");

  // The library's answer for the same visit (the field report's path).
  VisitSupport s;
  {
    storage::ProjectStore store = storage::ProjectStore::open(project, {});
    s = visit_support(store, visit);
  }
  ASSERT_TRUE(s.figures.rmr) << j.dump(2);
  ASSERT_TRUE(s.figures.q);
  // The class proposed is the one whose RMR range holds the visit's RMR.
  const double rmr = *s.figures.rmr;
  const std::string expected = rmr >= 60 ? "SC1" : rmr >= 40 ? "SC2" : "SC3";
  ASSERT_FALSE(j["classes"].is_null());
  EXPECT_EQ(j["classes"]["proposed"], expected) << "RMR " << rmr;
  // The Q chart at the form's ESR and the tunnel's span: the library's category.
  ASSERT_TRUE(s.q_support);
  EXPECT_EQ(j["q_chart"]["category"], s.q_support->category.number);
  EXPECT_EQ(j["q_chart"]["bolt_length"],
            format_fixed(2 + 0.15 * *s.span_m / 1.3, 2, " m"));  // L = 2 + 0.15 B / ESR
  EXPECT_FALSE(j["bieniawski"].contains("none"));
  // The proposed class checked on every wedge that can move (the visit's
  // wedge analysis: three sets around the sample profile).
  ASSERT_EQ(j["checks"].size(), 1u);
  EXPECT_EQ(j["checks"][0]["class"], expected);
  std::string why;
  storage::ProjectStore read_store = storage::ProjectStore::open(project, {});
  const auto wedges = project_visit_wedges(read_store, visit, &why);
  ASSERT_TRUE(wedges) << why;
  std::size_t moving = 0;
  for (const auto& w : wedges->analysis.wedges) moving += w.mode ? 1 : 0;
  ASSERT_GT(moving, 0u);
  EXPECT_EQ(j["checks"][0]["wedges"].size(), moving);
  for (const auto& w : j["checks"][0]["wedges"]) {
    if (w["below_target"].get<bool>()) {
      EXPECT_FALSE(w["fixes"].empty()) << w.dump();
    }
  }
  EXPECT_TRUE(j["decision"].is_null());
  EXPECT_GT(fs::file_size(dir / "s.png"), 10000u);
  ASSERT_TRUE(read_store.load_support_classes());

  // A class other than the proposed one without a reason: refused, nothing stored.
  const std::string other = expected == "SC3" ? "SC2" : "SC3";
  EXPECT_EQ(run(base + " --decide " + other + " --by Ana --out " + (dir / "d.json").string(), dir),
            2);
  EXPECT_NE(read(dir / "err.txt").find("--reason"), std::string::npos) << read(dir / "err.txt");
  EXPECT_FALSE(read_store.load_support_decision(visit));
  // With one: stored with who and when, and both classes checked.
  ASSERT_EQ(run(base + " --decide " + other + " --by Ana --reason 'water at the left wall' --out " +
                    (dir / "d.json").string(),
                dir),
            0)
      << read(dir / "err.txt");
  const auto d = read_store.load_support_decision(visit);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->class_name, other);
  EXPECT_EQ(d->proposed, expected);
  EXPECT_EQ(d->decided_by, "Ana");
  EXPECT_EQ(d->reason, "water at the left wall");
  EXPECT_FALSE(d->decided_at.empty());
  EXPECT_NE(d->checks.find(other + ":"), std::string::npos) << d->checks;
  const json dj = json::parse(read(dir / "d.json"));
  EXPECT_EQ(dj["decision"]["class"], other);
  EXPECT_EQ(dj["checks"].size(), 2u);

  // The field report's section, printed.
  storage::FieldReport report = storage::collect_field_report(read_store, visit);
  add_support_to_report(read_store, report);
  ASSERT_TRUE(report.support);
  EXPECT_FALSE(report.support->chart.empty());
  EXPECT_EQ(report.support->decision.front(), "class " + other + " (proposed: " + expected + ")");
  EXPECT_FALSE(report.support->rows.empty());
  storage::write_field_report_pdf(report, dir / "report.pdf");
  EXPECT_GT(fs::file_size(dir / "report.pdf"), 20000u);

  // The class with changes of its own for this round, each with its
  // reason: stored with the visit, in the JSON, the terminal's lines and
  // the field report.
  EXPECT_EQ(run(base + " --change 'bolt spacing: 1.5 m -> 1.2 m: wedge W3' --out " +
                    (dir / "c.json").string(),
                dir),
            2)
      << "a change without --decide";
  EXPECT_NE(read(dir / "err.txt").find("--change"), std::string::npos) << read(dir / "err.txt");
  EXPECT_EQ(run(base + " --decide " + other + " --by Ana --reason 'water at the left wall'" +
                    " --change 'bolt spacing: 1.5 m -> 1.2 m' --out " + (dir / "c.json").string(),
                dir),
            2)
      << "a change without its reason";
  EXPECT_NE(read(dir / "err.txt").find("REASON"), std::string::npos) << read(dir / "err.txt");
  EXPECT_EQ(read_store.list_support_decisions(visit).size(), 1u) << "nothing stored";
  ASSERT_EQ(run(base + " --decide " + other + " --by Ana --reason 'water at the left wall'" +
                    " --change 'bolt spacing: 1.5 m -> 1.2 m: wedge W3 below FoS 1.5'" +
                    " --change 'shotcrete: 50 mm -> 100 mm: water: the lining bonds badly' --out " +
                    (dir / "c.json").string(),
                dir),
            0)
      << read(dir / "err.txt");
  const auto changed = read_store.load_support_decision(visit);
  ASSERT_TRUE(changed);
  ASSERT_EQ(changed->changes.size(), 2u);
  EXPECT_EQ(changed->changes[0].what, "bolt spacing");
  EXPECT_EQ(changed->changes[0].from, "1.5 m");
  EXPECT_EQ(changed->changes[0].to, "1.2 m");
  EXPECT_EQ(changed->changes[0].reason, "wedge W3 below FoS 1.5");
  EXPECT_EQ(changed->changes[1].reason, "water: the lining bonds badly");  // colons kept
  EXPECT_EQ(changed->reason, "water at the left wall");  // the reason stays the class's
  const json cj = json::parse(read(dir / "c.json"));
  ASSERT_EQ(cj["decision"]["changes"].size(), 2u);
  EXPECT_EQ(cj["decision"]["changes"][1]["what"], "shotcrete");
  EXPECT_EQ(cj["decision"]["changes"][1]["from"], "50 mm");
  EXPECT_EQ(cj["decision"]["changes"][1]["to"], "100 mm");
  EXPECT_NE(read(dir / "out.txt")
                .find("change: bolt spacing 1.5 m -> 1.2 m (wedge W3 below FoS "
                      "1.5)"),
            std::string::npos)
      << read(dir / "out.txt");
  storage::FieldReport changed_report = storage::collect_field_report(read_store, visit);
  add_support_to_report(read_store, changed_report);
  ASSERT_TRUE(changed_report.support);
  const auto& lines = changed_report.support->decision;
  EXPECT_NE(std::find(lines.begin(), lines.end(),
                      "change: shotcrete 50 mm -> 100 mm (water: the lining bonds badly)"),
            lines.end());

  // Along the drive: the round's class against its chainage.
  ASSERT_EQ(run("drive " + project.string() + " --out " + (dir / "drive.png").string() +
                    " --support-csv " + (dir / "support.csv").string(),
                dir),
            0)
      << read(dir / "err.txt");
  const std::string csv = read(dir / "support.csv");
  EXPECT_NE(csv.find("105.00," + std::to_string(visit) + ","), std::string::npos) << csv;
  EXPECT_NE(csv.find("," + expected + "," + other + ",Ana,"), std::string::npos) << csv;
}

// A decision stored before changes had a field of their own (its JSON
// without "changes", the changes in its reason): the project opens, the
// verb and the field report read it with no changes, and a new decision
// with changes is stored beside it.
TEST(SupportVerb, ADecisionWithoutTheChangesFieldIsReadAsBefore) {
  const fs::path dir = temp_dir("old");
  const fs::path project = dir / "drive.rockface";
  const storage::RecordId visit = make_project(project, true);
  std::ofstream(dir / "classes.json") << kRmrClasses;
  const std::string base = "support " + project.string() + " --visit " + std::to_string(visit);
  ASSERT_EQ(run(base + " --classes " + (dir / "classes.json").string() + " --out " +
                    (dir / "s.json").string(),
                dir),
            0)
      << read(dir / "err.txt");
  {
    storage::sqlite::Connection db(project, storage::sqlite::Connection::Access::read_write);
    db.exec(
        "INSERT INTO support_decision (visit_id, class_name, decision_json, decided_at) "
        "VALUES (" +
            std::to_string(visit) +
            ", 'SC2', '{\"class\": \"SC2\", \"proposed\": \"SC2\", \"reason\": \"bolt "
            "spacing 1.5 -> 1.2 m for W3\", \"decided_by\": \"Ana\", \"decided_at\": "
            "\"2026-11-20T08:00:00.000Z\", \"checks\": \"\"}', '2026-11-20T08:00:00.000Z')",
        "test");
  }
  ASSERT_EQ(run(base + " --out " + (dir / "r.json").string(), dir), 0) << read(dir / "err.txt");
  const json j = json::parse(read(dir / "r.json"));
  ASSERT_TRUE(j["decision"].is_object()) << j.dump(2);
  EXPECT_EQ(j["decision"]["reason"], "bolt spacing 1.5 -> 1.2 m for W3");
  EXPECT_TRUE(j["decision"]["changes"].empty());
  storage::ProjectStore store = storage::ProjectStore::open(project, {});
  storage::FieldReport report = storage::collect_field_report(store, visit);
  add_support_to_report(store, report);
  ASSERT_TRUE(report.support);
  for (const auto& line : report.support->decision)
    EXPECT_EQ(line.rfind("change", 0), std::string::npos) << line;
  ASSERT_EQ(run(base + " --decide SC2 --by Ana --reason 'as before'" +
                    " --change 'bolt spacing: 1.5 m -> 1.2 m: wedge W3' --out " +
                    (dir / "d.json").string(),
                dir),
            0)
      << read(dir / "err.txt");
  const auto all = store.list_support_decisions(visit);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_TRUE(all[0].changes.empty());
  ASSERT_EQ(all[1].changes.size(), 1u);
  EXPECT_EQ(all[1].changes[0].to, "1.2 m");
}

TEST(SupportVerb, OpenQLinesProposeNothingFromQAndAreNamed) {
  const fs::path dir = temp_dir("open");
  const fs::path project = dir / "drive.rockface";
  const storage::RecordId visit = make_project(project, false);  // Jr not entered
  std::ofstream(dir / "q.json") << R"({"classes": [
    {"name": "Q1", "round_length_m": 3, "criteria": {"q": [1, null]}},
    {"name": "Q2", "round_length_m": 1.5, "criteria": {"q": [null, 1]}}]})";
  ASSERT_EQ(
      run("support " + project.string() + " --visit " + std::to_string(visit) + " --classes " +
              (dir / "q.json").string() + " --out " + (dir / "s.json").string(),
          dir),
      0)
      << read(dir / "err.txt");
  const json j = json::parse(read(dir / "s.json"));
  EXPECT_TRUE(j["rock_mass"]["q"].is_null());
  EXPECT_EQ(j["rock_mass"]["q_missing"], json({"Jr"}));
  EXPECT_NE(j["q_chart"]["none"].get<std::string>().find("Jr"), std::string::npos);
  EXPECT_TRUE(j["classes"]["proposed"].is_null());
  bool named = false;
  for (const auto& n : j["classes"]["notes"])
    named |= n.get<std::string>().find("Jr") != std::string::npos;
  EXPECT_TRUE(named) << j["classes"].dump(2);
  EXPECT_TRUE(j["checks"].empty());
}

TEST(SupportVerb, OverlappingClassesAreRefusedByNameAndNothingIsStored) {
  const fs::path dir = temp_dir("refused");
  const fs::path project = dir / "drive.rockface";
  const storage::RecordId visit = make_project(project, true);
  std::string text = kRmrClasses;
  text.replace(text.find("[40, 60]"), 8, "[40, 65]");
  std::ofstream(dir / "bad.json") << text;
  EXPECT_EQ(
      run("support " + project.string() + " --visit " + std::to_string(visit) + " --classes " +
              (dir / "bad.json").string() + " --out " + (dir / "s.json").string(),
          dir),
      2);
  const std::string err = read(dir / "err.txt");
  EXPECT_NE(err.find("bad.json: classes[1].criteria.rmr"), std::string::npos) << err;
  EXPECT_NE(err.find("SC2"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "s.json"));
  storage::ProjectStore store = storage::ProjectStore::open(project, {});
  EXPECT_FALSE(store.load_support_classes());
}

}  // namespace
}  // namespace rockface::app

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
#include "firmware-app/support/support_json.h"
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
  // the field report. Each FROM is what the chosen class gives (SC2: bolts
  // at 1.5 m, 100 mm of shotcrete; SC3: 1 m, 200 mm).
  const std::string spacing_from = other == "SC3" ? "1 m" : "1.5 m";
  const std::string shotcrete_from = other == "SC3" ? "200 mm" : "100 mm";
  const std::string shotcrete_to = other == "SC3" ? "250 mm" : "150 mm";
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
  ASSERT_EQ(
      run(base + " --decide " + other + " --by Ana --reason 'water at the left wall'" +
              " --change 'bolt spacing: " + spacing_from + " -> 1.2 m: wedge W3 below FoS 1.5'" +
              " --change 'shotcrete: " + shotcrete_from + " -> " + shotcrete_to +
              ": water: the lining bonds badly' --out " + (dir / "c.json").string(),
          dir),
      0)
      << read(dir / "err.txt");
  const auto changed = read_store.load_support_decision(visit);
  ASSERT_TRUE(changed);
  ASSERT_EQ(changed->changes.size(), 2u);
  EXPECT_EQ(changed->changes[0].what, "bolt spacing");
  EXPECT_EQ(changed->changes[0].from, spacing_from);
  EXPECT_EQ(changed->changes[0].to, "1.2 m");
  EXPECT_EQ(changed->changes[0].reason, "wedge W3 below FoS 1.5");
  EXPECT_EQ(changed->changes[1].reason, "water: the lining bonds badly");  // colons kept
  EXPECT_EQ(changed->reason, "water at the left wall");  // the reason stays the class's
  const json cj = json::parse(read(dir / "c.json"));
  ASSERT_EQ(cj["decision"]["changes"].size(), 2u);
  EXPECT_EQ(cj["decision"]["changes"][1]["what"], "shotcrete");
  EXPECT_EQ(cj["decision"]["changes"][1]["from"], shotcrete_from);
  EXPECT_EQ(cj["decision"]["changes"][1]["to"], shotcrete_to);
  EXPECT_NE(
      read(dir / "out.txt")
          .find("change: bolt spacing " + spacing_from + " -> 1.2 m (wedge W3 below FoS 1.5)"),
      std::string::npos)
      << read(dir / "out.txt");
  // The pattern as decided checked beside the class unchanged: in the
  // JSON, the terminal's lines and the decision's record.
  EXPECT_EQ(cj["decided_check"]["class"], other + " as changed") << cj.dump(2);
  EXPECT_EQ(cj["checks"].back()["class"], other);
  EXPECT_NE(read(dir / "out.txt").find("check " + other + " as changed: "), std::string::npos)
      << read(dir / "out.txt");
  EXPECT_EQ(changed->checks.rfind(other + " as changed: ", 0), 0u) << changed->checks;
  EXPECT_NE(changed->checks.find("; the class unchanged: " + other + ": "), std::string::npos)
      << changed->checks;
  storage::FieldReport changed_report = storage::collect_field_report(read_store, visit);
  add_support_to_report(read_store, changed_report);
  ASSERT_TRUE(changed_report.support);
  const auto& lines = changed_report.support->decision;
  EXPECT_NE(std::find(lines.begin(), lines.end(),
                      "change: shotcrete " + shotcrete_from + " -> " + shotcrete_to +
                          " (water: the lining bonds badly)"),
            lines.end());
  // The report's table is the pattern as decided's.
  EXPECT_EQ(changed_report.support->rows_pattern, other + " as changed");

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

// A decision that shortens the class's 4 m bolts to 0.5 m: the wedges are
// checked again with the changed pattern, beside the class unchanged. Each
// wedge's bolts reach past its apex exactly when their length exceeds the
// apex's depth (the class's 4 m, the decision's 0.5 m; the face's wedges
// are the face bolts', which the change leaves); the decision's
// record, read again from the project, is checked with its changes. A WHAT
// the check cannot apply is refused by name and nothing is stored; a stored
// decision whose change no longer applies is checked as its class and said.
TEST(SupportVerb, ADecisionsChangesAreCheckedBesideTheClassUnchanged) {
  const fs::path dir = temp_dir("changed");
  const fs::path project = dir / "drive.rockface";
  const storage::RecordId visit = make_project(project, true);
  std::ofstream(dir / "classes.json") << kRmrClasses;
  const std::string base = "support " + project.string() + " --visit " + std::to_string(visit);
  ASSERT_EQ(run(base + " --classes " + (dir / "classes.json").string() + " --decide SC2 --by Ana" +
                    " --reason 'the designer asked for SC2' --change 'bolt length: 4 m -> 0.5 m:" +
                    " the rig is down' --out " + (dir / "d.json").string(),
                dir),
            0)
      << read(dir / "err.txt");
  storage::ProjectStore store = storage::ProjectStore::open(project, {});
  const VisitSupport s = visit_support(store, visit);  // the stored decision, checked again
  ASSERT_TRUE(s.decision);
  ASSERT_TRUE(s.decided_check) << "the stored decision's changes applied";
  EXPECT_EQ(s.decided_check->class_name, "SC2 as changed");
  const analysis::SupportCheck* unchanged = nullptr;
  for (const auto& c : s.checks)
    if (c.class_name == "SC2") unchanged = &c;
  ASSERT_TRUE(unchanged);
  ASSERT_EQ(s.decided_check->wedges.size(), unchanged->wedges.size());
  ASSERT_FALSE(unchanged->wedges.empty());
  int differ = 0;
  for (std::size_t i = 0; i < unchanged->wedges.size(); ++i) {
    const auto& before = unchanged->wedges[i];
    const auto& after = s.decided_check->wedges[i];
    EXPECT_EQ(after.id, before.id);
    if (after.place == "face") {  // held by the face bolts (SC2 has none), not changed
      EXPECT_EQ(after.bolts_reach_past_apex, before.bolts_reach_past_apex) << after.id;
      continue;
    }
    EXPECT_EQ(before.bolts_reach_past_apex, 4.0 > before.apex_depth_m) << before.id;
    EXPECT_EQ(after.bolts_reach_past_apex, 0.5 > after.apex_depth_m) << after.id;
    EXPECT_LE(after.bolts_anchored, before.bolts_anchored) << after.id;
    differ += after.bolts_reach_past_apex != before.bolts_reach_past_apex ? 1 : 0;
  }
  EXPECT_GT(differ, 0) << "no wedge's apex lies between 0.5 m and 4 m deep";
  const json j = json::parse(read(dir / "d.json"));
  EXPECT_EQ(j["decided_check"]["class"], "SC2 as changed");
  EXPECT_EQ(j["decided_check"]["wedges"].size(), unchanged->wedges.size());
  EXPECT_EQ(s.decision->checks, decision_checks_words(s)) << "the record as checked now";
  // The field report: both checks, the table under the pattern as decided.
  storage::FieldReport report = storage::collect_field_report(store, visit);
  add_support_to_report(store, report);
  ASSERT_TRUE(report.support);
  const auto& checks = report.support->checks;
  EXPECT_NE(std::find(checks.begin(), checks.end(), checks_words(*unchanged)), checks.end());
  EXPECT_NE(std::find(checks.begin(), checks.end(), checks_words(*s.decided_check)), checks.end());
  EXPECT_EQ(report.support->rows_pattern, "SC2 as changed");

  // Refused by name, nothing stored: a WHAT the check cannot apply, a unit
  // of another quantity, a FROM the class does not give.
  const std::size_t stored = store.list_support_decisions(visit).size();
  for (const std::string& change :
       {std::string("bolt pattern: 4 m -> 6 m: W2"), std::string("bolt length: 4 m -> 150 kN: W2"),
        std::string("bolt length: 3 m -> 6 m: W2")}) {
    EXPECT_EQ(run(base + " --decide SC2 --by Ana --reason x --change '" + change + "' --out " +
                      (dir / "r.json").string(),
                  dir),
              2)
        << change;
    const std::string err = read(dir / "err.txt");
    EXPECT_NE(err.find("--change: change 1 (\"" + change.substr(0, change.find(':')) + "\")"),
              std::string::npos)
        << err;
  }
  EXPECT_EQ(store.list_support_decisions(visit).size(), stored);

  // A decision stored with a change the check cannot apply (made before
  // changes were checked): read as before, checked as its class, said.
  {
    storage::sqlite::Connection db(project, storage::sqlite::Connection::Access::read_write);
    db.exec(
        "INSERT INTO support_decision (visit_id, class_name, decision_json, decided_at) "
        "VALUES (" +
            std::to_string(visit) +
            ", 'SC2', '{\"class\": \"SC2\", \"proposed\": \"SC2\", \"changes\": "
            "[{\"what\": \"rock bolts\", \"from\": \"4\", \"to\": \"5\", \"reason\": "
            "\"W3\"}], \"reason\": \"\", \"decided_by\": \"Ana\", \"decided_at\": "
            "\"2026-11-29T08:00:00.000Z\", \"checks\": \"\"}', '2026-11-29T08:00:00.000Z')",
        "test");
  }
  storage::ProjectStore again = storage::ProjectStore::open(project, {});
  const VisitSupport old = visit_support(again, visit);
  ASSERT_TRUE(old.decision);
  ASSERT_EQ(old.decision->changes.size(), 1u);
  EXPECT_FALSE(old.decided_check);
  bool said = false;
  for (const auto& n : old.notes)
    said = said || n.find("changes are not applied to its check") != std::string::npos;
  EXPECT_TRUE(said);
}

// The Q chart's proposal with the sprayed concrete's energy absorption
// class of the 2015 legend (category 5 at Q 0.6, De 10: E700), in the JSON
// and the terminal's line (the field report prints the same words); a
// category without one (3 at Q 6) gives null and says none.
TEST(SupportVerb, TheQProposalGivesTheSprayedConcretesEnergyClass) {
  VisitSupport s;
  s.q_support = rockmass::q_support({0.6, 10.0, 1.0});
  ASSERT_EQ(s.q_support->category.number, 5);
  const json j = support_json(s);
  EXPECT_EQ(j["q_chart"]["energy_absorption"], "E700");
  EXPECT_EQ(j["q_chart"]["energy_absorption_j"], 700);
  EXPECT_NE(j["q_chart"]["words"].get<std::string>().find("energy absorption E700 (700 J"),
            std::string::npos)
      << j["q_chart"]["words"];
  const auto lines = support_summary(s);
  ASSERT_GE(lines.size(), 2u);
  EXPECT_NE(lines[1].find("E700"), std::string::npos) << lines[1];
  s.q_support = rockmass::q_support({6.0, 10.0, 1.0});
  ASSERT_EQ(s.q_support->category.number, 3);
  const json none = support_json(s);
  EXPECT_TRUE(none["q_chart"]["energy_absorption"].is_null());
  EXPECT_EQ(none["q_chart"]["words"].get<std::string>().find("energy absorption"),
            std::string::npos);
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

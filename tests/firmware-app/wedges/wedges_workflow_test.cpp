// `rockface wedges` end to end: the sample scene (horseshoe, three sets,
// water, pattern bolts and shotcrete), a project visit whose sets are
// measured planes, a scene that asks for nothing but the wedges, and bad
// input refused naming the field.
#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/progress.h"
#include "core/geometry/orientation.h"
#include "firmware-app/services/ui_services.h"
#include "firmware-app/wedges/report_wedges.h"
#include "firmware-app/wedges/wedge_input.h"
#include "firmware-app/wedges/wedges_json.h"
#include "firmware-app/wedges/wedges_workflow.h"
#include "storage/field_report/field_report.h"
#include "storage/field_report/field_report_pdf.h"
#include "storage/project/project_store.h"
#include "storage/scene/scene.h"
#include "storage/tunnel/tunnel_files.h"
#include "tests/support/run_in_dir.h"
#include "tests/support/temp_folders.h"
#include "tests/support/test_paths.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path temp_dir(const std::string& name) {
  return test::fresh_test_dir("rockface-wedges-" + name);
}

// `rockface wedges ARGS`.
int run(const std::string& args, const fs::path& dir) {
  return test::run_rockface_in("wedges " + args, dir);
}

std::string read(const fs::path& f) {
  return test::read_text(f);
}

json read_json(const fs::path& f) {
  return json::parse(read(f));
}

const fs::path kSamples = fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples";

TEST(WedgesVerb, SampleSceneEndToEnd) {
  const fs::path dir = temp_dir("scene");
  ASSERT_EQ(run((kSamples / "tunnel-wedges.scene.json").string() + " --out " +
                    (dir / "w.json").string() + " --png",
                dir),
            0)
      << read(dir / "err.txt");
  const json j = read_json(dir / "w.json");
  EXPECT_EQ(j["format"], "rockface-wedges/1");
  EXPECT_EQ(j["effects_simulated"], json({"gravity", "water", "bolts", "shotcrete"}));
  ASSERT_GE(j["wedges"].size(), 3u);
  // The same as the workflow's own numbers, rounded as the file rounds.
  WedgesRequest q;
  q.input = (kSamples / "tunnel-wedges.scene.json").string();
  const WedgesResult r = wedges_from_input(q);
  ASSERT_EQ(r.analysis.wedges.size(), j["wedges"].size());
  bool roof = false;
  for (std::size_t i = 0; i < j["wedges"].size(); ++i) {
    const json& w = j["wedges"][i];
    const tunnel::Wedge& x = r.analysis.wedges[i];
    EXPECT_EQ(w["id"], x.id);
    EXPECT_EQ(w["code"].get<std::string>().size(), 3u);
    // The file keeps 1e-4 m^3.
    EXPECT_NEAR(w["volume_m3"].get<double>(), x.mass.volume, 0.51e-4);
    EXPECT_GT(w["apex_height_m"].get<double>(), 0);
    EXPECT_GT(w["face_area_m2"].get<double>(), 0);
    EXPECT_GT(w["face_perimeter_m"].get<double>(), 0);
    EXPECT_TRUE(w.contains("margin_deg"));
    // The trace-length limit of 6 m holds on every wedge (the file keeps mm).
    for (const auto& [id, len] : w["trace_lengths_m"].items()) EXPECT_LE(len.get<double>(), 6.0005);
    if (w["place"] == "roof") {
      roof = true;
      EXPECT_TRUE(w.contains("fos_supported"));
      EXPECT_GT(w["bolts"]["anchored"].get<int>(), 0);
    }
  }
  EXPECT_TRUE(roof);
  EXPECT_GT(fs::file_size(dir / "w.png"), 20000u);
  const std::string out = read(dir / "out.txt");
  EXPECT_NE(out.find("effects simulated: gravity, water pressure, bolts, shotcrete"),
            std::string::npos);
}

TEST(WedgesVerb, NothingComputedThatTheSceneDidNotAskFor) {
  const fs::path dir = temp_dir("bare");
  std::ofstream(dir / "bare.scene.json") << R"({
    "format": "rockface-scene/1",
    "joints": [ { "id": "A", "dip": 60, "dipdir": 10, "friction": 30 },
                { "id": "B", "dip": 60, "dipdir": 130, "friction": 30 },
                { "id": "C", "dip": 60, "dipdir": 250, "friction": 30 } ],
    "wedges": { "profile": { "shape": "circle", "radius": 3 }, "axis": { "trend": 0, "plunge": 0 } }
  })";
  ASSERT_EQ(run((dir / "bare.scene.json").string() + " --out " + (dir / "w.json").string(), dir), 0)
      << read(dir / "err.txt");
  const json j = read_json(dir / "w.json");
  EXPECT_EQ(j["effects_simulated"], json({"gravity"}));
  ASSERT_FALSE(j["wedges"].empty());
  for (const auto& w : j["wedges"]) {
    EXPECT_FALSE(w.contains("fos_supported"));
    EXPECT_FALSE(w.contains("bolts"));
    EXPECT_FALSE(w.contains("shotcrete_force_n"));
    EXPECT_EQ(w["effects_used"], json({"gravity"}));
  }
  EXPECT_FALSE(fs::exists(dir / "w.png"));  // no --png, no picture
}

TEST(WedgesVerb, BadInputIsRefusedNamingTheField) {
  const fs::path dir = temp_dir("bad");
  std::ofstream(dir / "two.scene.json") << R"({
    "format": "rockface-scene/1",
    "joints": [ { "id": "A", "dip": 60, "dipdir": 10 }, { "id": "B", "dip": 60, "dipdir": 130 } ],
    "wedges": { "profile": { "shape": "circle", "radius": 3 }, "axis": { "trend": 0, "plunge": 0 } }
  })";
  EXPECT_EQ(run((dir / "two.scene.json").string() + " --out " + (dir / "w.json").string(), dir), 2);
  EXPECT_NE(read(dir / "err.txt").find("joints"), std::string::npos) << read(dir / "err.txt");
  EXPECT_NE(read(dir / "err.txt").find("three"), std::string::npos);
  std::ofstream(dir / "flat.scene.json") << R"({
    "format": "rockface-scene/1",
    "joints": [ { "id": "A", "dip": 60, "dipdir": 10 }, { "id": "B", "dip": 60, "dipdir": 130 },
                { "id": "C", "dip": 60, "dipdir": 250 } ],
    "wedges": { "profile": { "shape": "rectangle", "width": 6, "height": 0 },
                "axis": { "trend": 0, "plunge": 0 } }
  })";
  EXPECT_EQ(run((dir / "flat.scene.json").string() + " --out " + (dir / "w.json").string(), dir),
            2);
  EXPECT_NE(read(dir / "err.txt").find("wedges.profile.height"), std::string::npos)
      << read(dir / "err.txt");
  EXPECT_EQ(
      run((dir / "flat.scene.json").string() + " --axis 10 --out " + (dir / "w.json").string(),
          dir),
      2);
  EXPECT_FALSE(fs::exists(dir / "w.json"));
}

// Issue 41: `wedges P --bolts 3,1e-3,1e5` never ended; each value of
// --bolts is checked against its range before anything is computed.
TEST(WedgesVerb, ProjectBoltsOutsideTheirRangeAreRefusedByName) {
  const fs::path dir = temp_dir("bolt-range");
  const fs::path project = dir / "p.rockface";
  {
    storage::ProjectStore store = storage::ProjectStore::create(project, storage::ProjectInfo{});
    store.begin_visit("face");
  }
  auto said = [&](const std::string& bolts) {
    WedgesRequest q;
    q.input = project.string();
    q.bolts = bolts;
    try {
      wedges_from_input(q);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(said("3,1e-3,1e5"),
            "--bolts: SPACING: 0.001 m is outside [0.3, 10] m (the range of the bolts' setting)");
  EXPECT_EQ(said("3,1e-320,1e5").substr(0, 17), "--bolts: SPACING:");
  EXPECT_EQ(said("3,1,1e5,1e308"),
            "--bolts: BOND: 1e+308 N/m is outside [1000, 1e+08] N/m (the range of the bolts' "
            "setting)");
}

// Issue 41: `--shotcrete 0.05,1e308` was taken (any finite positive shear
// strength) and printed in 309 digits; it is held to the range the
// designer's support classes take (0.1-10 MPa), as the scene's is.
TEST(WedgesVerb, ProjectShotcreteShearOutsideItsRangeIsRefusedByName) {
  const fs::path dir = temp_dir("shotcrete-range");
  const fs::path project = dir / "p.rockface";
  {
    storage::ProjectStore store = storage::ProjectStore::create(project, storage::ProjectInfo{});
    store.begin_visit("face");
  }
  auto said = [&](const std::string& shotcrete) {
    WedgesRequest q;
    q.input = project.string();
    q.shotcrete = shotcrete;
    try {
      wedges_from_input(q);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(said("0.05,1e308"),
            "--shotcrete: SHEAR_STRENGTH: 1e+308 Pa is outside [100000, 1e+07] Pa (the range of "
            "the shotcrete's setting)");
  EXPECT_EQ(said("0.05,10"),
            "--shotcrete: SHEAR_STRENGTH: 10 Pa is outside [100000, 1e+07] Pa (the range of the "
            "shotcrete's setting)");
}

// Issue 41: a joint cohesion of 1e308 for the project's sets was taken.
TEST(WedgesVerb, ProjectCohesionOutsideItsRangeIsRefusedByName) {
  const fs::path dir = temp_dir("cohesion-range");
  const fs::path project = dir / "p.rockface";
  {
    storage::ProjectStore store = storage::ProjectStore::create(project, storage::ProjectInfo{});
    store.begin_visit("face");
  }
  for (const double cohesion : {1e308, -1.0}) {
    WedgesRequest q;
    q.input = project.string();
    q.cohesion_pa = cohesion;
    try {
      wedges_from_input(q);
      ADD_FAILURE() << cohesion << " Pa was taken";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "--cohesion") << e.what();
      EXPECT_NE(std::string(e.what()).find("[0, 1e8] Pa"), std::string::npos) << e.what();
    }
  }
}

// Issue 41: a section asked for at chainage 1e308 of a tunnel scene was
// refused with the chainage in 309 digits; it is said in 6 significant
// digits, and a chainage near the drive still to the millimetre.
TEST(WedgesVerb, AChainageBeyondAnyDriveIsSaidInSixDigits) {
  auto said = [](double chainage) {
    json scene = read_json(kSamples / "tunnel-drive.scene.json");
    scene["wedges"] = {{"sets", {"J1", "J2", "J3"}}, {"profile", "tunnel"}, {"chainage", chainage}};
    const fs::path dir = temp_dir("far-chainage");
    const fs::path file = dir / "far.scene.json";
    std::ofstream(file) << scene.dump();
    for (const char* f : {"tunnel-drive.alignment.csv", "tunnel-drive.profile.json"})
      fs::copy_file(kSamples / f, dir / f);
    try {
      (void)wedge_run_from_scene(storage::load_scene(file.string()));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string far = said(1e308);
  EXPECT_NE(
      far.find("chainage 1e+308 m lies beyond the alignment (0.000 to 200.000 m) by 1e+308 m"),
      std::string::npos)
      << far;
  EXPECT_LT(far.size(), 300u) << far;
  EXPECT_NE(said(200.5).find("chainage 200.500 m lies beyond the alignment (0.000 to 200.000 m) "
                             "by 0.500 m"),
            std::string::npos);
}

// Issue 41: an overflowed factor of safety (NaN) was shown as "stable";
// only no driving force at all (+infinity) is.
TEST(WedgesVerb, AnOverflowedFactorOfSafetyIsUnknownNotStable) {
  EXPECT_EQ(wedge_fos_text(std::numeric_limits<double>::quiet_NaN()), "unknown");
  EXPECT_EQ(wedge_fos_text(-std::numeric_limits<double>::infinity()), "unknown");
  EXPECT_EQ(wedge_fos_text(std::numeric_limits<double>::infinity()), "stable");
  EXPECT_EQ(wedge_fos_text(std::nullopt), "-");
  EXPECT_EQ(wedge_fos_text(1.234), "1.23");
}

TEST(WedgesVerb, ProjectVisitWithMeasuredSets) {
  const fs::path dir = temp_dir("project");
  const fs::path project = dir / "drive.rockface";
  storage::RecordId visit = 0;
  {
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
    visit = store.begin_visit("face at 105");
    // Three sets as a geologist's planes give them: a few degrees of scatter.
    const std::array<double, 5> ddip{-2, -1, 0, 1, 2}, ddir{1, -2, 2, -1, 0};
    std::vector<storage::Measurement> planes;
    for (auto [dip, dipdir] :
         {std::pair{65.0, 20.0}, std::pair{60.0, 145.0}, std::pair{55.0, 260.0}})
      for (std::size_t i = 0; i < ddip.size(); ++i) {
        storage::Measurement m;
        m.visit_id = visit;
        m.kind = storage::Measurement::Kind::trace;
        m.label = "T" + std::to_string(planes.size() + 1);
        m.points = {{0, 35, 0}, {1, 35, 1}};
        m.dip_deg = dip + ddip[i];
        m.dipdir_deg = dipdir + ddir[i];
        planes.push_back(m);
      }
    store.save_measurements(visit, planes);
    storage::VisitPlacement p;
    p.visit_id = visit;
    p.chainage = 105;
    p.note = "typed";
    store.save_visit_placement(p);
  }
  ASSERT_EQ(run(project.string() + " --visit " + std::to_string(visit) + " --out " +
                    (dir / "w.json").string() + " --png",
                dir),
            0)
      << read(dir / "err.txt");
  const json j = read_json(dir / "w.json");
  EXPECT_EQ(j["visit"], visit);
  ASSERT_EQ(j["sets"].size(), 3u);
  for (const auto& s : j["sets"]) {
    EXPECT_EQ(s["source"], "measured");
    EXPECT_EQ(s["friction_deg"], 30.0);
  }
  // The mean of each set's planes (symmetric scatter): within a degree of
  // the set's orientation, the rest is the Fisher mean's curvature.
  for (auto [dip, dipdir] :
       {std::pair{65.0, 20.0}, std::pair{60.0, 145.0}, std::pair{55.0, 260.0}}) {
    bool found = false;
    for (const auto& s : j["sets"])
      if (std::abs(s["dip"].get<double>() - dip) < 1 &&
          std::abs(s["dipdir"].get<double>() - dipdir) < 1)
        found = true;
    EXPECT_TRUE(found) << dip << "/" << dipdir;
  }
  EXPECT_DOUBLE_EQ(j["chainage"].get<double>(), 105.0);
  EXPECT_FALSE(j["wedges"].empty());
  bool assumed = false;
  for (const auto& n : j["notes"])
    if (n.get<std::string>().find("assumed") != std::string::npos) assumed = true;
  EXPECT_TRUE(assumed);
  EXPECT_TRUE(fs::exists(dir / "w.png"));
  // The library's answer for the same visit (the tablet's path).
  storage::ProjectStore store = storage::ProjectStore::open(project, {});
  std::string why;
  const auto r = project_visit_wedges(store, visit, &why);
  ASSERT_TRUE(r) << why;
  EXPECT_EQ(r->analysis.wedges.size(), j["wedges"].size());
  // The field report's section: one row per wedge, in words, and the picture.
  storage::FieldReport report = storage::collect_field_report(store, visit);
  add_wedges_to_report(store, report);
  ASSERT_TRUE(report.wedges);
  ASSERT_EQ(report.wedges->rows.size(), j["wedges"].size());
  for (std::size_t i = 0; i < report.wedges->rows.size(); ++i) {
    EXPECT_EQ(report.wedges->rows[i][0], j["wedges"][i]["id"]);
    EXPECT_EQ(report.wedges->rows[i][1], j["wedges"][i]["place"]);
  }
  EXPECT_FALSE(report.wedges->picture.empty());
  // Printed: the PDF writer lays the section out (cairo keeps text compressed,
  // so only that it writes is checked here).
  storage::write_field_report_pdf(report, dir / "report.pdf");
  EXPECT_GT(fs::file_size(dir / "report.pdf"), 20000u);
  // The tablet's Wedges view: the same wedges, in words and units.
  StoreWedgeRunner runner;
  NoProgress progress;
  const ui::WedgeTable table = runner.wedges(project, visit, {}, progress);
  ASSERT_EQ(table.rows.size(), j["wedges"].size());
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    ASSERT_EQ(table.rows[i].size(), table.columns.size());
    EXPECT_EQ(table.rows[i][1], j["wedges"][i]["place"]);
    // Margins to 0.1 degree with their unit, factors of safety to 2 decimals.
    const std::string& margin = table.rows[i][7];
    EXPECT_EQ(margin.substr(margin.size() - 2), "°");
    EXPECT_EQ(margin[margin.size() - 4], '.');
    const std::string& fos = table.rows[i][9];
    if (fos != "stable" && fos != "-") {
      EXPECT_EQ(fos[fos.size() - 3], '.') << fos;
    }
  }
  EXPECT_FALSE(table.bgr.empty());
}

TEST(WedgesReport, NoTunnelNoSection) {
  const fs::path dir = temp_dir("notunnel");
  storage::ProjectInfo info;
  info.name = "slope";
  storage::ProjectStore store = storage::ProjectStore::create(dir / "p.rockface", info);
  const storage::RecordId visit = store.begin_visit("a visit");
  storage::FieldReport report = storage::collect_field_report(store, visit);
  add_wedges_to_report(store, report);
  EXPECT_FALSE(report.wedges);
  std::string why;
  EXPECT_FALSE(project_visit_wedges(store, visit, &why));
  EXPECT_NE(why.find("no tunnel"), std::string::npos) << why;
}

}  // namespace
}  // namespace rockface::app

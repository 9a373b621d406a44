// Two tablets' projects up to one real PostgreSQL server and back: the
// server holds exactly what each tablet holds; a second sync sends nothing;
// a change goes up as a new revision with the history kept; a pull gives a
// project whose analysis is the tablet's bit for bit; the office's drive
// from the server is the drive of the project holding the same visits; a
// corrupt or truncated photograph on the server stops a pull by its hash;
// a client older than the server's schema is refused.
#include <cmath>
#include <fstream>
#include <map>
#include <optional>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/analysis/support_classes.h"
#include "core/analysis/support_decision.h"
#include "core/common/progress.h"
#include "firmware-app/import/import_surface.h"
#include "firmware-app/office/office_workflows.h"
#include "firmware-app/services/ui_services.h"
#include "firmware-app/tunnel/project_drive.h"
#include "storage/office/pg_connection.h"
#include "storage/office/pull_project.h"
#include "storage/office/sync_push.h"
#include "storage/project/model_registration.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"
#include "storage/report/report.h"
#include "tests/storage/office/office_environment.h"
#include "tests/storage/office/tablet_projects.h"
#include "tests/support/sample_records.h"

namespace rockface::office_test {
namespace {

namespace fs = std::filesystem;
using storage::office::sync_project;
using storage::office::SyncOptions;

SyncOptions small_chunks() {
  SyncOptions o;
  o.chunk_bytes = 4096;  // several chunks per test photograph
  return o;
}

TEST(OfficeSync, TwoTabletsSyncToOneServerAndPullBack) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-two-tablets");
  TabletProject a;
  a.name = "tablet A";
  a.seed = 1;
  TabletProject b;
  b.name = "tablet B";
  b.seed = 2;
  b.first_chainage = 107;
  make_tablet_project(dir / "a.rockface", a);
  make_tablet_project(dir / "b.rockface", b);
  {
    // Tablet A's first visit names its geologist (a comma in the name, for
    // the drive's CSV); the others name none.
    storage::ProjectStore store = storage::ProjectStore::open(dir / "a.rockface");
    store.save_visit_geologist(store.list_visits().front().id, "Anna Berger, site geologist");
  }
  // The schema-6 upgrade of a fresh project happens at create: take the
  // content after one open so that the comparison sees only the sync.
  const std::string before_a = project_content(dir / "a.rockface");
  NoProgress none;
  const auto ra = sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  const auto rb = sync_project(dir / "b.rockface", as_role(db, "tablet_b"), small_chunks(), none);
  EXPECT_EQ(ra.units_sent, 3) << "the project's records and two visits";
  // Two visits of two photographs each, and their meshes: the sample mesh is
  // the same in both visits, so it is stored (and sent) once.
  EXPECT_EQ(ra.blobs_sent, 5);
  EXPECT_GT(rb.records_sent, 0);
  EXPECT_EQ(first_difference(project_content(dir / "a.rockface"), before_a), "")
      << "the sync changed the tablet's data";
  expect_server_holds(as_superuser(db), dir / "a.rockface", 1);
  expect_server_holds(as_superuser(db), dir / "b.rockface", 1);

  // Again: nothing goes up, nothing changes on the server.
  const auto again =
      sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  EXPECT_EQ(again.units_total, 0);
  EXPECT_EQ(again.records_sent, 0);
  expect_server_holds(as_superuser(db), dir / "a.rockface", 1);

  // The office pulls the tunnel: both tablets' visits in one project.
  const auto pull = storage::office::pull_tunnel(as_role(db, "office_reader"), "Main drive",
                                                 dir / "pulled.rockface", none);
  EXPECT_EQ(pull.warnings, std::vector<std::string>{})
      << "both tablets carry the same design of the tunnel";
  storage::ProjectStore pulled = storage::ProjectStore::open(dir / "pulled.rockface");
  EXPECT_EQ(pulled.list_visits().size(), 4u);
  EXPECT_EQ(pulled.list_captures().size(), 4u);
  EXPECT_EQ(pulled.list_visit_placements().size(), 4u);
  ASSERT_TRUE(pulled.load_tunnel());
  // Photographs and meshes come back byte for byte.
  storage::ProjectStore original = storage::ProjectStore::open(dir / "b.rockface");
  const auto from_b = original.list_captures();
  bool found = false;
  for (const auto& c : pulled.list_captures()) {
    if (c.label != from_b.front().label || c.left_bytes != from_b.front().left_bytes) continue;
    EXPECT_EQ(pulled.load_capture_image(c.id, "left").bytes,
              original.load_capture_image(from_b.front().id, "left").bytes);
    found = true;
  }
  EXPECT_TRUE(found) << "tablet B's first capture is in the pulled project";

  // The office's drive from the server is the drive of the pulled project.
  // Who mapped each visit too, read from the server with the drive.
  const storage::office::ServerDrive records =
      app::server_drive_records(as_role(db, "office_reader"), "Main drive");
  const auto from_server = app::server_drive(records);
  const auto from_pulled = app::project_drive(pulled);
  const app::DriveGeologists named = app::server_drive_geologists(records);
  EXPECT_EQ(named, app::drive_geologists(pulled));
  ASSERT_EQ(named.size(), 1u) << "tablet A's first visit alone names its geologist";
  EXPECT_EQ(named.begin()->second, "Anna Berger, site geologist");
  EXPECT_EQ(app::drive_csv(from_server, named),
            app::drive_csv(from_pulled, app::drive_geologists(pulled)));
  EXPECT_EQ(app::drive_summary(from_server, named),
            app::drive_summary(from_pulled, app::drive_geologists(pulled)));
  EXPECT_NE(app::drive_csv(from_server, named).find(",\"Anna Berger, site geologist\"\n"),
            std::string::npos)
      << "the name, quoted for its comma, ends its visit's rows";
  EXPECT_EQ(from_server.visits.size(), 4u);
  // And its support per round (`drive postgresql://... --support-csv`).
  const auto rounds = app::server_drive_support(as_role(db, "office_reader"), "Main drive", none);
  EXPECT_EQ(app::drive_support_csv(rounds), app::drive_support_csv(app::drive_support(pulled)));
  EXPECT_EQ(rounds.size(), 4u) << "one round per placed visit";
}

TEST(OfficeSync, PulledProjectGivesTheSameAnalysisBitForBit) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-analysis");
  TabletProject a;
  a.name = "tablet A";
  a.visits = 1;
  a.dense_face_visit = true;
  make_tablet_project(dir / "a.rockface", a);
  NoProgress none;
  sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  storage::office::pull_tunnel(as_role(db, "office_reader"), "Main drive", dir / "p.rockface",
                               none);
  // One tablet's project: the pulled one keeps its ids, and every row.
  EXPECT_EQ(
      first_difference(project_content(dir / "p.rockface"), project_content(dir / "a.rockface")),
      "");

  // The tablet's analysis workflow on both.
  app::StoreAnalysisRunner runner;
  const storage::RecordId visit = 2;  // the mapped face
  const auto ida = runner.analyse(dir / "a.rockface", visit, none);
  const auto idp = runner.analyse(dir / "p.rockface", visit, none);
  storage::ProjectStore sa = storage::ProjectStore::open(dir / "a.rockface");
  storage::ProjectStore sp = storage::ProjectStore::open(dir / "p.rockface");
  const auto ra = sa.load_analysis(ida), rp = sp.load_analysis(idp);
  ASSERT_FALSE(ra.blocks.empty()) << "the mapped face has blocks to compare";
  ASSERT_EQ(ra.blocks.size(), rp.blocks.size());
  for (std::size_t i = 0; i < ra.blocks.size(); ++i) {
    // The whole verdict, as the store writes it, and the volume bit for bit.
    EXPECT_EQ(storage::block_to_json(ra.blocks[i]), storage::block_to_json(rp.blocks[i]))
        << ra.blocks[i].id;
    EXPECT_EQ(ra.blocks[i].volume, rp.blocks[i].volume);  // bit for bit
  }

  // The new analysis goes up as new records, the rest unchanged.
  const auto r = sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  EXPECT_EQ(r.units_sent, 1) << "only the analysed visit";
  EXPECT_EQ(r.records_sent, static_cast<int>(ra.blocks.size()) + 2)
      << "the analysis, its blocks and its log entry";
  expect_server_holds(as_superuser(db), dir / "a.rockface");
}

TEST(OfficeSync, AChangedRecordIsANewRevisionAndTheHistoryIsKept) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-revision");
  TabletProject a;
  a.visits = 1;
  make_tablet_project(dir / "a.rockface", a);
  NoProgress none;
  sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  {
    // The geologist moves the visit in the tunnel: the placement is replaced.
    storage::ProjectStore store = storage::ProjectStore::open(dir / "a.rockface");
    auto p = *store.load_visit_placement(1);
    p.chainage += 0.75;
    p.note = "corrected from the survey";
    store.save_visit_placement(p);
  }
  const auto status = storage::office::sync_status(dir / "a.rockface");
  EXPECT_TRUE(status.ever_synced);
  EXPECT_EQ(status.visits_waiting, 1);
  EXPECT_EQ(status.records_waiting, 2) << "the placement and the log entry of its change";
  const auto r = sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  EXPECT_EQ(r.records_sent, 2);
  EXPECT_EQ(r.blobs_sent, 0) << "no photograph changed";
  storage::office::Connection c(as_superuser(db));
  const auto history = c.query(
      "SELECT revision, body->'row'->>'chainage', body->'row'->>'note' FROM rockface.record "
      "WHERE kind = 'visit_placement' ORDER BY revision",
      {}, "reading the history");
  ASSERT_EQ(history.rows(), 2);
  EXPECT_EQ(history.text(0, 2), "typed");
  EXPECT_EQ(history.text(1, 2), "corrected from the survey");
  EXPECT_EQ(std::stod(history.text(1, 1)) - std::stod(history.text(0, 1)), 0.75);
  EXPECT_EQ(storage::office::sync_status(dir / "a.rockface").records_waiting, 0);
}

TEST(OfficeSync, ARecordGoneFromTheTabletGoesUpAsADeletedRevision) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-deleted");
  TabletProject a;
  a.visits = 2;
  make_tablet_project(dir / "a.rockface", a);
  NoProgress none;
  sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  // The program itself never deletes a record today (a change is a new
  // row); a row removed by another tool, or a future undo, must still reach
  // the office as a deletion, never be resurrected by a pull.
  std::string uuid;
  {
    storage::sqlite::Connection c(dir / "a.rockface",
                                  storage::sqlite::Connection::Access::read_write);
    storage::sqlite::Statement pick(
        c,
        "SELECT id, uuid FROM measurement WHERE id NOT IN (SELECT measurement_id FROM joint "
        "WHERE measurement_id IS NOT NULL) ORDER BY id DESC LIMIT 1",
        "picking a measurement");
    ASSERT_TRUE(pick.step()) << "the sample project has a measurement no joint refers to";
    const std::int64_t id = pick.column_int(0);
    uuid = pick.column_text(1);
    storage::sqlite::Statement del(c, "DELETE FROM measurement WHERE id = ?", "deleting it");
    del.bind(1, id).run();
  }
  const auto status = storage::office::sync_status(dir / "a.rockface");
  EXPECT_EQ(status.records_waiting, 1) << "the deletion alone";
  const auto r = sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  EXPECT_EQ(r.records_sent, 1);
  storage::office::Connection c(as_superuser(db));
  const auto history = c.query(
      "SELECT revision, deleted, body IS NULL FROM rockface.record WHERE kind = 'measurement' "
      "AND uuid = $1::uuid ORDER BY revision",
      {storage::office::Param::of(uuid)}, "reading the history");
  ASSERT_EQ(history.rows(), 2) << "the measurement as synced, then its deletion";
  EXPECT_EQ(history.text(0, 1), "f");
  EXPECT_EQ(history.text(1, 1), "t");
  EXPECT_EQ(history.text(1, 2), "t") << "a deleted revision carries no body";
  // Nothing waits any more; a second sync sends nothing; the server holds
  // the tablet's records (the deleted one no longer among them).
  EXPECT_EQ(storage::office::sync_status(dir / "a.rockface").records_waiting, 0);
  EXPECT_EQ(
      sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none).records_sent,
      0);
  expect_server_holds(as_superuser(db), dir / "a.rockface");
  // A pull does not bring it back.
  storage::office::pull_tunnel(as_role(db, "office_reader"), "Main drive", dir / "p.rockface",
                               none);
  storage::sqlite::Connection p(dir / "p.rockface", storage::sqlite::Connection::Access::read_only);
  storage::sqlite::Statement count(p, "SELECT count(*) FROM measurement WHERE uuid = ?",
                                   "counting");
  count.bind(1, uuid);
  ASSERT_TRUE(count.step());
  EXPECT_EQ(count.column_int(0), 0);
}

// Issue 27: the tablet's undo of a saved trace (ProjectStore::
// delete_measurement) takes the trace and the joint fitted from it; both go
// up as deleted revisions, with the action that says so, and a second sync
// sends nothing.
TEST(OfficeSync, ATraceTakenBackOnTheTabletGoesUpDeletedWithItsJoint) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-taken-back");
  TabletProject a;
  make_tablet_project(dir / "a.rockface", a);
  std::string trace_uuid, joint_uuid;
  storage::RecordId trace_id = 0;
  {
    auto store = storage::ProjectStore::open(dir / "a.rockface");
    const auto visit = *store.latest_visit();
    storage::Measurement t = store.list_measurements(visit).front();
    t.id = 0;
    t.label = "T99";
    trace_id = store.save_measurements(visit, {t}).front();
    storage::Joint j;
    j.label = "T99";
    j.dip_deg = 60;
    j.dipdir_deg = 120;
    j.measurement_id = trace_id;
    j.source = "trace T99";
    j.type = "trace";
    store.save_joints(visit, {}, {j});
  }
  NoProgress none;
  sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  {
    storage::sqlite::Connection c(dir / "a.rockface",
                                  storage::sqlite::Connection::Access::read_only);
    storage::sqlite::Statement m(c, "SELECT uuid FROM measurement WHERE id = ?", "reading");
    m.bind(1, trace_id);
    ASSERT_TRUE(m.step());
    trace_uuid = m.column_text(0);
    storage::sqlite::Statement j(c, "SELECT uuid FROM joint WHERE measurement_id = ?", "reading");
    j.bind(1, trace_id);
    ASSERT_TRUE(j.step());
    joint_uuid = j.column_text(0);
  }
  storage::ProjectStore::open(dir / "a.rockface").delete_measurement(trace_id);
  EXPECT_EQ(storage::office::sync_status(dir / "a.rockface").records_waiting, 3)
      << "the trace's deletion, its joint's, and the action saying so";
  EXPECT_EQ(
      sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none).records_sent,
      3);
  storage::office::Connection c(as_superuser(db));
  for (const auto& [kind, uuid] :
       {std::pair<std::string, std::string>{"measurement", trace_uuid}, {"joint", joint_uuid}}) {
    const auto history = c.query(
        "SELECT deleted FROM rockface.record WHERE kind = $1 AND uuid = $2::uuid ORDER BY "
        "revision",
        {storage::office::Param::of(kind), storage::office::Param::of(uuid)}, "reading history");
    ASSERT_EQ(history.rows(), 2) << kind << ": as synced, then deleted";
    EXPECT_EQ(history.text(1, 0), "t") << kind;
  }
  EXPECT_EQ(storage::office::sync_status(dir / "a.rockface").records_waiting, 0);
  expect_server_holds(as_superuser(db), dir / "a.rockface");
}

TEST(OfficeSync, APullSaysWhenTheTabletsCarryDifferentDesignsOfTheTunnel) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-two-designs");
  TabletProject a;
  a.name = "tablet A";
  a.visits = 1;
  TabletProject b = a;
  b.name = "tablet B";
  b.first_chainage = 107;
  b.underbreak_tolerance_m = 0.10;  // B was set up with another design tolerance
  make_tablet_project(dir / "a.rockface", a);
  make_tablet_project(dir / "b.rockface", b);
  NoProgress none;
  sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  sync_project(dir / "b.rockface", as_role(db, "tablet_b"), small_chunks(), none);
  const auto lines =
      app::run_pull(as_role(db, "office_reader"), "Main drive", dir / "p.rockface", none);
  std::string warning;
  for (const auto& line : lines)
    if (line.rfind("warning: ", 0) == 0) warning = line;
  EXPECT_NE(warning.find("different designs"), std::string::npos) << warning;
  EXPECT_NE(warning.find("holds the one of project 'tablet A'"), std::string::npos) << warning;
  EXPECT_NE(warning.find("'tablet B' differ"), std::string::npos) << warning;
  // The pulled project holds tablet A's design (the first synced).
  storage::ProjectStore pulled = storage::ProjectStore::open(dir / "p.rockface");
  ASSERT_TRUE(pulled.load_tunnel());
  EXPECT_EQ(pulled.load_tunnel()->underbreak_tolerance_m, 0.05);
}

TEST(OfficeSync, ACorruptOrTruncatedBlobOnTheServerIsDetectedOnPull) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-corrupt");
  TabletProject a;
  a.visits = 1;
  make_tablet_project(dir / "a.rockface", a);
  NoProgress none;
  sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  // One byte of a photograph's second chunk flipped on the server's disk.
  server().psql(
      "UPDATE rockface.blob_chunk SET bytes = set_byte(bytes, 100, (get_byte(bytes, 100) + 1) % "
      "256) WHERE idx = 1 AND sha256 = (SELECT sha256 FROM rockface.blob ORDER BY byte_size DESC "
      "LIMIT 1)",
      db);
  try {
    storage::office::pull_tunnel(as_role(db, "office_reader"), "Main drive", dir / "p.rockface",
                                 none);
    ADD_FAILURE() << "a corrupt photograph was pulled";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("corrupt on the server"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "p.rockface")) << "no half-pulled project is left";
  // The last chunk of another one gone: truncated.
  server().psql(
      "DELETE FROM rockface.blob_chunk WHERE (sha256, idx) = (SELECT sha256, max(idx) FROM "
      "rockface.blob_chunk WHERE sha256 = (SELECT sha256 FROM rockface.blob ORDER BY byte_size "
      "DESC OFFSET 1 LIMIT 1) GROUP BY sha256)",
      db);
  server().psql(
      "UPDATE rockface.blob_chunk SET bytes = set_byte(bytes, 100, (get_byte(bytes, 100) + 255) "
      "% 256) WHERE idx = 1 AND sha256 = (SELECT sha256 FROM rockface.blob ORDER BY byte_size "
      "DESC LIMIT 1)",
      db);
  try {
    storage::office::pull_tunnel(as_role(db, "office_reader"), "Main drive", dir / "p.rockface",
                                 none);
    ADD_FAILURE() << "a truncated blob was pulled";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("truncated on the server"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "p.rockface"));
}

TEST(OfficeSync, AClientOlderThanTheServersSchemaIsRefusedByName) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-newer-server");
  TabletProject a;
  a.visits = 1;
  make_tablet_project(dir / "a.rockface", a);
  server().psql("UPDATE rockface.meta SET value = '99' WHERE key = 'schema_version'", db);
  NoProgress none;
  try {
    sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
    ADD_FAILURE() << "an old client synced to a newer server";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("version 99"), std::string::npos) << m;
    EXPECT_NE(m.find("this client is too old"), std::string::npos) << m;
  }
  storage::office::Connection c(as_superuser(db));
  EXPECT_EQ(c.query("SELECT count(*) FROM rockface.record", {}, "counting").int64(0, 0), 0);
}

// Issue 27: a trace's compass reading (schema 9) goes to the office with its
// trace and comes back on a pull; a reading given again on the tablet goes
// up as a new revision of the same trace.
std::optional<storage::Measurement> trace_named(storage::ProjectStore& store,
                                                const std::string& label) {
  for (const auto& m : store.list_measurements())
    if (m.kind == storage::Measurement::Kind::trace && m.label == label) return m;
  return std::nullopt;
}

TEST(OfficeSync, ACompassReadingGoesUpWithItsTraceAndComesBack) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-compass");
  TabletProject a;
  a.visits = 1;
  make_tablet_project(dir / "a.rockface", a);
  storage::RecordId trace_id = 0;
  {
    auto store = storage::ProjectStore::open(dir / "a.rockface");
    const auto visit = *store.latest_visit();
    storage::Measurement t = store.list_measurements(visit).front();
    ASSERT_EQ(t.kind, storage::Measurement::Kind::trace);
    t.id = 0;
    t.label = "T77";
    t.dip_deg = 74;
    t.dipdir_deg = 111;
    t.compass_dip_deg = 74;
    t.compass_dipdir_deg = 111;
    t.compass_off_deg = 1.25;
    trace_id = store.save_measurements(visit, {t}).front();
  }
  NoProgress none;
  sync_project(dir / "a.rockface", as_role(db, "tablet_a"), {}, none);
  expect_server_holds(as_superuser(db), dir / "a.rockface");
  storage::office::pull_tunnel(as_role(db, "office_reader"), "Main drive", dir / "p.rockface",
                               none);
  {
    auto pulled = storage::ProjectStore::open(dir / "p.rockface");
    const auto back = trace_named(pulled, "T77");
    ASSERT_TRUE(back);
    EXPECT_EQ(back->compass_dip_deg, 74);
    EXPECT_EQ(back->compass_dipdir_deg, 111);
    EXPECT_EQ(back->compass_off_deg, 1.25);
  }

  // Given again on the tablet: the same trace, a new revision on the server.
  {
    auto store = storage::ProjectStore::open(dir / "a.rockface");
    storage::Measurement t = *trace_named(store, "T77");
    t.compass_dip_deg = 73;
    t.dip_deg = 73;
    store.set_trace_plane(trace_id, t);
  }
  EXPECT_GE(sync_project(dir / "a.rockface", as_role(db, "tablet_a"), {}, none).records_sent, 1);
  expect_server_holds(as_superuser(db), dir / "a.rockface");
  std::string uuid;
  {
    storage::sqlite::Connection c(dir / "a.rockface",
                                  storage::sqlite::Connection::Access::read_only);
    storage::sqlite::Statement m(c, "SELECT uuid FROM measurement WHERE id = ?", "reading");
    m.bind(1, trace_id);
    ASSERT_TRUE(m.step());
    uuid = m.column_text(0);
  }
  storage::office::Connection c(as_superuser(db));
  const auto history = c.query(
      "SELECT body->'row'->>'compass_dip' FROM rockface.record WHERE kind = 'measurement' AND "
      "uuid = $1::uuid ORDER BY revision",
      {storage::office::Param::of(uuid)}, "reading history");
  ASSERT_EQ(history.rows(), 2) << "as synced, then with the new reading";
  EXPECT_EQ(std::stod(history.text(0, 0)), 74);
  EXPECT_EQ(std::stod(history.text(1, 0)), 73);
}

// The round's support (issue 44): the tunnel's classes and a visit's
// decisions, each a record kind of its own, go up with the project and come
// back with a pull, every revision kept on the server, the latest in force.
TEST(OfficeSync, TheSupportClassesAndARoundsDecisionsGoUpAndComeBack) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-support");
  TabletProject a;
  a.visits = 1;
  make_tablet_project(dir / "a.rockface", a);
  {
    auto store = storage::ProjectStore::open(dir / "a.rockface");
    analysis::SupportClasses classes;
    classes.tunnel = "Main drive";
    classes.source = "classes.json";
    for (const char* name : {"A", "B"}) {
      analysis::SupportClass c;
      c.name = name;
      c.round_length_m = name[0] == 'A' ? 3.0 : 2.0;
      c.criteria.rmr =
          name[0] == 'A' ? analysis::FigureRange{60.0, 100.0} : analysis::FigureRange{0.0, 60.0};
      classes.classes.push_back(c);
    }
    store.save_support_classes(classes);
    const auto visit = *store.latest_visit();
    analysis::SupportDecision d;
    d.class_name = "A";
    d.proposed = "A";
    d.decided_by = "geologist";
    d.decided_at = "2026-11-29T03:00:00.000Z";
    d.checks = "every wedge at or above FoS 1.5";
    store.save_support_decision(visit, d);
    d.class_name = "B";
    d.reason = "a roof wedge the bolts of A do not reach past";
    d.changes.push_back({"bolt length", "3 m", "4 m", "W2"});
    d.decided_at = "2026-11-29T03:20:00.000Z";
    store.save_support_decision(visit, d);
  }
  NoProgress none;
  sync_project(dir / "a.rockface", as_role(db, "tablet_a"), {}, none);
  expect_server_holds(as_superuser(db), dir / "a.rockface");
  {
    storage::office::Connection c(as_superuser(db));
    const auto kinds = c.query(
        "SELECT kind, count(*) FROM rockface.record WHERE kind IN ('support_classes', "
        "'support_decision') GROUP BY kind ORDER BY kind",
        {}, "support records");
    ASSERT_EQ(kinds.rows(), 2);
    EXPECT_EQ(kinds.text(0, 0), "support_classes");
    EXPECT_EQ(kinds.text(1, 0), "support_decision");
    EXPECT_EQ(kinds.text(1, 1), "2") << "both decisions of the round, the history kept";
  }
  storage::office::pull_tunnel(as_role(db, "office_reader"), "Main drive", dir / "p.rockface",
                               none);
  auto pulled = storage::ProjectStore::open(dir / "p.rockface");
  const auto classes = pulled.load_support_classes();
  ASSERT_TRUE(classes);
  ASSERT_EQ(classes->classes.size(), 2u);
  EXPECT_EQ(classes->classes[1].name, "B");
  EXPECT_EQ(classes->classes[1].round_length_m, 2.0);
  const auto visit = *pulled.latest_visit();
  const auto decisions = pulled.list_support_decisions(visit);
  ASSERT_EQ(decisions.size(), 2u);
  EXPECT_EQ(decisions[0].class_name, "A");
  const auto latest = pulled.load_support_decision(visit);
  ASSERT_TRUE(latest);
  EXPECT_EQ(latest->class_name, "B");
  EXPECT_EQ(latest->reason, "a roof wedge the bolts of A do not reach past");
  ASSERT_EQ(latest->changes.size(), 1u);
  EXPECT_EQ(latest->changes[0].to, "4 m");
  EXPECT_EQ(latest->decided_by, "geologist");
}

}  // namespace
}  // namespace rockface::office_test

namespace rockface::office_test {
namespace {

// Issue 43: a scanner's cloud imported on the tablet as a visit goes up with
// the tablet's other visits and comes back in the office's pull as the
// tablet holds it: every row, the model's mesh at full resolution and its
// import record naming the file (the source line the field report prints).
TEST(OfficeSync, AnImportedScanGoesUpAndComesBackNamingItsSource) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-imported-scan");
  TabletProject a;
  a.name = "tablet A";
  a.visits = 1;
  make_tablet_project(dir / "a.rockface", a);
  // A gently curved face of 2,500 points, 5 cm apart, at the project's
  // survey coordinates (the import moves it to the project's datum).
  const fs::path scan = dir / "scan.xyz";
  {
    const Eigen::Vector3d at = storage::test::sample_project().datum + Eigen::Vector3d(3, 8, 1);
    std::ofstream out(scan);
    out.precision(12);
    for (int i = 0; i < 50; ++i)
      for (int k = 0; k < 50; ++k) {
        const double x = 0.05 * i, z = 0.05 * k;
        out << at.x() + x << ' ' << at.y() + 0.02 * std::sin(3 * x) * std::cos(2 * z) << ' '
            << at.z() + z << '\n';
      }
  }
  app::ImportResult imported;
  {
    storage::ProjectStore store = storage::ProjectStore::open(dir / "a.rockface");
    app::ImportRequest request;
    request.file = scan;
    imported = app::import_surface(store, request);
  }
  ASSERT_EQ(imported.registration_kind, "scanner");
  NoProgress none;
  sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  expect_server_holds(as_superuser(db), dir / "a.rockface");
  storage::office::pull_tunnel(as_role(db, "office_reader"), "Main drive", dir / "p.rockface",
                               none);
  // One tablet's project: the pulled one keeps its ids and every row.
  EXPECT_EQ(
      first_difference(project_content(dir / "p.rockface"), project_content(dir / "a.rockface")),
      "");
  storage::ProjectStore tablet = storage::ProjectStore::open(dir / "a.rockface");
  storage::ProjectStore pulled = storage::ProjectStore::open(dir / "p.rockface");
  const storage::Model there = pulled.load_model(imported.model);
  const storage::Model here = tablet.load_model(imported.model);
  EXPECT_EQ(there.mesh.vertices, here.mesh.vertices);
  EXPECT_EQ(there.mesh.faces.size(), imported.triangles);
  const auto source = storage::read_model_registration(there.registration).imported_from;
  EXPECT_EQ(source.rfind("scan.xyz: ", 0), 0u) << source;
  EXPECT_EQ(source, storage::read_model_registration(here.registration).imported_from);
}

// Issue 46: the geologist who mapped a visit goes up with it as a record of
// its own and comes back with `pull`; renamed, the new name comes back; a
// name taken away comes back as none, and a visit nobody named stays so.
TEST(OfficeSync, AVisitsGeologistGoesUpAndComesBackRenamedAndTakenAway) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-geologist");
  TabletProject a;
  a.name = "tablet A";
  make_tablet_project(dir / "a.rockface", a);
  storage::RecordId named = 0, unnamed = 0;
  {
    storage::ProjectStore tablet = storage::ProjectStore::open(dir / "a.rockface");
    const auto visits = tablet.list_visits();
    ASSERT_EQ(visits.size(), 2u);
    named = visits[0].id;
    unnamed = visits[1].id;
    // Stored as typed: the office's pages escape it.
    tablet.save_visit_geologist(named, "O'Brien <b>");
  }
  // The pulled project's geologist of each visit, by the visit's id.
  auto pulled_geologists = [&](const std::string& copy) {
    NoProgress none;
    sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
    storage::office::pull_tunnel(as_role(db, "office_reader"), "Main drive", dir / copy, none);
    storage::ProjectStore pulled = storage::ProjectStore::open(dir / copy);
    std::map<storage::RecordId, std::optional<std::string>> out;
    for (const auto& v : pulled.list_visits()) out[v.id] = v.geologist;
    return out;
  };
  using Named = std::optional<std::string>;
  auto first = pulled_geologists("first.rockface");
  EXPECT_EQ(first[named], Named("O'Brien <b>"));
  EXPECT_EQ(first[unnamed], std::nullopt);
  expect_server_holds(as_superuser(db), dir / "a.rockface");

  storage::ProjectStore::open(dir / "a.rockface").save_visit_geologist(named, "Anna Berger");
  auto renamed = pulled_geologists("renamed.rockface");
  EXPECT_EQ(renamed[named], Named("Anna Berger"));
  EXPECT_EQ(renamed[unnamed], std::nullopt);

  storage::ProjectStore::open(dir / "a.rockface").save_visit_geologist(named, "");
  auto taken_away = pulled_geologists("taken-away.rockface");
  EXPECT_EQ(taken_away.size(), 2u);
  EXPECT_EQ(taken_away[named], std::nullopt);
}

}  // namespace
}  // namespace rockface::office_test

// The Project screen's office panel, tapped on the headless tablet UI with
// the tablet's real sync (app::StoreSyncRunner) against the suite's real
// server, named once per tablet by a libpq service: the panel shows the
// server and what waits, the Sync button sends it on the worker, Cancel
// stops it with what was sent kept and the next Sync completes it, and
// without a network the panel says so while the rest of the tablet goes on.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "firmware-app/services/ui_services.h"
#include "storage/office/pg_connection.h"
#include "storage/office/sync_push.h"
#include "tests/office/office_environment.h"
#include "tests/office/tablet_projects.h"
#include "tests/storage/sample_records.h"
#include "ui/headless_session.h"

namespace rockface::office_test {
namespace {

namespace fs = std::filesystem;

// The tablet's one server as its set-up would write it: a service file
// section named by ROCKFACE_SERVICE (key=value lines of the conninfo).
void set_tablet_service(const fs::path& dir, const std::string& conninfo) {
  std::ofstream file(dir / "pg_service.conf");
  file << "[panel-office]\n";
  std::istringstream words(conninfo);
  for (std::string kv; words >> kv;) file << kv << "\n";
  file.close();
  ::setenv("PGSERVICEFILE", (dir / "pg_service.conf").c_str(), 1);
  ::setenv("ROCKFACE_SERVICE", "panel-office", 1);
}

std::unique_ptr<ui::HeadlessSession> open_tablet(const fs::path& project,
                                                 app::StoreSyncRunner& sync) {
  ui::UiOptions options;
  options.project = project;
  options.scale = 0.6f;
  options.max_display_triangles = 20000;
  ui::FieldServices services;
  services.sync = &sync;
  auto s = std::make_unique<ui::HeadlessSession>(options, services, 1280, 800);
  s->settle();
  s->tap("Project");
  return s;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string all;
  for (const auto& l : lines) all += l + "\n";
  return all;
}

TEST(OfficeSyncPanel, SyncButtonSendsWhatWaitsAndThePanelSaysSo) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-panel");
  TabletProject a;
  a.visits = 2;
  make_tablet_project(dir / "a.rockface", a);
  set_tablet_service(dir.path(), as_role(db, "tablet_a"));
  app::StoreSyncRunner sync;
  auto s = open_tablet(dir / "a.rockface", sync);
  s->frame();
  ui::OfficeState& office = s->state().office;
  ASSERT_TRUE(office.overview) << office.error;
  EXPECT_EQ(office.overview->server, "service=panel-office");
  EXPECT_FALSE(office.overview->ever_synced);
  EXPECT_GT(office.overview->records_waiting, 0);
  EXPECT_EQ(office.overview->visits_waiting, 2);

  s->tap("Sync");
  ASSERT_TRUE(s->state().task.running() || !office.lines.empty()) << "the tap started the sync";
  s->settle();
  s->frame();  // the panel re-reads the project's sync record
  EXPECT_NE(joined(office.lines).find("units sent"), std::string::npos) << joined(office.lines);
  ASSERT_TRUE(office.overview);
  EXPECT_TRUE(office.overview->ever_synced);
  EXPECT_EQ(office.overview->tunnel, "Main drive");
  EXPECT_EQ(office.overview->records_waiting, 0);
  expect_server_holds(as_superuser(db), dir / "a.rockface", 1);
}

TEST(OfficeSyncPanel, ACancelledSyncKeepsWhatWasSentAndTheNextSyncCompletesIt) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-panel-cancel");
  TabletProject a;
  a.visits = 2;
  make_tablet_project(dir / "a.rockface", a);
  set_tablet_service(dir.path(), as_role(db, "tablet_a"));
  app::StoreSyncRunner sync;
  auto s = open_tablet(dir / "a.rockface", sync);
  {
    // The office's own work holds the records table: the tablet's sync
    // waits at its first unit while the geologist taps Cancel, so the
    // cancel reaches the sync mid-way whatever the machine's speed.
    storage::office::Connection office(as_superuser(db));
    office.exec("BEGIN; LOCK TABLE rockface.record IN ACCESS EXCLUSIVE MODE", "holding records");
    s->tap("Sync");
    ASSERT_TRUE(s->state().task.running());
    s->tap("Cancel");
    office.exec("COMMIT", "releasing records");
  }
  s->settle();
  s->frame();
  ui::OfficeState& office = s->state().office;
  EXPECT_NE(joined(office.lines).find("cancelled"), std::string::npos) << joined(office.lines);
  ASSERT_TRUE(office.overview);
  EXPECT_GT(office.overview->records_waiting, 0) << "the cancel came before the last unit";

  s->tap("Sync");
  s->settle();
  s->frame();
  ASSERT_TRUE(office.overview);
  EXPECT_EQ(office.overview->records_waiting, 0);
  expect_server_holds(as_superuser(db), dir / "a.rockface", 1);
}

TEST(OfficeSyncPanel, WithoutANetworkThePanelSaysSoAndFieldWorkGoesOn) {
  storage::test::TempDir dir("office-panel-offline");
  TabletProject a;
  a.visits = 1;
  make_tablet_project(dir / "a.rockface", a);
  const std::string before = project_content(dir / "a.rockface");
  // Nothing listens on port 1 of this machine: the office is out of reach.
  set_tablet_service(dir.path(), "host=127.0.0.1 port=1 user=tablet_a dbname=rockface");
  app::StoreSyncRunner sync;
  auto s = open_tablet(dir / "a.rockface", sync);
  s->tap("Sync");
  s->settle();
  s->frame();
  const ui::OfficeState& office = s->state().office;
  EXPECT_NE(joined(office.lines).find("No network"), std::string::npos) << joined(office.lines);
  EXPECT_NE(joined(office.lines).find("Nothing is lost"), std::string::npos);
  ASSERT_TRUE(office.overview);
  EXPECT_FALSE(office.overview->ever_synced);
  // The rest of the tablet is untouched and answers.
  s->tap("Mapping");
  s->tap("Project");
  EXPECT_FALSE(s->state().task.running());
  EXPECT_EQ(first_difference(project_content(dir / "a.rockface"), before), "");
}

}  // namespace
}  // namespace rockface::office_test

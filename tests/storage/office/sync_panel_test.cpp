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
#include "tests/storage/office/office_environment.h"
#include "tests/storage/office/tablet_projects.h"
#include "tests/support/sample_records.h"
#include "ui/platform/headless_session.h"

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

// A tablet with a project of `visits` visits, its service naming the
// server of `conninfo`, and its UI open on the Project screen.
class Tablet {
 public:
  Tablet(const std::string& name, int visits, const std::string& conninfo) : dir_(name) {
    TabletProject a;
    a.visits = visits;
    make_tablet_project(file(), a);
    set_tablet_service(dir_.path(), conninfo);
    ui::UiOptions options;
    options.project = file();
    options.scale = 0.6f;
    options.max_display_triangles = 20000;
    ui::FieldServices services;
    services.sync = &sync_;
    ui_ = std::make_unique<ui::HeadlessSession>(options, services, 1280, 800);
    ui_->settle();
    ui_->tap("Project");
  }
  fs::path file() const { return dir_ / "a.rockface"; }
  ui::HeadlessSession& ui() { return *ui_; }
  ui::OfficeState& office() { return ui_->state().project.office; }

 private:
  storage::test::TempDir dir_;
  app::StoreSyncRunner sync_;
  std::unique_ptr<ui::HeadlessSession> ui_;
};

std::string joined(const std::vector<std::string>& lines) {
  std::string all;
  for (const auto& l : lines) all += l + "\n";
  return all;
}

TEST(OfficeSyncPanel, SyncButtonSendsWhatWaitsAndThePanelSaysSo) {
  const std::string db = fresh_database();
  Tablet tablet("office-panel", 2, as_role(db, "tablet_a"));
  ui::HeadlessSession* s = &tablet.ui();
  s->frame();
  ui::OfficeState& office = tablet.office();
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
  expect_server_holds(as_superuser(db), tablet.file(), 1);
}

TEST(OfficeSyncPanel, ACancelledSyncKeepsWhatWasSentAndTheNextSyncCompletesIt) {
  const std::string db = fresh_database();
  Tablet tablet("office-panel-cancel", 2, as_role(db, "tablet_a"));
  ui::HeadlessSession* s = &tablet.ui();
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
  ui::OfficeState& office = tablet.office();
  EXPECT_NE(joined(office.lines).find("cancelled"), std::string::npos) << joined(office.lines);
  ASSERT_TRUE(office.overview);
  EXPECT_GT(office.overview->records_waiting, 0) << "the cancel came before the last unit";

  s->tap("Sync");
  s->settle();
  s->frame();
  ASSERT_TRUE(office.overview);
  EXPECT_EQ(office.overview->records_waiting, 0);
  expect_server_holds(as_superuser(db), tablet.file(), 1);
}

TEST(OfficeSyncPanel, WithoutANetworkThePanelSaysSoAndFieldWorkGoesOn) {
  // Nothing listens on port 1 of this machine: the office is out of reach.
  Tablet tablet("office-panel-offline", 1, "host=127.0.0.1 port=1 user=tablet_a dbname=rockface");
  ui::HeadlessSession* s = &tablet.ui();
  const std::string before = project_content(tablet.file());
  s->tap("Sync");
  s->settle();
  s->frame();
  const ui::OfficeState& office = tablet.office();
  EXPECT_NE(joined(office.lines).find("No network"), std::string::npos) << joined(office.lines);
  EXPECT_NE(joined(office.lines).find("Nothing is lost"), std::string::npos);
  ASSERT_TRUE(office.overview);
  EXPECT_FALSE(office.overview->ever_synced);
  // The rest of the tablet is untouched and answers.
  s->tap("Mapping");
  s->tap("Project");
  EXPECT_FALSE(s->state().task.running());
  EXPECT_EQ(first_difference(project_content(tablet.file()), before), "");
}

}  // namespace
}  // namespace rockface::office_test

// A sync killed at every point: a child process syncs and dies by SIGKILL
// right before its n-th server round trip (each one a progress step), for
// every n a whole sync makes; after each kill a completing sync runs, and
// the server must then hold exactly the tablet's records, each once (no
// duplicate revision from a unit sent twice), and every photograph and mesh
// whole and hashing to its name. Then a network cut: the server stopped in
// the middle of a sync, the sync failing with "connection lost", the
// tablet's data untouched, and the next sync completing it.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

#include "core/common/progress.h"
#include "storage/office/pg_connection.h"
#include "storage/office/sync_push.h"
#include "tests/storage/office/office_environment.h"
#include "tests/storage/office/tablet_projects.h"
#include "tests/support/sample_records.h"

namespace rockface::office_test {
namespace {

namespace fs = std::filesystem;
using storage::office::sync_project;
using storage::office::SyncOptions;

// Counts steps; with kill_at > 0, dies at that step. With a callback, runs
// it at step `at` instead.
class StepProgress : public Progress {
 public:
  explicit StepProgress(int kill_at = 0) : kill_at_(kill_at) {}
  void report(std::string_view, double) override {
    ++steps_;
    if (kill_at_ > 0 && steps_ == kill_at_) ::raise(SIGKILL);
    if (on_step_ && steps_ == at_) on_step_();
  }
  bool cancel_requested() const override { return false; }
  int steps() const { return steps_; }
  void at(int step, std::function<void()> f) {
    at_ = step;
    on_step_ = std::move(f);
  }

 private:
  int kill_at_;
  int steps_ = 0;
  int at_ = 0;
  std::function<void()> on_step_;
};

SyncOptions small_chunks() {
  SyncOptions o;
  o.chunk_bytes = 4096;
  return o;
}

// Returns whether the child died by SIGKILL.
bool sync_killed_at(const fs::path& project, const std::string& server, int kill_at) {
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    int code = 0;
    try {
      StepProgress p(kill_at);
      sync_project(project, server, small_chunks(), p);
    } catch (...) {
      code = 3;
    }
    ::_exit(code);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) return WTERMSIG(status) == SIGKILL;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("the sync failed without being killed");
  return false;
}

TEST(OfficeSyncKills, EveryKillPointIsCompletedByTheNextSync) {
  storage::test::TempDir dir("office-kills");
  TabletProject a;
  a.visits = 3;
  a.image_width = 200;
  a.image_height = 150;
  // How many steps a whole sync takes, on a first database.
  int steps = 0;
  {
    const std::string db = fresh_database();
    make_tablet_project(dir / "count.rockface", a);
    StepProgress p;
    sync_project(dir / "count.rockface", as_role(db, "tablet_a"), small_chunks(), p);
    steps = p.steps();
  }
  ASSERT_GE(steps, 50) << "at least 50 kill points";
  std::printf("a whole sync of the test project: %d kill points\n", steps);
  int killed = 0;
  for (int n = 1; n <= steps; ++n) {
    SCOPED_TRACE("killed before step " + std::to_string(n) + " of " + std::to_string(steps));
    const std::string db = fresh_database();
    const fs::path project = dir / ("k" + std::to_string(n) + ".rockface");
    fs::copy_file(dir / "count.rockface", project);
    // The copy carries the count run's record of what it synced where (another
    // database, another server id): this server is new to it.
    const std::string before = project_content(project);
    killed += sync_killed_at(project, as_role(db, "tablet_a"), n) ? 1 : 0;
    NoProgress none;
    sync_project(project, as_role(db, "tablet_a"), small_chunks(), none);
    expect_server_holds(as_superuser(db), project, 1);
    EXPECT_EQ(first_difference(project_content(project), before), "");
    server().psql("DROP DATABASE " + db + " WITH (FORCE)", "postgres");
    fs::remove(project);
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_EQ(killed, steps) << "every step was a kill point";
}

TEST(OfficeSyncKills, ANetworkCutMidSyncLosesNothingAndTheNextSyncCompletes) {
  const std::string db = fresh_database();
  storage::test::TempDir dir("office-cut");
  TabletProject a;
  a.visits = 2;
  make_tablet_project(dir / "a.rockface", a);
  const std::string before = project_content(dir / "a.rockface");
  StepProgress p;
  // Half-way through the photographs the server goes away.
  p.at(12, [] { server().stop(); });
  try {
    sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), p);
    ADD_FAILURE() << "the sync went on without its server";
  } catch (const storage::office::ServerError& e) {
    EXPECT_TRUE(e.connection_lost()) << e.what();
  }
  server().start();
  EXPECT_EQ(first_difference(project_content(dir / "a.rockface"), before), "");
  const auto status = storage::office::sync_status(dir / "a.rockface");
  EXPECT_NE(status.last_outcome.find("interrupted"), std::string::npos) << status.last_outcome;
  NoProgress none;
  const auto r = sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
  EXPECT_EQ(r.units_sent, 3);
  expect_server_holds(as_superuser(db), dir / "a.rockface", 1);
  // A server that is not there at all: the sync says so at once.
  server().stop();
  try {
    sync_project(dir / "a.rockface", as_role(db, "tablet_a"), small_chunks(), none);
    ADD_FAILURE() << "synced to a stopped server";
  } catch (const storage::office::ServerError& e) {
    EXPECT_TRUE(e.connection_lost());
    EXPECT_NE(std::string(e.what()).find("cannot connect"), std::string::npos) << e.what();
  }
  server().start();
}

}  // namespace
}  // namespace rockface::office_test

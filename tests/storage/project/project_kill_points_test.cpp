// A flat battery at every write: each of the project store's operations
// (create, capture save, model save, analysis save, upgrade of a version-1
// file) runs in a child process that kills itself with SIGKILL right before
// its n-th write, sync or truncate call, for every n the operation makes
// (FaultyVfs::arm_kill). After every kill the project opens with the plain
// SQLite VFS, passes the full integrity check and holds exactly what was
// committed before, or that plus the complete new record: never half of it,
// never less.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <functional>
#include <sstream>
#include <string_view>

#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "tests/storage/project/faulty_vfs.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

namespace fs = std::filesystem;

std::size_t digest(const std::vector<std::uint8_t>& bytes) {
  return std::hash<std::string_view>{}(
      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

// What a project holds, without the times the store stamps on records:
// equal for two files with the same committed content.
std::string content_of(const fs::path& file) {
  auto store = ProjectStore::open(file);
  const IntegrityReport report = store.check_integrity(OpenOptions::Check::full);
  if (!report.ok)
    throw std::runtime_error("integrity check failed: " +
                             (report.problems.empty() ? "" : report.problems.front()));
  std::ostringstream s;
  s << "version " << store.schema_version() << "; project " << store.project().name << "\n";
  s << "visits " << store.list_visits().size() << "\n";
  for (const auto& summary : store.list_captures()) {
    const Capture c = store.load_capture(summary.id);
    s << "capture " << c.label << " " << digest(c.left.bytes) << " " << digest(c.right.bytes)
      << "\n";
  }
  for (const auto& summary : store.list_models()) {
    const Model m = store.load_model(summary.id);
    s << "model " << m.preset << " " << m.mesh.vertices.size() << " " << m.mesh.faces.size()
      << "\n";
  }
  for (const auto& run : store.list_analyses()) {
    const AnalysisRun a = store.load_analysis(run.id);
    s << "analysis " << a.preset << " " << a.blocks.size() << "\n";
  }
  // The log agrees with the data: an entry per save, committed with it.
  s << "actions " << store.list_actions().size() << "\n";
  return s.str();
}

// Runs `work` in a child that dies right before its `kill_at`-th write-like
// call (0: never). Returns whether the child was killed (the operation made
// at least that many calls); throws when it failed otherwise.
bool run_killed(const std::function<void()>& work, int kill_at) {
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    int code = 0;
    try {
      test::FaultyVfs::arm_kill(kill_at);
      work();
    } catch (...) {
      code = 3;
    }
    ::_exit(code);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) return true;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return false;
  throw std::runtime_error("the child failed (status " + std::to_string(status) + ")");
}

// One operation on a project in a known state.
struct Operation {
  std::string name;
  std::function<void(const fs::path&)> prepare;  // makes the state before (may make no file)
  std::function<void(const fs::path&)> run;      // the operation, through the faulty VFS
};

OpenOptions through_faulty_vfs() {
  OpenOptions o;
  o.vfs = test::FaultyVfs::kName;
  return o;
}

void project_with_a_capture(const fs::path& file) {
  auto store = ProjectStore::create(file, test::sample_project());
  const RecordId visit = store.begin_visit("tablet");
  store.save_capture(test::sample_capture(visit, 1, 320, 240));
}

std::vector<Operation> operations() {
  std::vector<Operation> ops;
  ops.push_back({"create", [](const fs::path&) {},
                 [](const fs::path& file) {
                   ProjectStore::create(file, test::sample_project(), through_faulty_vfs());
                 }});
  ops.push_back({"capture save", project_with_a_capture, [](const fs::path& file) {
                   auto store = ProjectStore::open(file, through_faulty_vfs());
                   Capture c = test::sample_capture(*store.latest_visit(), 2, 320, 240);
                   c.label = "the killed save";
                   store.save_capture(c);
                 }});
  ops.push_back({"model save", project_with_a_capture, [](const fs::path& file) {
                   auto store = ProjectStore::open(file, through_faulty_vfs());
                   store.save_model(test::sample_model(store.list_captures().front().id));
                 }});
  ops.push_back({"analysis save", project_with_a_capture, [](const fs::path& file) {
                   auto store = ProjectStore::open(file, through_faulty_vfs());
                   store.save_analysis(test::sample_analysis(*store.latest_visit(), std::nullopt));
                 }});
  ops.push_back({"upgrade",
                 [](const fs::path& file) {
                   sqlite::Connection db(file, sqlite::Connection::Access::read_write_create);
                   schema::create_version_1(db);
                   db.exec("PRAGMA journal_mode = WAL", "test");
                   sqlite::WriteTransaction tx(db, "test");
                   db.exec(
                       "INSERT INTO project VALUES (1, 'old', 0, 0, 0, '', "
                       "'2025-01-01T00:00:00.000Z', 'v1');"
                       "INSERT INTO visit VALUES (1, '2025-01-01T00:00:00.000Z', 'tablet', '')",
                       "test");
                   sqlite::Statement st(db,
                                        "INSERT INTO capture (visit_id, label, taken_at, "
                                        "created_at, left_format, right_format, left_image, "
                                        "right_image) VALUES (1, ?, '', '', 'jpeg', 'jpeg', ?, ?)",
                                        "test");
                   for (int i = 0; i < 2; ++i) {
                     st.reset();
                     st.bind(1, "pair " + std::to_string(i))
                         .bind_blob(2, test::encoded_image(160, 120, 10 + 2 * i, ".jpg"))
                         .bind_blob(3, test::encoded_image(160, 120, 11 + 2 * i, ".jpg"));
                     st.run();
                   }
                   tx.commit();
                 },
                 [](const fs::path& file) { ProjectStore::open(file, through_faulty_vfs()); }});
  return ops;
}

void remove_project(const fs::path& file) {
  for (const char* side : {"", "-wal", "-shm", "-journal"}) fs::remove(file.string() + side);
}

// A project file with its log, as a kill would find it on the card.
void copy_project(const fs::path& from, const fs::path& to) {
  remove_project(to);
  for (const char* side : {"", "-wal", "-journal"})
    if (fs::exists(from.string() + side)) fs::copy_file(from.string() + side, to.string() + side);
}

// The content of the project before the operation ("" when there is no
// file; a version-1 file is read as its upgrade would be, in a copy).
std::string content_before(const fs::path& file, const fs::path& scratch) {
  if (!fs::exists(file)) return "";
  copy_project(file, scratch);
  const std::string c = content_of(scratch);
  remove_project(scratch);
  return c;
}

// The write-like calls `op` makes when nothing kills it.
int write_calls(const Operation& op, const fs::path& dir) {
  const fs::path counted = dir / "counted.rockface";
  op.prepare(counted);
  test::FaultyVfs::arm(0);
  op.run(counted);
  const int calls = test::FaultyVfs::calls();
  remove_project(counted);
  return calls;
}

const Operation& operation_named(const std::string& name) {
  static const std::vector<Operation> ops = operations();
  for (const Operation& op : ops)
    if (op.name == name) return op;
  throw std::logic_error("no operation " + name);
}

}  // namespace

// Issue 16: at least 100 distinct kill points across the five operations.
TEST(ProjectKillPoints, TheFiveOperationsMakeAtLeastAHundredWrites) {
  test::FaultyVfs::install();
  test::TempDir dir("kill-points-count");
  int total = 0;
  for (const Operation& op : operations()) {
    const int calls = write_calls(op, dir.path());
    EXPECT_GT(calls, 3) << op.name << " writes nothing through the faulty VFS";
    RecordProperty(op.name + " write calls", calls);
    total += calls;
  }
  EXPECT_GE(total, 100);
}

// One test per operation (each kills it before every one of its writes, a
// child process each time): CTest runs them side by side.
class ProjectKillPoints : public ::testing::TestWithParam<std::string> {};

TEST_P(ProjectKillPoints, SigkillBeforeEveryWriteLosesNothingCommitted) {
  test::FaultyVfs::install();
  const Operation& op = operation_named(GetParam());
  test::TempDir dir("kill-points");
  // The number of write-like calls the operation makes.
  const bool upgrade = op.name == "upgrade";
  const int calls = write_calls(op, dir.path());
  ASSERT_GT(calls, 3) << "the operation writes nothing through the faulty VFS";

  // The state before the operation is made once, and each kill starts from
  // a copy of it (the project file with its log, as a kill would find it on
  // the card; the twin below has always been such a copy): the same bytes
  // before every kill, so the content before the operation (a version-1
  // file is read only after its upgrade) and after it run without a kill, on
  // a copy, are the same for every n and are taken once.
  const fs::path prepared = dir / "prepared.rockface";
  op.prepare(prepared);
  const std::string before = upgrade ? "" : content_before(prepared, dir / "scratch.rockface");
  const fs::path twin = dir / "twin.rockface";
  copy_project(prepared, twin);
  ASSERT_FALSE(run_killed([&] { op.run(twin); }, 0));
  const std::string after = content_of(twin);
  remove_project(twin);

  int old_state = 0;
  for (int n = 1; n <= calls; ++n) {
    SCOPED_TRACE("killed before write call " + std::to_string(n));
    const fs::path file = dir / ("kill-" + std::to_string(n) + ".rockface");
    copy_project(prepared, file);
    ASSERT_TRUE(run_killed([&] { op.run(file); }, n));
    if (!fs::exists(file)) {
      // Only a project being created may be absent, and then it can be
      // created afresh (no leftover blocks the name).
      EXPECT_EQ(op.name, "create");
      ProjectStore::create(file, test::sample_project());
      ++old_state;
    } else {
      std::string now;
      ASSERT_NO_THROW(now = content_of(file));
      if (upgrade) {
        // Opening upgrades: every record of version 1 is there either way.
        EXPECT_EQ(now, after);
      } else {
        EXPECT_TRUE(now == before || now == after) << "after the kill:\n"
                                                   << now << "before:\n"
                                                   << before << "complete:\n"
                                                   << after;
        if (now == before) ++old_state;
      }
    }
    remove_project(file);
  }
  // The first kills come before anything is committed.
  if (!upgrade) {
    EXPECT_GE(old_state, 1);
  }
  RecordProperty("kill_points", calls);
}

INSTANTIATE_TEST_SUITE_P(EachOperation, ProjectKillPoints,
                         ::testing::Values("create", "capture save", "model save", "analysis save",
                                           "upgrade"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name;
                           for (char c : info.param) name += c == ' ' ? '_' : c;
                           return name;
                         });

}  // namespace rockface::storage

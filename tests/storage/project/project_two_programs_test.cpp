// Two programs on one project: the tablet UI holds the project open (its UI
// thread's store, and the stores its workers open and close beside it) while
// another rockface program (a verb run on the desktop, the office sync)
// opens it, writes and ends. SQLite's locks serialise the two: nothing
// either one committed is lost and the file stays intact.
//
// The UI's side runs in this process. The other program is this test binary
// run again (a fresh process: a forked child would inherit SQLite's view of
// this process's locks and open files), told by the environment what to do;
// it does that before any test runs and ends.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <string>

#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFileVar = "ROCKFACE_TWO_PROGRAMS_FILE";
constexpr const char* kVisitVar = "ROCKFACE_TWO_PROGRAMS_VISIT";
constexpr const char* kSeesVar = "ROCKFACE_TWO_PROGRAMS_SEES";
constexpr const char* kWaitVar = "ROCKFACE_TWO_PROGRAMS_WAIT_MS";
constexpr const char* kSaysVar = "ROCKFACE_TWO_PROGRAMS_SAYS";

// The other program: opens the project (waiting for a write lock up to the
// environment's wait), checks it whole (full integrity check) and that it
// holds the number of visits the environment says (all that both programs
// committed before), starts a visit named by the environment with one
// action logged in it, and ends. Exit status 0 when all of that held, else
// 3 with the reason on stderr and in the file the environment names.
const bool kIsTheOtherProgram = [] {
  const char* file = std::getenv(kFileVar);
  const char* source = std::getenv(kVisitVar);
  const char* sees = std::getenv(kSeesVar);
  const char* wait_ms = std::getenv(kWaitVar);
  const char* says = std::getenv(kSaysVar);
  if (file == nullptr || source == nullptr || sees == nullptr || wait_ms == nullptr ||
      says == nullptr)
    return false;
  int code = 0;
  try {
    OpenOptions options;
    options.busy_timeout = std::chrono::milliseconds(std::stol(wait_ms));
    auto store = ProjectStore::open(file, options);
    const IntegrityReport report = store.check_integrity(OpenOptions::Check::full);
    if (!report.ok)
      throw std::runtime_error("integrity check: " + testing::PrintToString(report.problems));
    const std::size_t visits = store.list_visits().size();
    if (visits != std::stoul(sees))
      throw std::runtime_error("sees " + std::to_string(visits) + " visits, not " + sees);
    const RecordId visit = store.begin_visit(source);
    store.log_action(visit, "measured", source);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "the other program, visit %s: %s\n", source, e.what());
    std::ofstream(says) << e.what();
    code = 3;
  }
  std::fflush(stderr);
  ::_exit(code);
}();

// How the other program ended: "" when it stored its visit, else what it
// said (or how it ended when it said nothing).
struct OtherProgram {
  fs::path file;
  std::chrono::milliseconds wait{30000};  // ProjectStore's default
  std::string writes(const std::string& source, std::size_t sees) const {
    const fs::path says = file.string() + "." + std::to_string(::getpid()) + ".says";
    std::error_code ec;
    fs::remove(says, ec);
    const pid_t pid = ::fork();
    if (pid < 0) return "fork failed";
    if (pid == 0) {
      ::setenv(kFileVar, file.c_str(), 1);
      ::setenv(kVisitVar, source.c_str(), 1);
      ::setenv(kSeesVar, std::to_string(sees).c_str(), 1);
      ::setenv(kWaitVar, std::to_string(wait.count()).c_str(), 1);
      ::setenv(kSaysVar, says.c_str(), 1);
      const char* argv[] = {"storage_tests", nullptr};
      ::execv("/proc/self/exe", const_cast<char* const*>(argv));
      ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
    std::ifstream in(says);
    std::string said((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fs::remove(says, ec);
    if (!said.empty()) return said;
    return "the other program failed (wait status " + std::to_string(status) + ")";
  }
};

// Runs the other program on `file` and waits for it to end: "" when it
// stored its visit `source` after seeing `sees` visits in an intact file.
std::string other_program_writes(const fs::path& file, const std::string& source,
                                 std::size_t sees) {
  return OtherProgram{file}.writes(source, sees);
}

std::set<std::string> sources(const std::vector<Visit>& visits) {
  std::set<std::string> out;
  for (const auto& v : visits) out.insert(v.source);
  return out;
}

// A worker of the UI: opens its own store on the project, reads, closes.
void worker_reads(const fs::path& file) {
  OpenOptions read;
  read.read_only = true;
  ProjectStore::open(file, read).list_visits();
}

TEST(ProjectTwoPrograms, AVerbWritesWhileTheUiHoldsTheProjectOpen) {
  test::TempDir dir("two-programs");
  const fs::path file = dir / "site.rockface";
  ProjectStore::create(file, test::sample_project()).begin_visit("replay");
  std::set<std::string> committed{"replay"};

  // The UI's store stays open throughout; each round a worker of the UI
  // reads, a verb writes and ends, the UI sees it and saves a visit.
  std::optional<ProjectStore> ui(ProjectStore::open(file));
  for (int round = 1; round <= 3; ++round) {
    ASSERT_NO_THROW(worker_reads(file)) << "round " << round;
    const std::string verb = "measure " + std::to_string(round);
    ASSERT_EQ(other_program_writes(file, verb, committed.size()), "") << "round " << round;
    committed.insert(verb);
    EXPECT_EQ(sources(ui->list_visits()), committed) << "the UI sees what the verb committed";
    const std::string tablet = "tablet " + std::to_string(round);
    ui->log_action(ui->begin_visit(tablet), "trace saved", tablet);
    committed.insert(tablet);
  }
  ASSERT_EQ(other_program_writes(file, "sync", committed.size()), "")
      << "a program opening the file while the UI still holds it finds it intact";
  committed.insert("sync");
  ui.reset();  // the UI closes the project

  auto store = ProjectStore::open(file);
  const IntegrityReport report = store.check_integrity(OpenOptions::Check::full);
  EXPECT_TRUE(report.ok) << testing::PrintToString(report.problems);
  EXPECT_EQ(sources(store.list_visits()), committed);
  std::set<std::string> logged;
  for (const auto& a : store.list_actions())
    if (a.action == "trace saved" || a.action == "measured") logged.insert(a.detail);
  committed.erase("replay");
  EXPECT_EQ(logged, committed) << "each program's log entries, committed with its visits";
}

// The other program cannot wait for ever: when the UI keeps writing past its
// wait (a long save), it stops before storing anything, saying which file
// and what to do; the UI's save and everything before stay.
TEST(ProjectTwoPrograms, AVerbStopsCleanlyWhenTheUiKeepsWritingPastItsWait) {
  test::TempDir dir("two-programs-busy");
  const fs::path file = dir / "site.rockface";
  ProjectStore::create(file, test::sample_project()).begin_visit("replay");
  auto ui = ProjectStore::open(file);
  {
    // The UI's save, in progress while the verb runs (the store's own
    // transaction, opened on a connection of the UI's).
    sqlite::Connection saving(file, sqlite::Connection::Access::read_write);
    sqlite::WriteTransaction save(saving, "saving a capture");
    saving.exec("INSERT INTO visit (started_at, source, note) VALUES ('2026-11-26', 'tablet', '')",
                "saving a capture");
    OtherProgram verb{file, std::chrono::milliseconds(300)};
    const std::string said = verb.writes("measure", 1);
    EXPECT_NE(said.find(file.string()), std::string::npos) << said;
    EXPECT_NE(said.find("busy"), std::string::npos) << said;
    EXPECT_NE(said.find("nothing of this action was saved"), std::string::npos) << said;
    EXPECT_NE(said.find("run it again"), std::string::npos) << said;
    save.commit();
  }
  EXPECT_EQ(sources(ui.list_visits()), (std::set<std::string>{"replay", "tablet"}));
  // Run again once the UI's save is done, it stores its visit.
  EXPECT_EQ(other_program_writes(file, "measure", 2), "");

  auto store = ProjectStore::open(file);
  const IntegrityReport report = store.check_integrity(OpenOptions::Check::full);
  EXPECT_TRUE(report.ok) << testing::PrintToString(report.problems);
  EXPECT_EQ(sources(store.list_visits()), (std::set<std::string>{"replay", "tablet", "measure"}));
}

// The cause of the damage the first test catches, seen directly: this
// process's lock on the project (SQLite's shared lock, which tells another
// program ending its write that the project is still in use here) lasts
// while another store of this process opens and closes the file.
std::size_t posix_locks_of_this_process(const fs::path& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return 0;
  // /proc/locks: "1: POSIX  ADVISORY  READ 1234 fe:00:10954881 1073741826 1073742335"
  const std::string pid = " " + std::to_string(::getpid()) + " ";
  const std::string inode = ":" + std::to_string(st.st_ino) + " ";
  std::ifstream in("/proc/locks");
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);)
    n += line.find("POSIX") != std::string::npos && line.find(pid) != std::string::npos &&
         line.find(inode) != std::string::npos;
  return n;
}

TEST(ProjectTwoPrograms, TheUiKeepsItsLockWhileAWorkerOpensTheProject) {
  test::TempDir dir("own-lock");
  const fs::path file = dir / "site.rockface";
  ProjectStore::create(file, test::sample_project()).begin_visit("replay");
  auto ui = ProjectStore::open(file);
  ui.list_visits();
  ASSERT_GT(posix_locks_of_this_process(file), 0u) << "an open WAL project is share-locked";
  worker_reads(file);
  ProjectStore::open(file).begin_visit("worker");
  EXPECT_GT(posix_locks_of_this_process(file), 0u)
      << "another store's opening and closing dropped the UI's lock on " << file;
}

}  // namespace
}  // namespace rockface::storage

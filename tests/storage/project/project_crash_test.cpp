// A flat battery in the middle of a save: a child process saving a capture is
// killed with SIGKILL at many moments spread over the save. After every kill
// the project opens, passes the full integrity check, holds every capture
// committed before byte for byte, and holds the new capture either complete
// or not at all.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <map>
#include <random>
#include <string_view>
#include <thread>

#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using Clock = std::chrono::steady_clock;

std::size_t digest(const std::vector<std::uint8_t>& bytes) {
  return std::hash<std::string_view>{}(
      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

// An image-sized byte string with a JPEG signature; the content differs per
// seed so that no two saves share an image (shared images are stored once,
// which would make later saves shorter than the first).
std::vector<std::uint8_t> jpeg_sized_bytes(std::size_t size, std::uint64_t seed) {
  std::vector<std::uint8_t> bytes(size);
  std::mt19937_64 rng(seed);
  for (std::size_t i = 0; i + 8 <= size; i += 8) {
    const std::uint64_t v = rng();
    std::memcpy(bytes.data() + i, &v, 8);
  }
  bytes[0] = 0xFF;
  bytes[1] = 0xD8;
  bytes[2] = 0xFF;
  bytes[size - 2] = 0xFF;
  bytes[size - 1] = 0xD9;
  return bytes;
}

struct Expected {
  std::size_t left, right;
};

// Forks a child that runs `work` (which opens the project itself) and
// writes one byte to a pipe right before the part to be interrupted
// (`ready()`). Measures the time from that byte to the child's end into
// `duration`; kills the child with SIGKILL `kill_after` past the byte when
// given. Returns whether the child ended by itself.
bool run_child(const std::function<void(const std::function<void()>& ready)>& work,
               std::optional<std::chrono::microseconds> kill_after, Clock::duration* duration) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    ::close(pipe_fds[0]);
    int code = 0;
    try {
      work([&] {
        const char go = 's';
        if (::write(pipe_fds[1], &go, 1) != 1) ::_exit(4);
      });
    } catch (...) {
      code = 3;
    }
    ::_exit(code);
  }
  ::close(pipe_fds[1]);
  char go = 0;
  const bool signalled = ::read(pipe_fds[0], &go, 1) == 1;
  const auto start = Clock::now();
  ::close(pipe_fds[0]);
  if (signalled && kill_after) {
    std::this_thread::sleep_for(*kill_after);
    ::kill(pid, SIGKILL);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (duration) *duration = Clock::now() - start;
  if (!signalled) throw std::runtime_error("the child failed before its critical part");
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    throw std::runtime_error("the child failed with code " + std::to_string(WEXITSTATUS(status)));
  return WIFEXITED(status);
}

bool run_child_save(const std::filesystem::path& file, const Capture& capture,
                    std::optional<std::chrono::microseconds> kill_after,
                    Clock::duration* save_time) {
  return run_child(
      [&](const std::function<void()>& ready) {
        auto store = ProjectStore::open(file);
        ready();
        store.save_capture(capture);
      },
      kill_after, save_time);
}

TEST(ProjectCrash, SigkillDuringCaptureSaveLosesOnlyThatSave) {
  test::TempDir dir("crash");
  const auto file = dir / "site.rockface";
  std::map<std::string, Expected> committed;  // label -> image digests
  RecordId visit = 0;
  {
    auto store = ProjectStore::create(file, test::sample_project());
    visit = store.begin_visit("tablet");
    for (int i = 0; i < 2; ++i) {
      Capture c = test::sample_capture(visit, i);
      store.save_capture(c);
      committed[c.label] = {digest(c.left.bytes), digest(c.right.bytes)};
    }
  }
  // Two 1 MB images: big enough that a save (image pages, WAL append, fsync)
  // lasts long enough to be hit at 30 distinct moments.
  constexpr std::size_t kImageBytes = 1 << 20;
  auto make_capture = [&](int n) {
    Capture c;
    c.visit_id = visit;
    c.label = "killed save " + std::to_string(n);
    c.left.bytes = jpeg_sized_bytes(kImageBytes, 2 * static_cast<std::uint64_t>(n) + 100);
    c.right.bytes = jpeg_sized_bytes(kImageBytes, 2 * static_cast<std::uint64_t>(n) + 101);
    c.settings = {{"iso", "400"}};
    return c;
  };

  // The duration of an uninterrupted save, measured the same way (child,
  // from its signal to its exit); the kill times spread over 0 .. 1.2 of it.
  Clock::duration full_save{};
  {
    Capture c = make_capture(0);
    ASSERT_TRUE(run_child_save(file, c, std::nullopt, &full_save));
    committed[c.label] = {digest(c.left.bytes), digest(c.right.bytes)};
  }
  const auto full_us = std::chrono::duration_cast<std::chrono::microseconds>(full_save);
  RecordProperty("uninterrupted_save_us", static_cast<int>(full_us.count()));

  constexpr int kKills = 30;
  int interrupted = 0, completed = 0;
  for (int k = 0; k < kKills; ++k) {
    SCOPED_TRACE("kill " + std::to_string(k));
    const Capture c = make_capture(k + 1);
    const auto kill_after = std::chrono::microseconds(full_us.count() * 12 * k / (10 * kKills));
    run_child_save(file, c, kill_after, nullptr);

    auto store = ProjectStore::open(file);
    const IntegrityReport report = store.check_integrity(OpenOptions::Check::full);
    ASSERT_TRUE(report.ok) << (report.problems.empty() ? "" : report.problems.front());
    const auto captures = store.list_captures();
    bool saved = false;
    std::size_t found_committed = 0;
    for (const auto& summary : captures) {
      const Capture got = store.load_capture(summary.id);
      if (got.label == c.label) {
        // Either all of it or nothing: a capture that is there is complete.
        saved = true;
        EXPECT_EQ(digest(got.left.bytes), digest(c.left.bytes));
        EXPECT_EQ(digest(got.right.bytes), digest(c.right.bytes));
        EXPECT_EQ(got.settings, c.settings);
        continue;
      }
      auto it = committed.find(got.label);
      ASSERT_NE(it, committed.end()) << "unexpected capture " << got.label;
      EXPECT_EQ(digest(got.left.bytes), it->second.left) << got.label;
      EXPECT_EQ(digest(got.right.bytes), it->second.right) << got.label;
      ++found_committed;
    }
    EXPECT_EQ(found_committed, committed.size()) << "a committed capture was lost";
    // The log agrees with the data: a "capture saved" entry per capture.
    std::size_t logged = 0;
    for (const auto& e : store.list_actions())
      if (e.action == "capture saved") ++logged;
    EXPECT_EQ(logged, captures.size());
    if (saved) {
      committed[c.label] = {digest(c.left.bytes), digest(c.right.bytes)};
      ++completed;
    } else {
      ++interrupted;
    }
  }
  RecordProperty("kills_interrupting_the_save", interrupted);
  RecordProperty("kills_after_commit", completed);
  // The earliest kills come at a few percent of the save's duration, so at
  // least those must have interrupted it; otherwise the test exercised
  // nothing.
  EXPECT_GE(interrupted, 1);
}

// The upgrade of a version-1 project (one transaction that rebuilds the
// capture table around its images) killed at moments spread over its
// duration: afterwards the file is either still version 1 or fully version
// 2, and opening it (upgrading if needed) gives back every image.
class UpgradeCrash : public ::testing::TestWithParam<bool> {};

TEST_P(UpgradeCrash, SigkillDuringUpgradeLeavesOldOrNewNeverHalf) {
  // true: the version-1 file is in WAL mode, as version 1 wrote it; false:
  // in rollback-journal mode, as a copy made by other SQLite tools may be
  // (the kill then can leave a hot journal that opening must undo).
  const bool wal = GetParam();
  test::TempDir dir(wal ? "crash-upgrade-wal" : "crash-upgrade-rollback");
  const auto original = dir / "v1.rockface";
  constexpr int kCaptures = 3;
  constexpr std::size_t kImageBytes = 512 << 10;
  std::vector<std::pair<std::size_t, std::size_t>> digests;
  {
    sqlite::Connection db(original, sqlite::Connection::Access::read_write_create);
    schema::create_version_1(db);
    if (wal) db.exec("PRAGMA journal_mode = WAL", "test");
    sqlite::WriteTransaction tx(db, "test");
    db.exec(
        "INSERT INTO project VALUES (1, 'old', 0, 0, 0, '', '2025-01-01T00:00:00.000Z', 'v1');"
        "INSERT INTO visit VALUES (1, '2025-01-01T00:00:00.000Z', 'tablet', '')",
        "test");
    sqlite::Statement st(db,
                         "INSERT INTO capture (visit_id, label, taken_at, created_at, "
                         "left_format, right_format, left_image, right_image) VALUES (1, ?, '', "
                         "'', 'jpeg', 'jpeg', ?, ?)",
                         "test");
    for (int i = 0; i < kCaptures; ++i) {
      const auto left = jpeg_sized_bytes(kImageBytes, 1000 + 2 * i);
      const auto right = jpeg_sized_bytes(kImageBytes, 1001 + 2 * i);
      st.reset();
      st.bind(1, "pair " + std::to_string(i)).bind_blob(2, left).bind_blob(3, right);
      st.run();
      digests.emplace_back(digest(left), digest(right));
    }
    tx.commit();
  }
  const auto upgrade = [&](const std::filesystem::path& file) {
    return [file](const std::function<void()>& ready) {
      ready();
      ProjectStore::open(file);
    };
  };
  Clock::duration full{};
  {
    const auto copy = dir / "timing.rockface";
    std::filesystem::copy_file(original, copy);
    ASSERT_TRUE(run_child(upgrade(copy), std::nullopt, &full));
  }
  const auto full_us = std::chrono::duration_cast<std::chrono::microseconds>(full);
  RecordProperty("uninterrupted_upgrade_us", static_cast<int>(full_us.count()));

  constexpr int kKills = 10;
  int still_old = 0;
  for (int k = 0; k < kKills; ++k) {
    SCOPED_TRACE("kill " + std::to_string(k));
    const auto file = dir / ("v1-" + std::to_string(k) + ".rockface");
    std::filesystem::copy_file(original, file);
    run_child(upgrade(file), std::chrono::microseconds(full_us.count() * 12 * k / (10 * kKills)),
              nullptr);
    // The state the kill left (file and its log or journal), twice: one copy
    // for a raw look at its version, one that ProjectStore::open must recover
    // by itself.
    const auto same = dir / ("as-left-" + std::to_string(k) + ".rockface");
    for (const char* side : {"", "-wal", "-journal"}) {
      const std::filesystem::path from = file.string() + side;
      if (std::filesystem::exists(from))
        std::filesystem::copy_file(from, same.string() + side,
                                   std::filesystem::copy_options::overwrite_existing);
    }
    {
      // A plain writable SQLite opening recovers (rolls back or replays the
      // log) exactly as SQLite would for any program; then the version says
      // which side of the upgrade's commit the kill fell on.
      sqlite::Connection raw(file, sqlite::Connection::Access::read_write);
      const int version = schema::version_of(raw);
      EXPECT_TRUE(version == 1 || version == schema::kCurrentVersion) << version;
      if (version == 1) ++still_old;
    }
    auto store = ProjectStore::open(same);
    EXPECT_EQ(store.schema_version(), schema::kCurrentVersion);
    ASSERT_TRUE(store.check_integrity(OpenOptions::Check::full).ok);
    const auto captures = store.list_captures();
    ASSERT_EQ(captures.size(), static_cast<std::size_t>(kCaptures));
    for (int i = 0; i < kCaptures; ++i) {
      const Capture c = store.load_capture(captures[static_cast<std::size_t>(i)].id);
      EXPECT_EQ(digest(c.left.bytes), digests[static_cast<std::size_t>(i)].first);
      EXPECT_EQ(digest(c.right.bytes), digests[static_cast<std::size_t>(i)].second);
    }
    std::filesystem::remove(file);
  }
  RecordProperty("kills_before_upgrade_commit", still_old);
  EXPECT_GE(still_old, 1) << "no kill interrupted the upgrade";
}

INSTANTIATE_TEST_SUITE_P(JournalModes, UpgradeCrash, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "wal" : "rollback"; });

}  // namespace
}  // namespace rockface::storage

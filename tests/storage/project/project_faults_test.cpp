// A full card, a failing card, a file moved away, and files that are not
// projects: every failure is a clear error naming the file, nothing committed
// before is lost, and a file that is not a healthy project is never written.
#include <gtest/gtest.h>

#include <sqlite3.h>
#include <sys/mount.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/common/error.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "tests/storage/project/faulty_vfs.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

// What a reopened project holds: the capture labels, in order.
std::vector<std::string> capture_labels(const fs::path& file) {
  auto store = ProjectStore::open(file);
  EXPECT_TRUE(store.check_integrity(OpenOptions::Check::full).ok);
  std::vector<std::string> labels;
  for (const auto& c : store.list_captures()) labels.push_back(c.label);
  return labels;
}

TEST(ProjectFaults, SizeLimitReachedDuringASaveFailsCleanly) {
  TempDir dir("full-limit");
  const auto file = dir / "site.rockface";
  RecordId visit = 0;
  {
    auto store = ProjectStore::create(file, test::sample_project());
    visit = store.begin_visit("tablet");
    store.save_capture(test::sample_capture(visit, 1));
  }
  const auto size = static_cast<std::int64_t>(fs::file_size(file));
  {
    // SQLite's own limit (PRAGMA max_page_count): 64 KiB of room left, and a
    // capture of two 1600 x 1200 textured images (several hundred KiB).
    OpenOptions limited;
    limited.max_file_bytes = size + (64 << 10);
    auto store = ProjectStore::open(file, limited);
    const Capture big = test::sample_capture(visit, 2, 1600, 1200);
    const std::string message = message_of([&] { store.save_capture(big); });
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find("full"), std::string::npos) << message;
    // The store stays usable for what fits.
    EXPECT_NO_THROW(store.log_action(visit, "note", "card nearly full"));
  }
  EXPECT_EQ(capture_labels(file), std::vector<std::string>{"face 120 pair 1"});
  auto store = ProjectStore::open(file);
  EXPECT_EQ(store.list_actions().back().action, "note");
}

// A real full file system: a 2 MiB tmpfs. Mounting needs root and mount
// permission; without them the test says so and skips (the size-limit test
// above covers the same path through SQLite's own limit).
TEST(ProjectFaults, FullFileSystemFailsCleanly) {
  TempDir dir("full-fs");
  const fs::path mount_point = dir / "card";
  fs::create_directories(mount_point);
  if (::mount("tmpfs", mount_point.c_str(), "tmpfs", 0, "size=2m") != 0)
    GTEST_SKIP() << "cannot mount a tmpfs here: " << std::strerror(errno);
  struct Unmount {
    fs::path at;
    ~Unmount() { ::umount2(at.c_str(), MNT_DETACH); }
  } unmount{mount_point};

  const auto file = mount_point / "site.rockface";
  std::vector<std::string> saved;
  std::string message;
  {
    auto store = ProjectStore::create(file, test::sample_project());
    const RecordId visit = store.begin_visit("tablet");
    for (int i = 0; i < 20 && message.empty(); ++i) {
      const Capture c = test::sample_capture(visit, 10 + i, 800, 600);
      message = message_of([&] { store.save_capture(c); });
      if (message.empty()) saved.push_back(c.label);
    }
  }
  ASSERT_FALSE(message.empty()) << "2 MiB never filled up";
  EXPECT_FALSE(saved.empty());
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
  EXPECT_NE(message.find("full"), std::string::npos) << message;
  EXPECT_EQ(capture_labels(file), saved);
}

// The SD card's lock switch (a read-only mount): the project opens read-only
// and says why; nothing is written. Needs mount permission like the test above.
TEST(ProjectFaults, WriteProtectedCardOpensReadOnly) {
  TempDir dir("locked-card");
  const fs::path mount_point = dir / "card";
  fs::create_directories(mount_point);
  if (::mount("tmpfs", mount_point.c_str(), "tmpfs", 0, "size=4m") != 0)
    GTEST_SKIP() << "cannot mount a tmpfs here: " << std::strerror(errno);
  struct Unmount {
    fs::path at;
    ~Unmount() { ::umount2(at.c_str(), MNT_DETACH); }
  } unmount{mount_point};
  const auto file = mount_point / "site.rockface";
  Capture saved;
  {
    auto store = ProjectStore::create(file, test::sample_project());
    saved = test::sample_capture(store.begin_visit("tablet"), 1);
    store.save_capture(saved);
  }
  ASSERT_EQ(::mount(nullptr, mount_point.c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr), 0)
      << std::strerror(errno);
  auto store = ProjectStore::open(file);
  EXPECT_TRUE(store.read_only());
  EXPECT_NE(store.read_only_reason().find("write-protected"), std::string::npos);
  ASSERT_EQ(store.list_captures().size(), 1u);
  EXPECT_EQ(store.load_capture(store.list_captures()[0].id).right.bytes, saved.right.bytes);
  try {
    store.begin_visit("tablet");
    ADD_FAILURE() << "saved to a write-protected card";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("write-protected"), std::string::npos) << e.what();
  }
}

TEST(ProjectFaults, IoErrorAtEveryWriteOfASaveLeavesTheProjectWhole) {
  test::FaultyVfs::install();
  TempDir dir("io-error");
  const auto file = dir / "site.rockface";
  RecordId visit = 0;
  {
    auto store = ProjectStore::create(file, test::sample_project());
    visit = store.begin_visit("tablet");
    store.save_capture(test::sample_capture(visit, 1));
  }
  OpenOptions faulty;
  faulty.vfs = test::FaultyVfs::kName;
  // How many write/sync/truncate calls one save makes.
  const Capture probe = test::sample_capture(visit, 2, 320, 240);
  int calls_per_save = 0;
  {
    TempDir scratch("io-error-count");
    fs::copy_file(file, scratch / "copy.rockface");
    auto store = ProjectStore::open(scratch / "copy.rockface", faulty);
    test::FaultyVfs::arm(0);
    store.save_capture(probe);
    calls_per_save = test::FaultyVfs::calls();
  }
  ASSERT_GT(calls_per_save, 5);
  RecordProperty("write_calls_per_save", calls_per_save);

  std::vector<std::string> expected = {"face 120 pair 1"};
  for (int n = 1; n <= calls_per_save; ++n) {
    SCOPED_TRACE("failing from write call " + std::to_string(n));
    Capture c = test::sample_capture(visit, 2, 320, 240);
    c.label = "save " + std::to_string(n);
    std::string message;
    {
      auto store = ProjectStore::open(file, faulty);
      test::FaultyVfs::arm(n);
      message = message_of([&] { store.save_capture(c); });
      test::FaultyVfs::disarm();
    }
    EXPECT_FALSE(message.empty()) << "the failing card went unnoticed";
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find("input/output error"), std::string::npos) << message;
    const auto labels = capture_labels(file);
    // A failed fsync of the commit frame can leave the capture committed
    // (the frame reached the card, the confirmation did not): then it must
    // be complete. Otherwise it is absent.
    if (labels.size() == expected.size() + 1) {
      EXPECT_EQ(labels.back(), c.label);
      auto store = ProjectStore::open(file);
      EXPECT_EQ(store.load_capture(store.list_captures().back().id).left.bytes, c.left.bytes);
      expected.push_back(c.label);
    }
    EXPECT_EQ(labels, expected);
  }
}

TEST(ProjectFaults, ProjectMovedOrDeletedWhileOpenIsAClearError) {
  TempDir dir("moved");
  const fs::path card = dir / "card";
  fs::create_directories(card);
  {
    auto store = ProjectStore::create(card / "site.rockface", test::sample_project());
    const RecordId visit = store.begin_visit("tablet");
    store.save_capture(test::sample_capture(visit, 1));
    fs::rename(card, dir / "moved-card");
    const std::string message =
        message_of([&] { store.save_capture(test::sample_capture(visit, 2)); });
    EXPECT_NE(message.find("moved or deleted"), std::string::npos) << message;
    EXPECT_NE(message.find((card / "site.rockface").string()), std::string::npos) << message;
  }
  // Where it is now, the project opens with what was saved before the move.
  EXPECT_EQ(capture_labels(dir / "moved-card" / "site.rockface"),
            std::vector<std::string>{"face 120 pair 1"});

  // Deleted under an open store: a save would only reach a file that no
  // longer has a name (and is gone on close), so it is refused.
  auto doomed = ProjectStore::open(dir / "moved-card" / "site.rockface");
  fs::remove_all(dir / "moved-card");
  const std::string gone = message_of([&] { doomed.begin_visit("tablet"); });
  EXPECT_NE(gone.find("moved or deleted"), std::string::npos) << gone;
}

// Opening must recognise what is not a healthy project, say so, and leave the
// file exactly as it was.
class NotAProject : public ::testing::Test {
 protected:
  void expect_refused(const fs::path& file, const std::string& words) {
    const auto before = test::read_file_bytes(file);
    try {
      ProjectStore::open(file);
      ADD_FAILURE() << file << " was opened as a project";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), file.string());
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
    EXPECT_EQ(test::read_file_bytes(file), before) << "the file was changed";
  }
  TempDir dir_{"not-a-project"};
};

TEST_F(NotAProject, MissingEmptyTextAndFolder) {
  EXPECT_THROW(ProjectStore::open(dir_ / "missing.rockface"), InputError);
  EXPECT_FALSE(fs::exists(dir_ / "missing.rockface")) << "open() must not create";
  std::ofstream(dir_ / "empty.rockface").close();
  expect_refused(dir_ / "empty.rockface", "empty file");
  std::ofstream(dir_ / "notes.rockface") << "dip 45 dipdir 120\n";
  expect_refused(dir_ / "notes.rockface", "not an SQLite database");
  EXPECT_FALSE(fs::exists(dir_ / "notes.rockface-wal"));
  EXPECT_FALSE(fs::exists(dir_ / "notes.rockface-journal"));
  fs::create_directories(dir_ / "folder.rockface");
  EXPECT_THROW(ProjectStore::open(dir_ / "folder.rockface"), InputError);
}

TEST_F(NotAProject, SqliteDatabaseOfAnotherProgram) {
  const auto file = dir_ / "photos.db";
  {
    sqlite::Connection db(file, sqlite::Connection::Access::read_write_create);
    db.exec("CREATE TABLE t (x); INSERT INTO t VALUES (1)", "test");
  }
  expect_refused(file, "another program");
}

TEST_F(NotAProject, DamagedProject) {
  const auto file = dir_ / "damaged.rockface";
  {
    auto store = ProjectStore::create(file, test::sample_project());
    const RecordId visit = store.begin_visit("tablet");
    for (int i = 0; i < 3; ++i) store.save_capture(test::sample_capture(visit, i));
  }
  const auto good = test::read_file_bytes(file);
  ASSERT_GT(good.size(), 64u * 4096u);
  // Pages 2..4 hold table roots and the first rows: overwrite them with a
  // pattern, as a failing card would.
  std::vector<std::uint8_t> bad = good;
  std::fill(bad.begin() + 4096, bad.begin() + 4 * 4096, 0x5A);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bad.data()), static_cast<std::streamsize>(bad.size()));
  }
  expect_refused(file, "damaged");

  // Half the file gone (a copy interrupted): damaged, not silently shorter.
  const auto truncated = dir_ / "truncated.rockface";
  {
    std::ofstream out(truncated, std::ios::binary);
    out.write(reinterpret_cast<const char*>(good.data()),
              static_cast<std::streamsize>(good.size() / 2));
  }
  expect_refused(truncated, "damaged");
}

}  // namespace
}  // namespace rockface::storage

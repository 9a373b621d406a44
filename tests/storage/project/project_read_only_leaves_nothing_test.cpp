// Issue 41: a project opened read-only (`profile`, `drive`, `wedges`,
// `report`: verbs that only read) left `-wal` and `-shm` files beside it
// when they closed: SQLite makes them for a read-only connection's reads
// and a read-only connection cannot remove them. Only reading a project
// leaves nothing beside it and never changes its bytes.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

TEST(ProjectReadOnly, ReadingLeavesNothingBesideTheProject) {
  TempDir dir("read-only-leaves-nothing");
  const fs::path file = dir / "p.rockface";
  {
    auto store = ProjectStore::create(file, test::sample_project());
    store.begin_visit("test");
  }
  const auto before = listing(dir.path());
  const auto bytes = test::read_file_bytes(file);
  ASSERT_EQ(before, std::set<std::string>{"p.rockface"});
  {
    OpenOptions read;
    read.read_only = true;
    auto store = ProjectStore::open(file, read);
    EXPECT_TRUE(store.read_only());
    EXPECT_EQ(store.list_visits().size(), 1u);
    EXPECT_FALSE(store.load_tunnel());
    // Moved: the store that ends last tidies, once.
    ProjectStore moved = std::move(store);
    EXPECT_EQ(moved.list_visits().size(), 1u);
  }
  EXPECT_EQ(listing(dir.path()), before);
  EXPECT_EQ(test::read_file_bytes(file), bytes);
}

TEST(ProjectReadOnly, AWriterOpenBesideKeepsItsFiles) {
  TempDir dir("read-only-beside-a-writer");
  const fs::path file = dir / "p.rockface";
  auto writer = ProjectStore::create(file, test::sample_project());
  writer.begin_visit("test");
  ASSERT_TRUE(fs::exists(file.string() + "-wal"));
  {
    OpenOptions read;
    read.read_only = true;
    auto reader = ProjectStore::open(file, read);
    EXPECT_EQ(reader.list_visits().size(), 1u);
  }
  // The writer's log is untouched: it saves on as before.
  EXPECT_TRUE(fs::exists(file.string() + "-wal"));
  writer.begin_visit("test");
  EXPECT_EQ(writer.list_visits().size(), 2u);
}

}  // namespace
}  // namespace rockface::storage

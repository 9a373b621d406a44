// The UI thread reads while a worker writes (DESIGN.md "Threads": one
// connection per thread): no corruption, no "database is locked" reaching
// either side, and the reader only ever sees whole captures.
#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <thread>

#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

TEST(ProjectThreads, UiReadsWhileTwoWorkersWrite) {
  test::TempDir dir("threads");
  const auto file = dir / "site.rockface";
  RecordId visit = 0;
  {
    auto store = ProjectStore::create(file, test::sample_project());
    visit = store.begin_visit("tablet");
  }
  constexpr int kCaptures = 12;
  std::vector<Capture> captures;
  std::map<std::string, std::size_t> sizes;  // label -> left + right bytes
  for (int i = 0; i < kCaptures; ++i) {
    captures.push_back(test::sample_capture(visit, 100 + i, 320, 240));
    sizes[captures.back().label] =
        captures.back().left.bytes.size() + captures.back().right.bytes.size();
  }

  std::atomic<bool> writing{true};
  std::string capture_error, log_error, reader_error;
  std::thread capture_worker([&] {
    try {
      auto store = ProjectStore::open(file);
      for (const auto& c : captures) {
        const RecordId id = store.save_capture(c);
        auto model = test::sample_model(id);
        store.save_model(model);
      }
    } catch (const std::exception& e) {
      capture_error = e.what();
    }
    writing = false;
  });
  // A second writer (e.g. the analysis worker) competing for the write lock.
  std::thread log_worker([&] {
    try {
      auto store = ProjectStore::open(file);
      for (int i = 0; writing && i < 400; ++i)
        store.log_action(visit, "progress", std::to_string(i));
    } catch (const std::exception& e) {
      log_error = e.what();
    }
  });

  int reads = 0;
  std::size_t last_count = 0;
  std::thread ui([&] {
    try {
      auto store = ProjectStore::open(file);
      while (true) {
        const bool last_round = !writing;
        const auto list = store.list_captures();
        if (list.size() < last_count) throw std::runtime_error("captures disappeared");
        last_count = list.size();
        for (const auto& s : list) {
          const Capture c = store.load_capture(s.id);
          if (c.left.bytes.size() + c.right.bytes.size() != sizes.at(c.label))
            throw std::runtime_error("half a capture: " + c.label);
        }
        store.list_models();
        store.list_actions(visit);
        ++reads;
        if (last_round) break;
      }
    } catch (const std::exception& e) {
      reader_error = e.what();
    }
  });
  capture_worker.join();
  log_worker.join();
  ui.join();
  EXPECT_EQ(capture_error, "");
  EXPECT_EQ(log_error, "");
  EXPECT_EQ(reader_error, "");
  EXPECT_GT(reads, 1);
  EXPECT_EQ(last_count, static_cast<std::size_t>(kCaptures));
  RecordProperty("ui_read_rounds", reads);

  auto store = ProjectStore::open(file);
  EXPECT_TRUE(store.check_integrity(OpenOptions::Check::full).ok);
  EXPECT_EQ(store.list_captures().size(), static_cast<std::size_t>(kCaptures));
  EXPECT_EQ(store.list_models().size(), static_cast<std::size_t>(kCaptures));
}

}  // namespace
}  // namespace rockface::storage

#include "tests/support/temp_folders.h"

#include <algorithm>
#include <iostream>
#include <mutex>
#include <system_error>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace rockface::test {

namespace {

std::mutex g_mutex;
std::vector<std::filesystem::path> g_folders;
bool g_listening = false;

// At the end of the program (after GoogleTest's summary): the folders go
// when the tests passed, else they are named.
class TempFolderCleanup : public ::testing::EmptyTestEventListener {
  void OnTestProgramEnd(const ::testing::UnitTest& unit) override {
    const std::lock_guard<std::mutex> lock(g_mutex);
    for (const auto& dir : g_folders) {
      if (!unit.Passed()) {
        std::cerr << "[ KEPT     ] a test failed: its files are in " << dir.string() << "\n";
        continue;
      }
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
      if (ec) std::cerr << "cannot remove " << dir.string() << ": " << ec.message() << "\n";
    }
    g_folders.clear();
  }
};

}  // namespace

void remove_when_passed(const std::filesystem::path& dir) {
  const std::lock_guard<std::mutex> lock(g_mutex);
  if (std::find(g_folders.begin(), g_folders.end(), dir) != g_folders.end()) return;
  // GoogleTest owns the listener from here on.
  if (!std::exchange(g_listening, true))
    ::testing::UnitTest::GetInstance()->listeners().Append(new TempFolderCleanup);
  g_folders.push_back(dir);
}

}  // namespace rockface::test

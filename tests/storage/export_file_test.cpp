// Issue 41: a folder given for a file (`profile --out .`) said "cannot put
// the file in place: Success" (the errno read after remove() reset it): it is
// refused as bad input naming the folder, before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/common/error.h"
#include "storage/export_file.h"
#include "tests/storage/sample_records.h"

namespace rockface::storage {
namespace {

TEST(ExportFile, AFolderForTheFileIsRefusedByName) {
  test::TempDir dir("export-file-folder");
  std::filesystem::create_directories(dir / "out");
  const std::filesystem::path folder = dir / "out";
  std::string message = "accepted";
  try {
    write_text_atomically(folder, "text");
  } catch (const InputError& e) {
    message = e.what();
  } catch (const std::exception& e) {
    message = std::string("not an InputError: ") + e.what();
  }
  EXPECT_EQ(message, folder.string() + ": is a folder, not a file: give the file's name");
  // Nothing left beside it, and the folder is still a folder.
  EXPECT_TRUE(std::filesystem::is_directory(folder));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1u);
}

}  // namespace
}  // namespace rockface::storage

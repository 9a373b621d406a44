// The one atomic file writer (core/common/atomic_file.h): the whole content
// or the old file, never half of one, never a temporary file left behind,
// and an error that names the file and the system's reason.
#include "core/common/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/error.h"

namespace rockface {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "rockface-atomic-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(dir_, ec);
  }
  static std::string read(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_)) out.push_back(e.path().filename().string());
    return out;
  }
  fs::path dir_;
};

TEST_F(AtomicFile, WritesTheWholeContent) {
  std::string big(3 * 1000 * 1000 + 7, '\0');  // larger than any buffer
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i * 31 % 251);
  write_text_atomically(dir_ / "big.bin", big);
  EXPECT_EQ(read(dir_ / "big.bin"), big);

  write_file_atomically(dir_ / "text.txt", [](std::ostream& out) { out << "one " << 2 << '\n'; });
  EXPECT_EQ(read(dir_ / "text.txt"), "one 2\n");

  const unsigned char bytes[] = {0, 1, 2, 255};
  write_bytes_atomically(dir_ / "bytes.bin", bytes, sizeof bytes);
  EXPECT_EQ(read(dir_ / "bytes.bin"), std::string("\0\1\2\xff", 4));

  // Replacing a file replaces all of it, also by a shorter content.
  write_text_atomically(dir_ / "big.bin", "short");
  EXPECT_EQ(read(dir_ / "big.bin"), "short");
  EXPECT_EQ(names().size(), 3u) << "no temporary file is left";
}

TEST_F(AtomicFile, AFailedWriteLeavesTheOldFileAndNoTemporaryFile) {
  const fs::path file = dir_ / "report.json";
  write_text_atomically(file, "old");
  EXPECT_THROW(write_file_atomically(file,
                                     [](std::ostream& out) {
                                       out << "half of the new";
                                       throw std::runtime_error("the writer failed");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read(file), "old");
  EXPECT_EQ(names(), std::vector<std::string>{"report.json"});
}

TEST_F(AtomicFile, AFailedRenameLeavesTheOldEntryAndNoTemporaryFile) {
  // A folder in the way: the content is written, the rename is refused.
  const fs::path file = dir_ / "taken";
  fs::create_directories(file / "inside");
  try {
    write_text_atomically(file, "new");
    FAIL() << "writing over a folder was accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    EXPECT_EQ(what.find("Success"), std::string::npos) << what;
  }
  EXPECT_TRUE(fs::is_directory(file / "inside"));
  EXPECT_EQ(names(), std::vector<std::string>{"taken"});
}

TEST_F(AtomicFile, AMissingFolderNamesThePathAndTheReason) {
  const fs::path file = dir_ / "no-such-folder" / "out.json";
  try {
    write_text_atomically(file, "x");
    FAIL() << "writing into a missing folder was accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
    EXPECT_EQ(what.find("Success"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir_ / "no-such-folder"));
}

// What writing `text` at `file` says: "" when it was accepted, else the
// error's text.
std::string refusal(const fs::path& file, const std::string& text) {
  try {
    write_text_atomically(file, text);
    return "";
  } catch (const Error& e) {
    return e.what();
  }
}

TEST_F(AtomicFile, AReadOnlyFolderIsRefusedAndItsFileKept) {
  const fs::path file = dir_ / "settings.json";
  write_text_atomically(file, "old");
  fs::permissions(dir_,
                  fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                      fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec,
                  fs::perm_options::replace);
  if (::geteuid() != 0) {
    const std::string what = refusal(file, "new");
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    EXPECT_NE(what.find("Permission denied"), std::string::npos) << what;
  } else {
    // root writes into any folder: the write is tried as user "nobody".
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(3);
      const std::string what = refusal(file, "new");
      if (what.empty()) ::_exit(1);
      const bool named = what.find(file.string()) != std::string::npos &&
                         what.find("Permission denied") != std::string::npos;
      ::_exit(named ? 0 : 2);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0)
        << "1: the write was accepted, 2: the error did not name the file and the reason, "
           "3: cannot become nobody";
  }
  EXPECT_EQ(read(file), "old");
  EXPECT_EQ(names(), std::vector<std::string>{"settings.json"});
}

// Issue 41: a folder given for a file (`profile --out .`) said "cannot put
// the file in place: Success" (the errno read after remove() reset it): it is
// refused as bad input naming the folder, before anything is written.
TEST_F(AtomicFile, AFolderForTheFileIsRefusedByName) {
  const fs::path folder = dir_ / "out";
  fs::create_directories(folder);
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
  EXPECT_TRUE(fs::is_directory(folder));
  EXPECT_EQ(names(), std::vector<std::string>{"out"});
}

}  // namespace
}  // namespace rockface

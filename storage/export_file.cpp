#include "storage/export_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/common/error.h"

namespace rockface::storage {

namespace {

// Puts what is written to a file (or a folder's entries) on the card: 0, or
// the errno of a failed sync. A path that cannot be opened for it (some file
// systems refuse folders) is left as it is.
int sync_path(const std::filesystem::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) return 0;
  const int rc = ::fsync(fd) == 0 ? 0 : errno;
  ::close(fd);
  return rc;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write) {
  // A folder given for the file (`--out .`) is said as such, before anything
  // is written (issue 41: "cannot put the file in place: Success").
  std::error_code is_dir_ec;
  if (std::filesystem::is_directory(file, is_dir_ec))
    throw InputError(file.string(), "is a folder, not a file: give the file's name");
  std::filesystem::path temp = file;
  temp += ".writing-" + std::to_string(::getpid());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(file.string() + ": cannot write the file: " + std::strerror(errno));
    try {
      write(out);
    } catch (...) {
      out.close();
      std::error_code ec;
      std::filesystem::remove(temp, ec);
      throw;
    }
    out.flush();
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(temp, ec);
      throw Error(file.string() + ": writing the file failed (card full or removed?)");
    }
  }
  // The data must be on the card before the rename makes it visible.
  if (const int err = sync_path(temp, O_RDONLY); err != 0) {
    std::error_code ec;
    std::filesystem::remove(temp, ec);
    throw Error(file.string() + ": writing the file failed: " + std::strerror(err));
  }
  std::error_code ec;
  std::filesystem::rename(temp, file, ec);
  if (ec) {
    const std::string why = ec.message();  // before remove() resets ec
    std::filesystem::remove(temp, ec);
    throw Error(file.string() + ": cannot put the file in place: " + why);
  }
  // The rename is an entry of the folder: on the card once the folder is.
  const std::filesystem::path folder = file.parent_path();
  sync_path(folder.empty() ? std::filesystem::path(".") : folder, O_RDONLY | O_DIRECTORY);
}

void write_text_atomically(const std::filesystem::path& file, std::string_view text) {
  write_file_atomically(file, [&](std::ostream& out) { out << text; });
}

}  // namespace rockface::storage

#include "storage/export_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/common/error.h"

namespace rockface::storage {

void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write) {
  std::filesystem::path temp = file;
  temp += ".writing-" + std::to_string(::getpid());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(file.string() + ": cannot write the export: " + std::strerror(errno));
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
      throw Error(file.string() + ": writing the export failed (card full or removed?)");
    }
  }
  // The data must be on the card before the rename makes it visible.
  if (const int fd = ::open(temp.c_str(), O_RDONLY); fd >= 0) {
    const int rc = ::fsync(fd);
    ::close(fd);
    if (rc != 0) {
      std::error_code ec;
      std::filesystem::remove(temp, ec);
      throw Error(file.string() + ": writing the export failed: " + std::strerror(errno));
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, file, ec);
  if (ec) {
    std::filesystem::remove(temp, ec);
    throw Error(file.string() + ": cannot put the export in place: " + ec.message());
  }
}

}  // namespace rockface::storage

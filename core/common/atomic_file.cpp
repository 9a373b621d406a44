#include "core/common/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <streambuf>
#include <string>
#include <vector>

#include "core/common/error.h"

namespace rockface {

namespace {

namespace fs = std::filesystem;

// The system's text for an error number; never "Success".
std::string error_text(int err) {
  if (err == 0) return "unknown error";
  return std::strerror(err);
}

[[noreturn]] void fail(const fs::path& file, const std::string& what, int err) {
  throw Error(file.string() + ": " + what + ": " + error_text(err));
}

// A stream buffer over a file descriptor that keeps the errno of the first
// failed write, so the error says why (a full card, a removed card).
class FdBuffer : public std::streambuf {
 public:
  explicit FdBuffer(int fd) : fd_(fd), buffer_(1 << 16) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  int error() const { return error_; }

  // Writes out what is buffered: false (error() set) when it cannot.
  bool drain() {
    const char* p = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    while (left > 0 && error_ == 0) {
      const ssize_t n = ::write(fd_, p, left);
      if (n < 0) {
        if (errno == EINTR) continue;
        error_ = errno;
      } else if (n == 0) {
        error_ = EIO;
      } else {
        p += n;
        left -= static_cast<std::size_t>(n);
      }
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return error_ == 0;
  }

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) return traits_type::eof();
    if (traits_type::eq_int_type(ch, traits_type::eof())) return traits_type::not_eof(ch);
    *pptr() = traits_type::to_char_type(ch);
    pbump(1);
    return ch;
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  int fd_;
  std::vector<char> buffer_;
  int error_ = 0;
};

// A name beside the target that no other writer (thread or process) uses.
fs::path temporary_name(const fs::path& file) {
  static std::atomic<unsigned> counter{0};
  fs::path temp = file;
  temp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return temp;
}

// Closes the temporary file and removes it; keeps the caller's errno.
void discard(int fd, const fs::path& temp) {
  const int saved = errno;
  if (fd >= 0) ::close(fd);
  ::unlink(temp.c_str());
  errno = saved;
}

// Puts the folder's entries (the rename) on the card. File systems that
// cannot sync a folder (some refuse to open one) are left as they are.
void sync_folder(const fs::path& file) {
  const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void write_file_atomically(const fs::path& file, const std::function<void(std::ostream&)>& write) {
  if (file.empty()) throw Error("cannot write a file with no name");
  // A folder given for the file (`profile --out .`) is said as such, before
  // anything is written (issue 41: it said "cannot put the file in place:
  // Success").
  std::error_code is_dir_ec;
  if (fs::is_directory(file, is_dir_ec))
    throw InputError(file.string(), "is a folder, not a file: give the file's name");
  const fs::path temp = temporary_name(file);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) fail(file, "cannot write the file", errno);
  {
    FdBuffer buffer(fd);
    std::ostream out(&buffer);
    try {
      write(out);
    } catch (...) {
      discard(fd, temp);
      throw;
    }
    out.flush();
    if (!buffer.drain() || !out) {
      const int err = buffer.error();
      discard(fd, temp);
      fail(file, "writing the file failed (card full or removed?)", err);
    }
  }
  // The data must be on the card before the rename makes it visible.
  if (::fsync(fd) != 0) {
    const int err = errno;
    discard(fd, temp);
    fail(file, "writing the file failed (card full or removed?)", err);
  }
  if (::close(fd) != 0) {
    const int err = errno;
    discard(-1, temp);
    fail(file, "writing the file failed (card full or removed?)", err);
  }
  if (::rename(temp.c_str(), file.c_str()) != 0) {
    const int err = errno;
    discard(-1, temp);
    fail(file, "cannot put the file in place", err);
  }
  sync_folder(file);
}

void write_text_atomically(const fs::path& file, std::string_view text) {
  write_file_atomically(file, [&](std::ostream& out) {
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  });
}

void write_bytes_atomically(const fs::path& file, const void* data, std::size_t size) {
  write_text_atomically(file, std::string_view(static_cast<const char*>(data), size));
}

}  // namespace rockface

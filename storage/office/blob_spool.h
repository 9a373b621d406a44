#pragma once
// The blobs (photographs, meshes) a pull reads from the server, kept in a
// file beside the pulled project until the project is built (issue 46: an
// office visit opening held its pooled connection through its whole build;
// the server's bytes are read first, in the pull's one snapshot, and the
// connection is free again while the project is written). Each blob is
// checked against its SHA-256 as it arrives: a corrupt or truncated blob on
// the server stops the read, naming it. A blob named twice is read once.
// The file is removed with the spool.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>

#include "core/common/progress.h"
#include "storage/office/pg_connection.h"

namespace rockface::storage::office {

class BlobSpool {
 public:
  explicit BlobSpool(std::filesystem::path file);
  ~BlobSpool();
  BlobSpool(const BlobSpool&) = delete;
  BlobSpool& operator=(const BlobSpool&) = delete;

  // Reads blob `sha` of `size` bytes from the server into the spool.
  // `what` names the record and column for the messages.
  void fetch(Connection& server, const std::string& sha, std::int64_t size, const std::string& what,
             Progress& progress);
  // Hands the spooled blob's bytes to `sink` in pieces, in order.
  void copy(const std::string& sha,
            const std::function<void(const std::uint8_t*, std::size_t)>& sink);
  bool has(const std::string& sha) const { return at_.count(sha) > 0; }

 private:
  struct Place {
    std::int64_t offset = 0, size = 0;
  };
  std::filesystem::path file_;
  std::fstream io_;
  std::int64_t end_ = 0;
  std::map<std::string, Place> at_;
};

}  // namespace rockface::storage::office

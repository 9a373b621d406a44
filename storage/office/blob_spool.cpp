#include "storage/office/blob_spool.h"

#include <algorithm>
#include <system_error>
#include <vector>

#include "core/common/error.h"
#include "storage/office/sha256.h"

namespace rockface::storage::office {

BlobSpool::BlobSpool(std::filesystem::path file) : file_(std::move(file)) {
  io_.open(file_, std::ios::in | std::ios::out | std::ios::binary | std::ios::trunc);
  if (!io_) throw InputError(file_.string(), "cannot be written (the pull keeps its blobs there)");
}

BlobSpool::~BlobSpool() {
  io_.close();
  std::error_code ec;
  std::filesystem::remove(file_, ec);
}

void BlobSpool::fetch(Connection& server, const std::string& sha, std::int64_t size,
                      const std::string& what, Progress& progress) {
  if (has(sha)) return;
  progress.step("fetching photographs and meshes", 0.5);
  const Result head =
      server.query("SELECT complete, byte_size, chunk_size FROM rockface.blob WHERE sha256 = $1",
                   {Param::of(sha)}, "fetching " + what);
  if (head.rows() == 0 || head.text(0, 0) != "t")
    throw InputError(server.label() + ": " + what, "missing or incomplete on the server");
  if (head.int64(0, 1) != size)
    throw InputError(server.label() + ": " + what,
                     "the server says it has " + std::to_string(head.int64(0, 1)) +
                         " bytes, the record " + std::to_string(size));
  const std::int64_t chunk = head.int64(0, 2);
  const std::int64_t chunks = (size + chunk - 1) / chunk;
  io_.seekp(end_);
  Sha256 h;
  std::int64_t at = 0;
  for (std::int64_t i = 0; i < chunks; ++i) {
    progress.step("fetching photographs and meshes", 0.5);
    const Result r =
        server.query("SELECT bytes FROM rockface.blob_chunk WHERE sha256 = $1 AND idx = $2",
                     {Param::of(sha), Param::of(i)}, "fetching " + what, true);
    const std::int64_t want = std::min(chunk, size - at);
    if (r.rows() == 0 || static_cast<std::int64_t>(r.bytes(0, 0).size()) != want)
      throw InputError(server.label() + ": " + what,
                       "truncated on the server: chunk " + std::to_string(i) + " of " +
                           std::to_string(chunks) +
                           (r.rows() == 0 ? " is missing" : " has the wrong length") +
                           "; the pull was abandoned");
    const auto bytes = r.bytes(0, 0);
    h.add(bytes);
    io_.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(want));
    at += want;
  }
  if (!io_) throw InputError(file_.string(), "cannot be written (the disk may be full)");
  const std::string got = h.hex();
  if (got != sha)
    throw InputError(server.label() + ": " + what,
                     "corrupt on the server: its bytes hash to " + got +
                         ", not to their name; the pull was abandoned");
  at_[sha] = {end_, size};
  end_ += size;
}

void BlobSpool::copy(const std::string& sha,
                     const std::function<void(const std::uint8_t*, std::size_t)>& sink) {
  const auto it = at_.find(sha);
  if (it == at_.end()) throw InputError("blob " + sha, "was not read from the server");
  io_.flush();
  io_.seekg(it->second.offset);
  // A megabyte at a time: a mesh or a photograph is never held whole.
  std::vector<std::uint8_t> piece(1 << 20);
  for (std::int64_t left = it->second.size; left > 0;) {
    const auto n = static_cast<std::size_t>(std::min<std::int64_t>(left, piece.size()));
    io_.read(reinterpret_cast<char*>(piece.data()), static_cast<std::streamsize>(n));
    if (!io_) throw InputError(file_.string(), "cannot be read back");
    sink(piece.data(), n);
    left -= static_cast<std::int64_t>(n);
  }
}

}  // namespace rockface::storage::office

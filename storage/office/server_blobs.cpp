#include "storage/office/server_blobs.h"

#include <algorithm>

#include "core/common/error.h"
#include "storage/office/sha256.h"

namespace rockface::storage::office {

ServerPhotograph read_server_photograph(Connection& c, const std::string& image_uuid) {
  const std::string what = "photograph " + image_uuid;
  const Result rec = c.query(
      "SELECT body #>> '{row,bytes,$blob}', (body #>> '{row,bytes,size}')::bigint, "
      "body #>> '{row,format}' FROM rockface.record WHERE kind = 'image' AND uuid = $1::uuid "
      "AND NOT deleted ORDER BY revision DESC LIMIT 1",
      {Param::of(image_uuid)}, "finding " + what);
  if (rec.rows() == 0 || rec.is_null(0, 0))
    throw InputError(what, "not on " + c.label() + ", or this role may not read it");
  const std::string sha = rec.text(0, 0);
  const std::int64_t size = rec.int64(0, 1);
  ServerPhotograph out;
  out.format = rec.text(0, 2);
  const Result head =
      c.query("SELECT complete, byte_size, chunk_size FROM rockface.blob WHERE sha256 = $1",
              {Param::of(sha)}, "fetching " + what);
  if (head.rows() == 0 || head.text(0, 0) != "t" || head.int64(0, 1) != size)
    throw InputError(c.label() + ": " + what, "missing or incomplete on the server");
  const std::int64_t chunk = head.int64(0, 2);
  out.bytes.reserve(static_cast<std::size_t>(size));
  Sha256 h;
  for (std::int64_t i = 0, at = 0; at < size; ++i) {
    const Result r = c.query("SELECT bytes FROM rockface.blob_chunk WHERE sha256 = $1 AND idx = $2",
                             {Param::of(sha), Param::of(i)}, "fetching " + what, true);
    const std::int64_t want = std::min(chunk, size - at);
    if (r.rows() == 0 || static_cast<std::int64_t>(r.bytes(0, 0).size()) != want)
      throw InputError(c.label() + ": " + what,
                       "truncated on the server: chunk " + std::to_string(i) + " is " +
                           (r.rows() == 0 ? "missing" : "of the wrong length"));
    const auto bytes = r.bytes(0, 0);
    h.add(bytes);
    out.bytes.insert(out.bytes.end(), bytes.begin(), bytes.end());
    at += want;
  }
  const std::string got = h.hex();
  if (got != sha)
    throw InputError(c.label() + ": " + what,
                     "corrupt on the server: its bytes hash to " + got + ", not to their name");
  return out;
}

}  // namespace rockface::storage::office

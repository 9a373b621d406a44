#include "storage/office/blob_upload.h"

#include <set>

#include "core/common/error.h"
#include "storage/office/sqlite_rows.h"

namespace rockface::storage::office {

void upload_blob(Connection& server, sqlite::Connection& db, const BlobSource& blob,
                 std::int64_t chunk_bytes, Progress& progress, double fraction,
                 BlobUploadStats& stats) {
  const std::string doing = "sending " + blob.table + " " + std::to_string(blob.rowid) + "'s " +
                            blob.column + " (" + blob.sha256.substr(0, 12) + ")";
  progress.step("sending photographs and meshes", fraction);
  // blob_state sees a blob this tablet may not read (another tunnel's copy
  // of the same bytes: schema version 2 lets a tablet read only the blobs
  // its tunnel's records refer to, and its own unfinished uploads).
  const auto blob_state = [&] {
    return server.query(
        "SELECT complete, chunk_size, uploader = current_user FROM rockface.blob_state($1)",
        {Param::of(blob.sha256)}, doing);
  };
  Result state = blob_state();
  if (state.rows() == 1 && state.text(0, 0) == "t") {
    ++stats.already_there;
    return;
  }
  if (state.rows() == 0) {
    progress.step("sending photographs and meshes", fraction);
    server.query(
        "INSERT INTO rockface.blob (sha256, byte_size, chunk_size) VALUES ($1, $2, $3) "
        "ON CONFLICT (sha256) DO NOTHING",
        {Param::of(blob.sha256), Param::of(blob.size), Param::of(chunk_bytes)}, doing);
    state = blob_state();
  }
  if (state.rows() == 1 && state.text(0, 0) == "t") {  // finished by another meanwhile
    ++stats.already_there;
    return;
  }
  if (state.rows() != 1 || state.text(0, 2) != "t")
    throw Error(server.label() + ": " + doing +
                ": another login is sending the same bytes and has not finished; the next sync "
                "sends the records that need them");
  // The chunking the upload began with, so that a resumed one fits it.
  const std::int64_t chunk = state.int64(0, 1);
  std::set<std::int64_t> have;
  {
    const Result r = server.query("SELECT idx FROM rockface.blob_chunk WHERE sha256 = $1",
                                  {Param::of(blob.sha256)}, doing);
    for (int i = 0; i < r.rows(); ++i) have.insert(r.int64(i, 0));
  }
  BlobReader reader(db, blob.table, blob.column, blob.rowid);
  if (reader.size() != blob.size) {
    db.exec("DELETE FROM sync_blob WHERE sha256 = '" + blob.sha256 + "'", "forgetting a hash");
    throw Error(db.file().string() + ": " + doing +
                ": the stored bytes changed since they were hashed; the next sync hashes them "
                "again");
  }
  std::vector<std::uint8_t> piece;
  const std::int64_t chunks = (blob.size + chunk - 1) / chunk;
  for (std::int64_t i = 0; i < chunks; ++i) {
    if (have.count(i)) continue;
    progress.step("sending photographs and meshes", fraction);
    piece.resize(static_cast<std::size_t>(std::min(chunk, blob.size - i * chunk)));
    reader.read(i * chunk, piece);
    server.query(
        "INSERT INTO rockface.blob_chunk (sha256, idx, bytes) VALUES ($1, $2, $3) "
        "ON CONFLICT (sha256, idx) DO NOTHING",
        {Param::of(blob.sha256), Param::of(i), Param::binary(piece)}, doing);
    stats.bytes += static_cast<std::int64_t>(piece.size());
  }
  progress.step("sending photographs and meshes", fraction);
  const Result done =
      server.query("SELECT rockface.complete_blob($1)", {Param::of(blob.sha256)}, doing);
  if (done.text(0, 0) != "t") {
    db.exec("DELETE FROM sync_blob WHERE sha256 = '" + blob.sha256 + "'", "forgetting a hash");
    throw Error(server.label() + ": " + doing +
                ": the server found the bytes it received do not match their SHA-256; it dropped "
                "them and the next sync sends them again");
  }
  ++stats.sent;
}

}  // namespace rockface::storage::office

#pragma once
// `rockface sync`: a project's records up to the office server.
//
// Units, each in its own server transaction: the project's own records
// (the project, cameras, calibrations, the tunnel, ...), then one unit per
// visit with everything it holds. Photographs and meshes go first, each
// once by SHA-256, in chunks read from the project file piece by piece;
// the server verifies a blob's hash before it marks it complete, and a
// record may only refer to a complete blob. A unit whose records did not
// change since the last sync is not sent; a changed record becomes a new
// revision on the server (its history kept). Killed at any point (SIGKILL,
// a network cut, a server restart) the server holds whole units and whole
// blobs only, and the next run completes the work. The project file gains
// only the record of what was synced (sync_target, sync_record, sync_blob,
// sync_run).
#include <cstdint>
#include <filesystem>
#include <string>

#include "core/common/progress.h"

namespace rockface::storage::office {

struct SyncOptions {
  // The server's tunnel the visits go to; empty = the project's tunnel's name.
  std::string tunnel;
  // Bytes per blob chunk (one chunk is in memory at a time).
  std::int64_t chunk_bytes = 1 << 20;
  int connect_timeout_s = 10;
};

struct SyncResult {
  std::string server_label;  // masked connection string
  std::string tunnel;
  int units_total = 0, units_sent = 0;
  int records_sent = 0;  // new revisions the server stored
  int blobs_sent = 0, blobs_already_there = 0;
  std::int64_t blob_bytes_sent = 0;
  std::int64_t record_bytes_sent = 0;  // JSON text of the records sent
};

// What waits to go up to a server the project synced to before (for the
// tablet's Project screen), read from the project alone.
struct SyncStatus {
  bool ever_synced = false;
  std::string server_label, tunnel, last_sync_at, last_outcome;
  int records_waiting = 0;  // new or changed since the last sync
  int visits_waiting = 0;
};
SyncStatus sync_status(const std::filesystem::path& project);

// Throws ServerError (connection_lost when the server is unreachable or
// went away), Error or InputError naming the project or the server;
// Cancelled when progress asks. Progress steps come before every server
// round trip, so a cancel (or a test's kill) can fall between any two.
SyncResult sync_project(const std::filesystem::path& project, const std::string& conninfo,
                        const SyncOptions& options, Progress& progress);

}  // namespace rockface::storage::office

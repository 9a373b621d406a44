#pragma once
// `rockface pull`: a project built from the office server's records of one
// tunnel (every tablet's visits), on another tablet or a desktop. The rows
// come back with the values they were sent with, so the pulled project gives
// the same analysis as the tablet's, bit for bit; a pull of a tunnel that
// one project synced keeps that project's record ids too. Every photograph
// and mesh is checked against its SHA-256 as it arrives: a corrupt or
// truncated blob on the server stops the pull, naming it. The project
// appears complete or not at all (built beside the target, then renamed).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/common/progress.h"
#include "storage/office/pg_connection.h"

namespace rockface::storage::office {

struct PullResult {
  std::string server_label;
  int projects = 0, visits = 0, records = 0, blobs = 0;
  std::int64_t blob_bytes = 0;  // read from the server
  // Photographs left on the server (PullOptions::photographs false).
  int photographs_left = 0;
  // What the geologist must check in the pulled project, in words: e.g.
  // tablets that carry different designs of the tunnel (one is kept).
  std::vector<std::string> warnings;
};

// What a pull leaves out. A copy for the figures along the drive (the
// office's rounds: rock mass, support, over- and underbreak) needs no
// photograph: each image row keeps its format and byte_size but its bytes
// stay empty and are never read from the server. Meshes always come (the
// over- and underbreak are measured on them).
struct PullOptions {
  bool photographs = true;
};

PullResult pull_tunnel(const std::string& conninfo, const std::string& tunnel,
                       const std::filesystem::path& out, Progress& progress,
                       int connect_timeout_s = 10);
// The same over an open connection (the office's web session, whose role
// decides what the pull may read); the connection must be outside a
// transaction.
PullResult pull_tunnel(Connection& server, const std::string& tunnel,
                       const std::filesystem::path& out, Progress& progress,
                       const PullOptions& options = {});

}  // namespace rockface::storage::office

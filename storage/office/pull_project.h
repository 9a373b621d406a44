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
#include <memory>
#include <string>
#include <vector>

#include "core/common/progress.h"
#include "storage/office/blob_spool.h"
#include "storage/office/pg_connection.h"
#include "storage/office/server_records.h"

namespace rockface::storage::office {

struct PullResult {
  std::string server_label;
  int projects = 0, visits = 0, records = 0, blobs = 0;
  std::int64_t blob_bytes = 0;  // read from the server
  // Photographs and meshes left on the server (PullOptions).
  int photographs_left = 0, meshes_left = 0;
  // What the geologist must check in the pulled project, in words: e.g.
  // tablets that carry different designs of the tunnel (one is kept).
  std::vector<std::string> warnings;
};

// What a pull leaves out. A copy for the figures along the drive (the
// office's rounds: rock mass, support, over- and underbreak) needs no
// photograph: each image row keeps its format and byte_size but its bytes
// stay empty and are never read from the server. Meshes always come (the
// over- and underbreak are measured on them).
//
// A copy for the office's visit pages (issue 46) holds the visits it names
// and the project-level records (server_records.h's read_visit_records):
// none of the other visits' records, each named visit under the id a pull
// of the whole tunnel gives it. What the pages show of the rest of the
// drive (where a round starts) is read beside it (PullRead::drive_visits).
// Its photographs may stay on the server too: a page fetches each one when
// it is shown (server_blobs.h).
//
// A copy for figures already kept (the rounds' over- and underbreak,
// round_figures.h) needs no mesh either: each model row keeps its
// registration, its mesh stays on the server.
struct PullOptions {
  bool photographs = true;
  bool meshes = true;
  std::vector<std::string> visits;  // server uuids; empty: every visit
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

// A pull in its two halves, for a caller that must give the connection
// back between them (issue 46: the office's visit openings held a pooled
// connection through the whole build, and the other people's requests
// waited for it). read_pull reads all the pull needs in one snapshot of the
// server — the records, and the blobs it keeps spooled beside `out`, each
// checked against its SHA-256 — and ends its transaction; the connection is
// then free. build_pulled_project makes the project at `out` from it
// without the server. pull_tunnel is the two in a row.
struct PullRead {
  std::filesystem::path out;
  PullOptions options;
  PullResult result;  // the server's label and the warnings so far
  ServerTunnel tunnel;
  std::vector<ServerRecord> records;  // in the order they go in
  ServerRecord base;                  // the project row every tablet agrees on
  bool keep_ids = false;
  std::unique_ptr<BlobSpool> blobs;
  // A copy of some visits (PullOptions::visits): every live visit of the
  // drive without its records (server_records.h), in the same snapshot.
  std::vector<ServerDriveVisit> drive_visits;
};
PullRead read_pull(Connection& server, const std::string& tunnel, const std::filesystem::path& out,
                   Progress& progress, const PullOptions& options = {});
PullResult build_pulled_project(PullRead& read, Progress& progress);

}  // namespace rockface::storage::office

#pragma once
// Reading a tunnel's records back from the office server (pull, the
// office's drive): the tunnel, its tablets' projects and visits in the
// server's order, and the latest revision of each record of given kinds.
// The server's visit order is (started_at, project, local id): on one
// tablet's project it is the project's own order.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "storage/office/pg_connection.h"

namespace rockface::storage::office {

struct ServerVisit {
  std::string uuid, project_uuid;
  std::int64_t local_id = 0;
};

struct ServerRecord {
  std::string kind, uuid;
  std::optional<std::string> visit_uuid;
  std::string project_uuid;
  std::int64_t local_id = 0;
  int project_schema = 0;
  std::string body;  // JSON text (record_documents.h)
};

struct ServerTunnel {
  std::int64_t id = 0;
  std::string name;
  std::vector<std::string> projects;  // uuids, first synced first
  std::vector<ServerVisit> visits;    // in the server's order
};

// Throws InputError when the tunnel is not there or the role may not read it.
ServerTunnel read_server_tunnel(Connection& c, const std::string& name);

// The latest revision of every live record of the tunnel of the given kinds
// (all kinds when empty). Refuses, naming the record, one written by a
// project schema newer than this program's.
std::vector<ServerRecord> read_current_records(Connection& c, std::int64_t tunnel_id,
                                               const std::vector<std::string>& kinds,
                                               bool with_body = true);

// The latest revision of the records a page of some visits needs (the
// office's visit pages, issue 46): every record of those visits, the
// project-level records (the tunnel, its design, cameras, calibrations),
// and whatever these refer to in other visits (a texture taken by an
// earlier visit, a photograph two visits share) — not the other visits'
// records. What a page shows of the rest of the drive (where its round
// starts: the previous face of its heading) comes from read_drive_visits.
std::vector<ServerRecord> read_visit_records(Connection& c, std::int64_t tunnel_id,
                                             const std::vector<std::string>& visit_uuids);

// A visit of the drive as a round's start is read from it
// (firmware-app/tunnel/round_start.h), without its records: the id a pull
// of the whole tunnel gives it, its start as stored, its stored
// placement's chainage and its heading.
struct ServerDriveVisit {
  std::string uuid, started_at;
  std::int64_t pulled_id = 0;
  std::optional<double> chainage;  // none: no placement stored
  std::string heading;             // "" none
};
// Every live visit of `tunnel` (read_server_tunnel), in the server's order.
// `keep_ids`: a pull keeps the tablet's ids (one project synced the
// tunnel); otherwise it numbers the live visits 1, 2, ... in that order.
std::vector<ServerDriveVisit> read_drive_visits(Connection& c, const ServerTunnel& tunnel,
                                                bool keep_ids);

}  // namespace rockface::storage::office

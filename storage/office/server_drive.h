#pragma once
// What the office's drive (`rockface drive postgresql://... --tunnel NAME`)
// needs from the server, across every tablet's visits of a tunnel: the
// tunnel's drive direction and, per placed visit, its chainage, joint sets,
// measured planes and geologist — read with a few queries over the latest revisions,
// not by pulling the projects. Visits are numbered as a pull numbers them
// (one tablet's project: its own visit ids; several: the server's order).
#include <optional>
#include <string>
#include <vector>

#include "core/tunnel/alignment.h"
#include "storage/office/pg_connection.h"
#include "storage/project/project_records.h"

namespace rockface::storage::office {

struct DriveVisitRecords {
  RecordId visit_id = 0;
  double chainage = 0;
  std::vector<JointSet> sets;             // in their stored order
  std::vector<Measurement> measurements;  // dip and dip direction only
  std::optional<std::string> geologist;   // who mapped it; none: nobody named
};

struct ServerDrive {
  tunnel::Drive drive = tunnel::Drive::ascending;
  std::vector<DriveVisitRecords> visits;  // by chainage, then visit id
};

// Throws InputError when the tunnel is not on the server or no tablet sent
// its alignment.
ServerDrive read_server_drive(Connection& c, const std::string& tunnel);

}  // namespace rockface::storage::office

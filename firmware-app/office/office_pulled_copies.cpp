#include "firmware-app/office/office_pulled_copies.h"

#include "core/common/error.h"
#include "storage/office/server_records.h"

namespace rockface::app::office_web {

namespace office = storage::office;

std::map<storage::RecordId, std::string> pulled_visit_uuids(office::Connection& c,
                                                            const std::string& tunnel) {
  // Visits are numbered as the pull numbers them (server_drive.h).
  const office::ServerTunnel t = office::read_server_tunnel(c, tunnel);
  std::map<storage::RecordId, std::string> out;
  for (std::size_t i = 0; i < t.visits.size(); ++i)
    out[t.projects.size() == 1 ? t.visits[i].local_id : static_cast<storage::RecordId>(i + 1)] =
        t.visits[i].uuid;
  return out;
}

PulledVisit pulled_visit(SharedOfficeCache& cache, OfficeSession& session,
                         const std::string& tunnel, const std::string& visit_uuid) {
  PulledVisit out;
  out.copy = cache.pulled(session, tunnel);
  out.file = out.copy->file;
  for (const auto& [id, uuid] : pulled_visit_uuids(session.db, tunnel))
    if (uuid == visit_uuid) {
      out.visit_id = id;
      return out;
    }
  throw InputError("visit " + visit_uuid, "no such visit in tunnel " + tunnel);
}

}  // namespace rockface::app::office_web

#include "firmware-app/office/office_pulled_copies.h"

#include <system_error>

#include "core/common/error.h"
#include "core/common/progress.h"
#include "firmware-app/office/office_pages.h"
#include "firmware-app/office/web_security.h"
#include "storage/office/pull_project.h"
#include "storage/office/server_records.h"

namespace rockface::app::office_web {

namespace office = storage::office;

PulledVisit pulled_visit(OfficeSession& session, const std::string& tunnel,
                         const std::string& visit_uuid) {
  const std::string stamp = tunnel_stamp(session.db, tunnel);
  PulledTunnel& copy = session.pulled[tunnel];
  if (copy.file.empty() || copy.stamp != stamp || !std::filesystem::exists(copy.file)) {
    std::error_code ec;
    if (!copy.file.empty()) std::filesystem::remove(copy.file, ec);
    copy = {};
    std::filesystem::create_directories(session.folder);
    const std::filesystem::path file = session.folder / ("tunnel-" + random_token() + ".rockface");
    NoProgress quiet;
    try {
      office::pull_tunnel(session.db, tunnel, file, quiet);
    } catch (...) {
      // The pull's snapshot transaction may still be open on the session.
      session.db.exec("ROLLBACK", "ending a failed pull");
      throw;
    }
    copy = {file, stamp};
  }
  // Visits are numbered as the pull numbers them (server_drive.h).
  const office::ServerTunnel t = office::read_server_tunnel(session.db, tunnel);
  for (std::size_t i = 0; i < t.visits.size(); ++i)
    if (t.visits[i].uuid == visit_uuid)
      return {copy.file, t.projects.size() == 1 ? t.visits[i].local_id
                                                : static_cast<storage::RecordId>(i + 1)};
  throw InputError("visit " + visit_uuid, "no such visit in tunnel " + tunnel);
}

}  // namespace rockface::app::office_web

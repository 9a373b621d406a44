#pragma once
// The visit pages read a pulled copy holding the visit (storage/office/
// pull_project.h: the visit's records and the tunnel; of the drive's other
// visits, only their faces, beside the copy: SharedPull::drive), made on a connection acting as the
// session's role so that the role's row-level security decides what it holds, shared read-only by
// the sessions whose roles read the same tunnels (office_shared_cache.h)
// and made again when a tablet has synced since.
#include <filesystem>
#include <string>
#include <utility>

#include "firmware-app/office/office_shared_cache.h"
#include "storage/project/project_records.h"

namespace rockface::app::office_web {

struct PulledVisit {
  std::shared_ptr<const SharedPull> copy;  // kept while the visit is read
  std::filesystem::path file;              // the pulled project
  storage::RecordId visit_id = 0;          // the visit's id in it
  // The drive's faces where the visit's round starts (the copy holds no
  // other visit): for collect_visit_report and the exports.
  const DriveFaces* drive = nullptr;
};

// `db` acts as the session's role; it is back in the pool on return (the
// copy's rows read: SharedOfficeCache::pulled). Without `photographs` the copy's images
// are empty (a page fetches each one it shows from the server); the field
// report and the exports, which print them, ask for them. Throws
// InputError when the tunnel or the visit is not readable by the session's
// role.
PulledVisit pulled_visit(SharedOfficeCache& cache, RequestConnection& db, const std::string& tunnel,
                         const std::string& visit_uuid, bool photographs = false);
// Two visits in one copy (side by side), without photographs.
std::pair<PulledVisit, PulledVisit> pulled_visits(SharedOfficeCache& cache, RequestConnection& db,
                                                  const std::string& tunnel, const std::string& a,
                                                  const std::string& b);

}  // namespace rockface::app::office_web

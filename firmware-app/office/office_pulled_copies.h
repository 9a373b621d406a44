#pragma once
// The visit pages read a pulled copy of the tunnel (storage/office/
// pull_project.h), made on a connection acting as the session's role so that the role's
// row-level security decides what it holds, shared read-only by the
// sessions whose roles read the same tunnels (office_shared_cache.h) and
// made again when a tablet has synced since.
#include <filesystem>
#include <string>

#include "firmware-app/office/office_shared_cache.h"
#include "storage/project/project_records.h"

namespace rockface::app::office_web {

struct PulledVisit {
  std::shared_ptr<const SharedPull> copy;  // kept while the visit is read
  std::filesystem::path file;              // the pulled project
  storage::RecordId visit_id = 0;          // the visit's id in it
};

// `db` acts as the session's role. Throws InputError when the tunnel or
// the visit is not readable by the session's role.
PulledVisit pulled_visit(SharedOfficeCache& cache, storage::office::Connection& db,
                         const std::string& tunnel, const std::string& visit_uuid);

}  // namespace rockface::app::office_web

#include "firmware-app/office/office_pulled_copies.h"

#include "core/common/error.h"

namespace rockface::app::office_web {

PulledVisit pulled_visit(SharedOfficeCache& cache, storage::office::Connection& db,
                         const std::string& tunnel, const std::string& visit_uuid) {
  PulledVisit out;
  out.copy = cache.pulled(db, tunnel);
  out.file = out.copy->file;
  const auto it = out.copy->visit_ids.find(visit_uuid);
  if (it == out.copy->visit_ids.end())
    throw InputError("visit " + visit_uuid, "no such visit in tunnel " + tunnel);
  out.visit_id = it->second;
  return out;
}

}  // namespace rockface::app::office_web

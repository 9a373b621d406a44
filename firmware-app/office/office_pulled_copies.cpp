#include "firmware-app/office/office_pulled_copies.h"

#include <algorithm>

#include "core/common/error.h"

namespace rockface::app::office_web {

namespace {

PulledVisit visit_of(const std::shared_ptr<const SharedPull>& copy, const std::string& tunnel,
                     const std::string& visit_uuid) {
  PulledVisit out;
  out.copy = copy;
  out.file = copy->file;
  const auto it = copy->visit_ids.find(visit_uuid);
  if (it == copy->visit_ids.end())
    throw InputError("visit " + visit_uuid, "no such visit in tunnel " + tunnel);
  out.visit_id = it->second;
  if (copy->drive) out.drive = &*copy->drive;
  return out;
}

// A visit's uuid as the server has it, or refused before it reaches SQL as
// a uuid (a malformed one would read as the database's error).
const std::string& checked_uuid(const std::string& uuid) {
  const bool ok = uuid.size() == 36 && std::all_of(uuid.begin(), uuid.end(), [](char c) {
                    return c == '-' || (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
                  });
  if (!ok) throw InputError("visit " + uuid, "not a visit of this server");
  return uuid;
}

}  // namespace

PulledVisit pulled_visit(SharedOfficeCache& cache, RequestConnection& db, const std::string& tunnel,
                         const std::string& visit_uuid, bool photographs) {
  PullScope scope;
  scope.photographs = photographs;
  scope.visits = {checked_uuid(visit_uuid)};
  return visit_of(cache.pulled(db, tunnel, scope), tunnel, visit_uuid);
}

std::pair<PulledVisit, PulledVisit> pulled_visits(SharedOfficeCache& cache, RequestConnection& db,
                                                  const std::string& tunnel, const std::string& a,
                                                  const std::string& b) {
  PullScope scope;
  scope.photographs = false;
  scope.visits = {checked_uuid(a), checked_uuid(b)};
  std::sort(scope.visits.begin(), scope.visits.end());
  const auto copy = cache.pulled(db, tunnel, scope);
  return {visit_of(copy, tunnel, a), visit_of(copy, tunnel, b)};
}

}  // namespace rockface::app::office_web

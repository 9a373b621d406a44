#include "firmware-app/records/project_visit.h"

#include <string>

#include "core/common/error.h"

namespace rockface::app {

void require_visit(storage::ProjectStore& store, storage::RecordId visit) {
  std::string ids;
  for (const auto& v : store.list_visits()) {
    if (v.id == visit) return;
    ids += (ids.empty() ? "" : ", ") + std::to_string(v.id);
  }
  throw InputError(
      "--visit", "the project " + store.file().string() + " has no visit " + std::to_string(visit) +
                     (ids.empty() ? " (it has no visits)" : " (its visits: " + ids + ")"));
}

}  // namespace rockface::app

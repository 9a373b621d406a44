#pragma once
// A visit asked for by number (`--visit N`) checked against the project's
// visits, so that a visit that does not exist is said as such, not as one
// that "is not placed" or "has 0 measured joint sets" (issue 41).
#include "storage/project/project_records.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// Throws InputError("--visit", "the project P has no visit 99 (its visits:
// 1, 2)") unless the project has visit `visit`.
void require_visit(storage::ProjectStore& store, storage::RecordId visit);

}  // namespace rockface::app

#pragma once
// The field report's "Wedges around the excavation": the wedges of the
// project's tunnel around the visit's face with the visit's sets.
#include "storage/field_report/field_report.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// Fills report.wedges when the project has a tunnel and the visit three
// or more sets; leaves it empty otherwise.
void add_wedges_to_report(storage::ProjectStore& store, storage::FieldReport& report);

}  // namespace rockface::app

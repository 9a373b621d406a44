#pragma once
// The rock mass in the field report (`rockface report`): the visit's
// figures and classifications, or why there are none.
#include "storage/field_report/field_report.h"
#include "storage/project/project_store.h"

namespace rockface::app {

void add_rock_mass_to_report(storage::ProjectStore& store, storage::FieldReport& report);

}  // namespace rockface::app

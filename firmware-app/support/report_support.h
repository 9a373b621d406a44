#pragma once
// The field report's "Support of this round" (issue 44): the proposals,
// the Q chart with the visit's point, the checks and the decision.
#include "storage/field_report/field_report.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// Fills report.support when the project holds support classes or the visit
// a decision; leaves it empty otherwise (the report is then as before).
void add_support_to_report(storage::ProjectStore& store, storage::FieldReport& report);

}  // namespace rockface::app

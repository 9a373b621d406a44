#pragma once
// The field report's "Facets on the 3D image": the proposals of one run of
// the propose workflow (its sets, what is not a set, the picture).
#include "core/common/preset.h"
#include "firmware-app/propose/propose_workflow.h"
#include "storage/field_report/field_report.h"

namespace rockface::app {

void add_facets_to_report(const ProposeResult& result, Preset preset, storage::FieldReport& report);

}  // namespace rockface::app

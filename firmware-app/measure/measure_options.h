#pragma once
// `rockface measure`'s options as typed turned into a MeasureRequest
// (measure_workflow.h): --sets read as a count or "auto", --add-to-visit
// made the visit measured on, --point-sigma and --friction checked. Every
// value is checked here, naming the option at fault, before any pick is
// read.
#include <optional>
#include <string>

#include "firmware-app/measure/measure_workflow.h"
#include "storage/project/project_records.h"

namespace rockface::app {

struct MeasureOptions {
  MeasureRequest request;  // the options that are the request's as typed
  std::string sets;        // a count or "auto"; empty: the picks'
  std::optional<storage::RecordId> add_to_visit;
};

// Throws InputError naming the option: --point-sigma outside (0, 10] m,
// --friction outside (0, 90) degrees, --sets not a count in [1, 12] or
// "auto", --add-to-visit with --visit or --model, a --geologist name that
// storage/project/visit_geologist.h refuses or given with --add-to-visit.
MeasureRequest measure_request(const MeasureOptions& options);

}  // namespace rockface::app

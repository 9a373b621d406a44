#pragma once
// The analysis report (core/analysis/report.h) as JSON (SCENE.md, format
// rockface-report/1), written by report_json.cpp.
#include <string>

#include "core/analysis/report.h"

namespace rockface::storage {

// JSON text of the report (format rockface-report/1), pretty-printed.
std::string report_to_json(const analysis::Report& report);
// One block as a JSON object text (what the project store keeps per block).
std::string block_to_json(const analysis::ReportBlock& block);

}  // namespace rockface::storage

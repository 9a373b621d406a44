#pragma once
// The analysis report (core/analysis/report.h) as JSON (SCENE.md, format
// rockface-report/1), written by report_json.cpp; one block of it read back
// by report_block_reader.cpp (what the project store keeps per block).
#include <string>

#include "core/analysis/report.h"

namespace rockface::storage {

// JSON text of the report (format rockface-report/1), pretty-printed.
std::string report_to_json(const analysis::Report& report);
// One block as a JSON object text (what the project store keeps per block).
std::string block_to_json(const analysis::ReportBlock& block);
// The block back from such a text. Lenient, for stored rows of every
// version: absent or malformed fields stay at their defaults (an optional
// absent), a malformed part (rotation, dynamics, ...) is left out, text that
// is no JSON object gives a default block. Null numbers read as NaN, except
// the optional ones the writer nulls when it has none (fos, stability's fos,
// the limit point's), which read as none.
analysis::ReportBlock block_from_json(const std::string& text);

}  // namespace rockface::storage

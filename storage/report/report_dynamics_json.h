#pragma once
// The block report's `dynamics` (the motion after failure) as JSON, both
// ways: written into the report by report_json.cpp, read back from a
// stored block (the field report, the UI's playback).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/analysis/report.h"

namespace rockface::storage {

nlohmann::ordered_json dynamics_to_json(const analysis::ReportDynamics& d);
// The `dynamics` of a block's report JSON object; none when it has none or
// the text is not a report block.
std::optional<analysis::ReportDynamics> dynamics_from_block_json(const std::string& block_json);

}  // namespace rockface::storage

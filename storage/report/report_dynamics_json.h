#pragma once
// The block report's `dynamics` (the motion after failure) as JSON, both
// ways: written into the report by report_json.cpp, read back with the rest
// of a stored block by report_block_reader.cpp.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/analysis/report.h"

namespace rockface::storage {

nlohmann::ordered_json dynamics_to_json(const analysis::ReportDynamics& d);
// A block report's `dynamics` object read back (null numbers are unknowns,
// NaN); none when it is not one this program wrote.
std::optional<analysis::ReportDynamics> dynamics_from_json(const nlohmann::json& dynamics);

}  // namespace rockface::storage

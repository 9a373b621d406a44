#pragma once
// The block report's `dynamics` (the motion after failure) as JSON, both
// ways: written into the report by report_json.cpp, read back from a
// stored block (the field report, the UI's playback).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "storage/report.h"

namespace rockface::storage {

nlohmann::ordered_json dynamics_to_json(const ReportDynamics& d);
// The `dynamics` of a block's report JSON object; none when it has none or
// the text is not a report block.
std::optional<ReportDynamics> dynamics_from_block_json(const std::string& block_json);
// "leaves J1 at 0.34 s"
std::string event_text(const ReportMotionEvent& e);

}  // namespace rockface::storage

#pragma once
// What a geologist reads first when a block is tapped: its verdict in words,
// the factor of safety with its mode and sliding direction, the margin, size
// and weight, the rotatable corners and edges, the remote axis and, where the
// scene asked for it, the equilibrium path's limit point. The full report
// JSON stays available under it.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "storage/project/project_records.h"

namespace rockface::ui {

// block: the stored columns (label, verdict, mode, factor of safety);
// report: the block's report JSON (a "blocks" entry of rockface-report/1),
// for the rest. Absent or malformed fields are left out, never guessed.
std::vector<std::string> block_summary(const storage::BlockResult& block,
                                       const nlohmann::json& report);

}  // namespace rockface::ui

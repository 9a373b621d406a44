#pragma once
// What a geologist reads first when a block is tapped: its verdict in words,
// the factor of safety with its mode and sliding direction, the margin, size
// and weight, the rotatable corners and edges, the remote axis and, where the
// scene asked for it, the equilibrium path's limit point. The full report
// JSON stays available under it.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace rockface::ui {

struct BlockView;

// report: the block's report JSON (a "blocks" entry of rockface-report/1);
// absent or malformed fields are left out, never guessed.
std::vector<std::string> block_summary(const BlockView& block, const nlohmann::json& report);

}  // namespace rockface::ui

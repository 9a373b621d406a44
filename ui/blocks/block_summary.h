#pragma once
// What a geologist reads first when a block is tapped: its verdict in words,
// the factor of safety with its mode and sliding direction, the margin, size
// and weight, the rotatable corners and edges, the remote axis and, where the
// scene asked for it, the equilibrium path's limit point.
#include <string>
#include <vector>

#include "core/analysis/report.h"

namespace rockface::ui {

// The block's verdict as stored (storage reads the row back as the report's
// block). Unknown numbers (NaN, a null in the stored report) are left out,
// never guessed.
std::vector<std::string> block_summary(const analysis::ReportBlock& block);

}  // namespace rockface::ui

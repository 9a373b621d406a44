#pragma once
// The one word that sums up an analysed block (it picks the block's colour on
// the Blocks screen and the model, and its layer in the exports), decided from the block's verdict:
// its finiteness, removability, mode and factor of safety.
#include "core/analysis/report.h"

namespace rockface::analysis {

// Ordered from most to least alarming.
enum class BlockVerdict {
  moves,     // finite, removable and the factor of safety is below 1 (or a free fall)
  marginal,  // a verdict within its tolerance or the measurements' uncertainty
  holds,     // finite and removable, but friction holds it (FoS >= 1)
  keyed,     // finite, not removable
  infinite,  // not finite: no block
};

const char* verdict_name(BlockVerdict verdict);

BlockVerdict verdict_of(const analysis::ReportBlock& block);

}  // namespace rockface::analysis

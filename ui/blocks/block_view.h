#pragma once
// One analysed block as the Blocks screen and the model view show it: the
// verdict as stored (the one verdict type, read back by storage) and what
// only the tablet adds: the one word that picks its colour and the report
// in words. Points stay absolute, as in the report: subtract the project's
// datum to draw them (core/analysis/block_reading.h).
#include <string>
#include <vector>

#include "core/analysis/block_verdict.h"
#include "core/analysis/report.h"

namespace rockface::ui {

struct BlockView {
  analysis::ReportBlock block;
  analysis::BlockVerdict verdict = analysis::BlockVerdict::infinite;
  std::vector<std::string> summary;  // ui/blocks/block_summary.h: the report in words
};

BlockView make_block_view(analysis::ReportBlock block);

}  // namespace rockface::ui

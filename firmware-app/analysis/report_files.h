#pragma once
// The report of `rockface analyse --out REPORT.json` as files: the report
// (rockface-report/1) and, beside it, one PNG plot per block with an
// equilibrium path (mechanics_plot.h), which the report names. The report is
// written whole or not at all, so a full disk never leaves half a report in
// place of a good one.
#include <string>

#include "core/analysis/report.h"

namespace rockface::app {

// Fills each plotted block's mechanics.plot. Throws Error naming the file
// that cannot be written.
void write_report_files(analysis::Report& report, const std::string& report_file);

}  // namespace rockface::app

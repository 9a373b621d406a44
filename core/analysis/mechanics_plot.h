#pragma once
// The equilibrium path of each block as a small PNG plot (load factor
// lambda against the largest vertex displacement), written beside the
// report: REPORT.<block id>.path.png. The report's mechanics.plot names it.
#include <string>
#include <vector>

#include "core/analysis/report.h"

namespace rockface::analysis {

// Writes one plot per block with a path; throws Error when a file cannot
// be written.
void write_mechanics_plots(Report& report, const std::string& report_path);

// The plot of one path as an 8-bit BGR image (exposed for tests).
struct PlotImage {
  int width = 0, height = 0;
  std::vector<unsigned char> bgr;
};
PlotImage plot_path(const ReportMechanics& m, int width = 360, int height = 240);

}  // namespace rockface::analysis

#pragma once
// The motion after failure of each simulated block as a PNG beside the
// report: REPORT.<block id>.dynamics.png (storage/field_report/
// dynamics_picture.h draws it). The block's dynamics.picture names it.
#include <string>

#include "core/analysis/report.h"

namespace rockface::app {

// Throws Error naming the file that cannot be written.
void write_dynamics_pictures(analysis::Report& report, const std::string& report_path);

}  // namespace rockface::app

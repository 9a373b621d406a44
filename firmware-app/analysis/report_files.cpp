#include "firmware-app/analysis/report_files.h"

#include "core/analysis/mechanics_plot.h"
#include "core/common/atomic_file.h"
#include "firmware-app/analysis/dynamics_pictures.h"
#include "storage/report/report.h"

namespace rockface::app {

void write_report_files(analysis::Report& report, const std::string& report_file) {
  // The plots first: the report names them.
  analysis::write_mechanics_plots(report, report_file);
  write_dynamics_pictures(report, report_file);
  write_text_atomically(report_file, storage::report_to_json(report));
}

}  // namespace rockface::app

#include "firmware-app/analysis/report_files.h"

#include <cstdio>
#include <fstream>

#include "core/common/error.h"
#include "firmware-app/analysis/mechanics_plot.h"

namespace rockface::app {

void write_report_files(storage::Report& report, const std::string& report_file) {
  write_mechanics_plots(report, report_file);
  const std::string json = storage::report_to_json(report);
  // Write beside the target and rename, so a full disk never leaves a
  // half-written report in place of a good one.
  const std::string tmp = report_file + ".part";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f << json;
    f.flush();
    if (!f) {
      std::remove(tmp.c_str());
      throw Error(report_file + ": cannot write the report (disk full or no permission?)");
    }
  }
  if (std::rename(tmp.c_str(), report_file.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Error(report_file + ": cannot write the report");
  }
}

}  // namespace rockface::app

// The tablet's "Field report" (ui::FieldReportRunner): the same PDF as
// `rockface report` (cli/verb_report.cpp), from its own read-only
// connection to the project (one per thread).
#include "firmware-app/records/visit_field_report.h"
#include "firmware-app/services/ui_services.h"
#include "storage/field_report/field_report.h"
#include "storage/field_report/field_report_pdf.h"
#include "storage/project/project_store.h"

namespace rockface::app {

std::string StoreFieldReportRunner::write(const std::filesystem::path& project,
                                          storage::RecordId visit_id,
                                          const std::filesystem::path& pdf, Progress& progress) {
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(project, read);
  progress.step("collecting the visit", 0.1);
  const storage::FieldReport report = collect_visit_report(store, visit_id);
  progress.step("writing the PDF", 0.7);
  storage::write_field_report_pdf(report, pdf);
  return std::to_string(report.blocks.size()) +
         (report.blocks.size() == 1 ? " block, " : " blocks, ") +
         std::to_string(report.joints.size()) + (report.joints.size() == 1 ? " joint" : " joints");
}

}  // namespace rockface::app

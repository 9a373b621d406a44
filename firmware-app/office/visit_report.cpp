#include "firmware-app/office/visit_report.h"

#include <fstream>
#include <iterator>
#include <system_error>

#include "firmware-app/office/web_security.h"
#include "firmware-app/rockmass/rock_mass_report.h"
#include "firmware-app/support/report_support.h"
#include "firmware-app/tunnel/report_tunnel.h"
#include "firmware-app/wedges/report_wedges.h"
#include "storage/field_report/field_report_pdf.h"

namespace rockface::app {

storage::FieldReport collect_visit_report(storage::ProjectStore& store, storage::RecordId visit) {
  // The same steps, in the same order, as firmware-app/cli/verb_report.cpp.
  storage::FieldReport report = storage::collect_field_report(store, visit);
  add_tunnel_to_report(store, report);
  add_wedges_to_report(store, report);
  add_rock_mass_to_report(store, report);
  add_support_to_report(store, report);
  return report;
}

std::vector<std::uint8_t> visit_report_pdf(const storage::FieldReport& report,
                                           const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  const std::filesystem::path file = folder / ("report-" + office_web::random_token() + ".pdf");
  storage::write_field_report_pdf(report, file);
  std::ifstream in(file, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
  std::error_code ec;
  std::filesystem::remove(file, ec);
  return bytes;
}

}  // namespace rockface::app

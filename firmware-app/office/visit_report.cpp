#include "firmware-app/office/visit_report.h"

#include <fstream>
#include <iterator>
#include <system_error>

#include "firmware-app/office/web_security.h"
#include "storage/field_report/field_report_pdf.h"

namespace rockface::app {

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

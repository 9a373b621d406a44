#pragma once
// The field report of one visit as `rockface report` gathers it (the
// store's figures, then the tunnel, the wedges, the rock mass and the
// support added by their workflows): what the office's visit page shows
// and its PDF prints, so the browser and the printed report agree.
#include <cstdint>
#include <vector>

#include "firmware-app/records/visit_field_report.h"
#include "storage/field_report/field_report.h"

namespace rockface::app {

// The report as PDF bytes (storage/field_report/field_report_pdf.h), written
// through a temporary file in `folder`.
std::vector<std::uint8_t> visit_report_pdf(const storage::FieldReport& report,
                                           const std::filesystem::path& folder);

}  // namespace rockface::app

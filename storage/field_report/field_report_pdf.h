#pragma once
// The field report as a PDF (A4, cairo's PDF surface): title and visit; the
// camera and preset; the accuracy (scale, vertical, north, ground control,
// several 3D images); the face picture with traces and blocks; the
// stereonet; the joint and joint-set tables; the block table with verdicts,
// margins, modes, factors of safety and rotatability; the effects simulated.
#include <filesystem>

#include "storage/field_report/field_report.h"

namespace rockface::storage {

// Throws rockface::Error naming the file when it cannot be written.
void write_field_report_pdf(const FieldReport& report, const std::filesystem::path& file);

}  // namespace rockface::storage

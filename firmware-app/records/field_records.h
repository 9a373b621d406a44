#pragma once
// What the field workflow stores after each step, made from the step's
// result: the model of a reconstruction (mesh, registration and its
// accuracy figures) and the record of a block analysis. Shared by
// `rockface replay` and the tablet UI's runners, so both store the same.
#include <string>

#include "core/analysis/report.h"
#include "core/common/preset.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "storage/project/project_records.h"
#include "storage/report/reconstruction_report.h"

namespace rockface::app {

// The model of `capture_id`, textured with its left image. The registration's
// parameters_json holds the reconstruction report (how it was scaled and
// oriented, its accuracy), the predicted depth precision and the range pole
// targets (project frame).
storage::Model model_record(const photogrammetry::ReconstructionResult& rec,
                            storage::RecordId capture_id,
                            const storage::ReconstructionReportContext& accuracy);

storage::AnalysisRun analysis_record(const analysis::Report& report, storage::RecordId visit_id,
                                     std::optional<storage::RecordId> model_id, Preset preset);

}  // namespace rockface::app

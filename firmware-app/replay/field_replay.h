#pragma once
// The field workflow, headless, through the mock camera (`rockface replay`):
// capture (or load) the pair, reconstruct and register it, take the traces,
// find and analyse the blocks, and store every step in the project file.
#include <optional>
#include <string>

#include "core/common/preset.h"
#include "core/common/progress.h"
#include "storage/project_records.h"
#include "storage/report.h"

namespace rockface::app {

struct ReplayRequest {
  std::string source;            // a scene file (synthetic capture) or a folder of earlier captures
  std::string project;           // *.rockface; created when missing
  std::optional<Preset> preset;  // none: the scene's analysis.preset (standard for a folder)
};

struct ReplayOutcome {
  storage::RecordId visit_id = 0;
  storage::RecordId capture_id = 0;
  storage::RecordId model_id = 0;
  std::vector<storage::RecordId> more_model_ids;  // further pairs of the visit, in the face frame
  std::optional<storage::RecordId> analysis_id;
  std::size_t model_points = 0;
  std::string registration;            // how the model was scaled and oriented
  double predicted_depth_sigma_m = 0;  // sigma_Z at the face distance
  std::vector<std::string> guidance;   // capture guidance notes
  std::optional<storage::Report> report;
};

// Throws InputError for bad input (naming file and field) and Error for the
// rest; whatever was stored before a failure stays stored.
ReplayOutcome replay_field_workflow(const ReplayRequest& request, Progress& progress);

}  // namespace rockface::app

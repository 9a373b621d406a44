#pragma once
// The field workflow, headless, through the mock camera (`rockface replay`):
// capture (or load) the pair, reconstruct and register it, take the traces,
// find and analyse the blocks, and store every step in the project file.
#include <optional>
#include <string>

#include "core/analysis/report.h"
#include "core/common/preset.h"
#include "core/common/progress.h"
#include "firmware-app/reconstruct/registration_options.h"
#include "storage/project/project_records.h"

namespace rockface::app {

struct ReplayRequest {
  std::string source;            // a scene file (synthetic capture) or a folder of earlier captures
  std::string project;           // *.rockface; created when missing
  std::optional<Preset> preset;  // none: the scene's analysis.preset (standard for a folder)
  // A folder of photographs (issue 42): what registers its pair, given as
  // options; each overrides the visit file beside the photographs
  // (visit.json, storage/scene/visit_file_json.h). Refused with a scene,
  // which gives its own.
  RegistrationOptions registration;
  // The heading the visit is taken at (storage/tunnel/visit_heading.h);
  // "": the visit file's, if it names one.
  std::string heading;
  // The geologist who maps the visit (storage/project/visit_geologist.h);
  // "": the visit file's, if it names one.
  std::string geologist;
};

// A joint's orientation as measured from its picked traces, beside the
// orientation the scene gives it (for a synthetic scene: the truth).
struct JointComparison {
  std::string id;
  double scene_dip = 0, scene_dipdir = 0;  // degrees
  bool measured = false;                   // false: orientation unknown (why: `problem`)
  double dip = 0, dipdir = 0, sigma = 0;   // degrees, when measured
  double angle = 0;                        // degrees between the two planes, when measured
  std::vector<std::string> traces;
  std::vector<std::string> compass_read;  // its traces whose compass reading gave the plane
  std::string problem;
};

struct ReplayOutcome {
  storage::RecordId visit_id = 0;
  storage::RecordId capture_id = 0;
  storage::RecordId model_id = 0;
  std::vector<storage::RecordId> more_model_ids;  // further pairs of the visit, in the face frame
  std::optional<storage::RecordId> analysis_id;
  std::size_t model_points = 0;
  std::string registration;            // how the model was scaled and oriented
  double predicted_depth_sigma_m = 0;  // sigma_Z at the face distance (base lengths if unscaled)
  // Issue 38: false when nothing gave the model a scale (no range pole,
  // control points or baseline): its lengths are in units of the base.
  bool scaled = true;
  std::vector<std::string> guidance;  // capture guidance notes
  std::string heading;                // the visit's, "" none
  std::string geologist;              // the visit's, "" none
  // With picks: each scene joint's plane measured from its traces beside
  // the scene's (JointComparison), in scene order.
  std::vector<JointComparison> joints;
  std::optional<analysis::Report> report;
};

// Throws InputError for bad input (naming file and field) and Error for the
// rest; whatever was stored before a failure stays stored.
ReplayOutcome replay_field_workflow(const ReplayRequest& request, Progress& progress);

}  // namespace rockface::app

#pragma once
// The geometric model of a visit as a scene (SCENE.md, format
// "rockface-scene/1") for desktop analysis: joints (with their points and
// strengths), free faces and surface patches from the area measurements,
// traces, and the preset and effects of the visit's latest block analysis.
// Coordinates are absolute (datum added back) as the scene format requires.
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "core/photogrammetry/surface/trace_pieces.h"
#include "storage/project/project_records.h"

namespace rockface::storage {

class ProjectStore;

struct SceneSource {
  ProjectInfo project;
  RecordId visit_id = 0;
  std::vector<Joint> joints;
  std::vector<Measurement> measurements;
  std::optional<AnalysisRun> analysis;  // the latest one of the visit, if any
};

// The visit's traces as the analysis takes them: the stored trace
// measurements in order, where pieces of one joint stored from different
// pairs (models) of the visit are joined into one trace, as the replay joins
// them (photogrammetry::join_trace_pieces): its label is the first piece's,
// `pieces` the labels of the stored traces in it. Points datum-relative.
std::vector<photogrammetry::FaceTrace> scene_traces(const std::vector<Measurement>& measurements);

// The scene; a joined trace lists its stored traces in "pieces".
nlohmann::json make_scene_json(const SceneSource& source);

// What a visit (the latest when none) holds for its scene. Throws InputError
// when the project has no visit.
SceneSource load_scene_source(ProjectStore& store, std::optional<RecordId> visit_id = {});

// Visit `visit_id` (the latest visit when none) to `file`; logs the export
// when the project is writable.
void export_scene_json(ProjectStore& store, const std::filesystem::path& file,
                       std::optional<RecordId> visit_id = {});

}  // namespace rockface::storage

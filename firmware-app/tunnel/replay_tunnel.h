#pragma once
// The tunnel in a replay of a scene with a `tunnel` section: the project
// takes the scene's tunnel (when it has none yet), the range pole stands
// where the geologist typed it (when the scene types it), and the visit is
// placed in the tunnel once its 3D images are stored.
#include <optional>
#include <string>

#include <Eigen/Core>

#include "storage/project/project_store.h"
#include "storage/scene/scene.h"

namespace rockface::app {

// The range pole's lower target (datum-relative) where the scene's
// tunnel.placement types it; nothing when the scene has no typed placement.
std::optional<Eigen::Vector3d> typed_range_pole(const storage::Scene& scene);

// Saves the scene's tunnel into a project that has none, places the visit
// and saves its placement. Returns a line for the replay's guidance.
std::string place_replayed_visit(storage::ProjectStore& store, const storage::Scene& scene,
                                 storage::RecordId visit_id);

}  // namespace rockface::app

#pragma once
// The reconstructed surface as the project stores it (storage::Mesh).
#include "core/photogrammetry/surface_mesh.h"
#include "storage/project_records.h"

namespace rockface::app {

storage::Mesh project_mesh(const photogrammetry::SurfaceMesh& mesh);

}  // namespace rockface::app

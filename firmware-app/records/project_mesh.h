#pragma once
// The reconstructed surface as the project stores it (storage::Mesh).
#include "core/photogrammetry/surface/surface_mesh.h"
#include "storage/project/project_records.h"

namespace rockface::app {

storage::Mesh project_mesh(const photogrammetry::SurfaceMesh& mesh);

// Back to the 3D image: the left photograph's pixel of every vertex comes
// from its texture coordinates (texture_width x texture_height, the left
// photograph's size); empty when the mesh has none.
photogrammetry::SurfaceMesh surface_mesh(storage::Mesh&& mesh, int texture_width,
                                         int texture_height);

}  // namespace rockface::app

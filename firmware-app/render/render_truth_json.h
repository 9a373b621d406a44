#pragma once
// truth.json beside a synthetic render (SCENE.md, `rockface render`): both
// camera poses (position + world-to-camera rotation), the intrinsics, the
// target centres in both images, the reference line, the true trace
// polylines in world and left-image coordinates, and where the depth map is.
// World coordinates are absolute (the scene's datum added back).
#include <string>

#include <Eigen/Core>

#include "camera/synthetic_renderer.h"

namespace rockface::app {

std::string render_truth_json(const camera::SyntheticScene& scene,
                              const camera::SyntheticRender& render, const Eigen::Vector3d& origin,
                              const std::string& scene_name);

}  // namespace rockface::app

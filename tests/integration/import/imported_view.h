#pragma once
// Where a point at survey coordinates falls on the left photograph of an
// imported visit's virtual view (`import --view-from`): the pixels the
// tests tap as a geologist would. The pinhole is written here from the
// stored camera, not taken from the product's projection, so the picks'
// truth does not come from the code under test.
#include <array>
#include <optional>

#include <Eigen/Core>

#include "storage/project/project_store.h"

namespace rockface::test {

struct ImportedView {
  Eigen::Vector3d datum;            // the project's, survey coordinates
  Eigen::Matrix3d world_to_camera;  // mesh frame to the camera's
  Eigen::Vector3d centre;           // the camera's, mesh frame
  photogrammetry::CameraIntrinsics K;

  std::array<double, 2> pixel(const Eigen::Vector3d& survey) const {
    const Eigen::Vector3d c = world_to_camera * (survey - datum - centre);
    return {K.fx * c.x() / c.z() + K.cx, K.fy * c.y() / c.z() + K.cy};
  }
};

// The newest model's view; none when that model has no camera.
inline std::optional<ImportedView> newest_imported_view(storage::ProjectStore& store) {
  const auto model = store.load_model(store.list_models().back().id);
  if (!model.camera_to_mesh) return std::nullopt;
  const auto capture = store.load_capture(*model.texture_capture_id);
  return ImportedView{store.project().datum, model.camera_to_mesh->R.transpose(),
                      model.camera_to_mesh->t,
                      store.load_calibration(*capture.calibration_id).intrinsics};
}

}  // namespace rockface::test

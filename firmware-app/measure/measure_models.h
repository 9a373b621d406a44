#pragma once
// The 3D images that picks are measured on, and what they were seen from:
// a model file (MODEL.ply of `rockface reconstruct`, with the camera it was
// reconstructed with) or the models of a project, one per stereo pair of a
// visit. The messages name the command line's options (--camera, --model,
// --visit, --photo), which the tablet does not offer.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/measure/photo_view.h"
#include "core/photogrammetry/surface/surface_mesh.h"
#include "storage/project/project_records.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// Where the 3D images come from.
struct ModelSource {
  std::string source;  // a model file (*.ply) or a project
  // Model file: the camera it was reconstructed with (camera JSON), and the
  // left photograph (default: the model's TextureFile).
  std::string camera, photo;
  // Project: one model (pair 1 only), or a visit's models (default: the
  // newest visit with a model).
  std::optional<storage::RecordId> model, visit;
  // The precision of a picked point, m (default: the reconstruction's sigma_Z).
  std::optional<double> point_sigma;
};

// One 3D image and what it was seen from.
struct LoadedModel {
  photogrammetry::SurfaceMesh mesh;
  std::map<std::string, measure::PhotoView> views;
  std::map<std::string, cv::Mat> photos;
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  double point_sigma = 0.01;
  double correlation_length = 0;
  std::string name;
  // Project only.
  std::optional<storage::RecordId> model_id, capture_id;
};

// The model file `from.source` (pair 1, its left photograph only).
LoadedModel load_ply_model(const ModelSource& from);

// One stored model, its photographs named for its pair (measure::pair_photo).
LoadedModel load_stored_model(storage::ProjectStore& store, const ModelSource& from,
                              storage::RecordId id, int pair);

// The 3D images of the project to measure on, one per pair: --model alone,
// else the pairs of --visit or of the newest visit with a model.
struct ProjectPairs {
  std::vector<storage::RecordId> models;
  std::string what;  // "model 3", "visit 2", for messages
};
ProjectPairs project_pairs(storage::ProjectStore& store, const ModelSource& from);

}  // namespace rockface::app

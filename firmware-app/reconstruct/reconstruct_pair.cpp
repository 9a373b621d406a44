#include "firmware-app/reconstruct/reconstruct_pair.h"

#include <filesystem>
#include <fstream>
#include <future>

#include <opencv2/imgcodecs.hpp>

#include "core/analysis/preset_options.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/preset.h"
#include "storage/exchange/mesh_export.h"
#include "storage/report/reconstruction_report.h"
#include "storage/scene/camera_json.h"

namespace rockface::app {

namespace {

cv::Mat read_image(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(path, "no such file");
  cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) throw InputError(path, "not an image OpenCV can read (PNG, JPEG, TIFF ...)");
  return image;
}

}  // namespace

photogrammetry::ReconstructionResult reconstruct_pair_files(const PairReconstructionRequest& o,
                                                            Progress& progress) {
  // Check every argument before the long work starts.
  const auto preset = analysis::preset_options(parse_preset(o.preset, "--preset")).reconstruction;
  const std::string ext = std::filesystem::path(o.out).extension().string();
  if (ext != ".ply" && ext != ".obj")
    throw InputError("--out", "the model file must end in .ply or .obj, not '" + ext + "'");
  const photogrammetry::RegistrationSources sources = registration_sources(o.registration);
  const auto left_camera = storage::load_camera_json(o.camera);
  const auto right_camera =
      o.right_camera.empty() ? left_camera : storage::load_camera_json(o.right_camera);
  // Decoding a 24 Mpx photograph is one thread's work: the two side by side.
  auto right_image = std::async(std::launch::async, [&] { return read_image(o.right); });
  const cv::Mat left = read_image(o.left);
  const cv::Mat right = right_image.get();

  photogrammetry::ReconstructionResult result = photogrammetry::reconstruct(
      left, right, left_camera, right_camera, preset, sources, progress);

  storage::MeshExportOptions mesh_options;
  mesh_options.datum = result.datum;
  mesh_options.texture_file = std::filesystem::absolute(o.left).string();
  // Both writers go through a temporary file: a failed write leaves no half model.
  if (ext == ".ply")
    storage::write_ply(o.out, result.mesh, mesh_options);
  else
    storage::write_obj(o.out, result.mesh, mesh_options);
  if (!o.report.empty()) {
    storage::ReconstructionReportContext context{
        o.left,       o.right, preset.name, o.registration.range_pole, o.registration.baseline,
        sources.north};
    write_text_atomically(o.report, storage::reconstruction_report_json(result, context));
  }
  return result;
}

}  // namespace rockface::app

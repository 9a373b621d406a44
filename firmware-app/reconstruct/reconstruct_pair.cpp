#include "firmware-app/reconstruct/reconstruct_pair.h"

#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/preset.h"
#include "core/photogrammetry/targets/reference_line.h"
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

photogrammetry::NorthReference parse_north(const PairReconstructionRequest& o) {
  photogrammetry::NorthReference n;
  const auto line = photogrammetry::parse_reference_line(o.reference_line, "--reference-line");
  n.from_px = line[0];
  n.to_px = line[1];
  n.azimuth_deg = *o.azimuth;
  n.declination_deg = o.declination.value_or(0.0);
  return n;
}

}  // namespace

photogrammetry::ReconstructionResult reconstruct_pair_files(const PairReconstructionRequest& o,
                                                            Progress& progress) {
  // Check every argument before the long work starts.
  const auto preset = photogrammetry::reconstruction_preset(parse_preset(o.preset, "--preset"));
  const std::string ext = std::filesystem::path(o.out).extension().string();
  if (ext != ".ply" && ext != ".obj")
    throw InputError("--out", "the model file must end in .ply or .obj, not '" + ext + "'");
  if (o.azimuth.has_value() != !o.reference_line.empty())
    throw InputError(o.azimuth ? "--reference-line" : "--azimuth",
                     "--azimuth and --reference-line go together (the compass bearing of a line "
                     "given by two pixels of the left image)");
  if (o.declination && !o.azimuth)
    throw InputError("--declination", "needs --azimuth and --reference-line");
  if (o.range_pole && !(*o.range_pole > 0))
    throw InputError("--range-pole", "the pole length must be > 0 m");
  if (o.baseline && !(*o.baseline > 0)) throw InputError("--baseline", "the base must be > 0 m");

  photogrammetry::RegistrationSources sources;
  sources.range_pole_m = o.range_pole;
  sources.baseline_m = o.baseline;
  if (o.azimuth) sources.north = parse_north(o);
  if (!o.gcp.empty()) {
    std::ifstream in(o.gcp);
    if (!in) throw InputError(o.gcp, "cannot open the control-point file");
    sources.control_points = photogrammetry::parse_control_points(in, o.gcp);
    sources.control_points_where = o.gcp;
    if (sources.control_points.size() < 3)
      throw InputError(o.gcp, "need three or more control points, found " +
                                  std::to_string(sources.control_points.size()));
  }
  const auto left_camera = storage::load_camera_json(o.camera);
  const auto right_camera =
      o.right_camera.empty() ? left_camera : storage::load_camera_json(o.right_camera);
  const cv::Mat left = read_image(o.left);
  const cv::Mat right = read_image(o.right);

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
    storage::ReconstructionReportContext context{o.left,       o.right,    preset.name,
                                                 o.range_pole, o.baseline, sources.north};
    write_text_atomically(o.report, storage::reconstruction_report_json(result, context));
  }
  return result;
}

}  // namespace rockface::app

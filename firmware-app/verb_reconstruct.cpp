// `rockface reconstruct LEFT RIGHT --camera CAMERA.json [--right-camera CAMERA.json]
//  [--preset P] [--range-pole LENGTH_M] [--azimuth DEG --reference-line U1,V1,U2,V2
//  [--declination DEG]] [--gcp GCP.csv] [--baseline M] --out MODEL.ply [--report REPORT.json]`
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "core/common/preset.h"
#include "core/photogrammetry/reconstruction.h"
#include "core/photogrammetry/reference_line.h"
#include "firmware-app/atomic_file.h"
#include "firmware-app/verb_registry.h"
#include "storage/camera_json.h"
#include "storage/mesh_export.h"
#include "storage/reconstruction_report.h"

namespace rockface::app {
namespace {

struct ReconstructOptions {
  std::string left, right, camera, right_camera, preset = "standard", gcp, out, report;
  std::string reference_line;
  std::optional<double> range_pole, azimuth, declination, baseline;
};

// Stage names on stderr as they change: a 24 Mpx pair takes a while.
class StderrProgress final : public Progress {
 public:
  void report(std::string_view stage, double) override {
    const std::string s(stage.substr(0, stage.find(':')));
    if (s != last_) std::cerr << "rockface reconstruct: " << s << "\n";
    last_ = s;
  }
  bool cancel_requested() const override { return false; }

 private:
  std::string last_;
};

cv::Mat read_image(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(path, "no such file");
  cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) throw InputError(path, "not an image OpenCV can read (PNG, JPEG, TIFF ...)");
  return image;
}

photogrammetry::NorthReference parse_north(const ReconstructOptions& o) {
  photogrammetry::NorthReference n;
  const auto line = photogrammetry::parse_reference_line(o.reference_line, "--reference-line");
  n.from_px = line[0];
  n.to_px = line[1];
  n.azimuth_deg = *o.azimuth;
  n.declination_deg = o.declination.value_or(0.0);
  return n;
}

int run(const ReconstructOptions& o) {
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

  StderrProgress progress;
  const photogrammetry::ReconstructionResult result = photogrammetry::reconstruct(
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
    write_atomically(o.report, storage::reconstruction_report_json(result, context));
  }

  const char* unit = result.scaled ? "m" : "base lengths";
  std::printf(
      "%zu points, %zu triangles; spacing %.4g %s; distance %.4g %s, base %.4g %s "
      "(1/%.1f)\n",
      result.mesh.size(), result.mesh.triangles.size(), result.point_spacing, unit, result.distance,
      unit, result.base, unit, 1.0 / result.accuracy.base_ratio);
  std::printf("relative orientation: %d of %d matches, reprojection %.2f px rms\n",
              result.orientation.inliers, result.orientation.matches,
              result.orientation.rms_reprojection_px);
  std::printf("scale: %s, vertical: %s, north: %s\n", result.scale_source.c_str(),
              result.vertical_source.c_str(), result.north_source.c_str());
  if (result.control_points)
    std::printf("control points: rms %.4f m, worst %s (%.4f m)\n", result.control_points->rms_m,
                result.control_points->worst_id.c_str(), result.control_points->worst_m);
  std::printf("predicted depth precision sigma_Z = %.4g %s at %.4g %s\n", result.accuracy.sigma_z,
              unit, result.distance, unit);
  for (const auto& w : result.accuracy.warnings) std::printf("warning: %s\n", w.c_str());
  return 0;
}

VerbRun setup_reconstruct(CLI::App& sub) {
  auto o = std::make_shared<ReconstructOptions>();
  sub.add_option("LEFT", o->left, "left photograph")->required();
  sub.add_option("RIGHT", o->right, "right photograph")->required();
  sub.add_option("--camera", o->camera, "calibration of the camera (rockface-camera/1)")
      ->required();
  sub.add_option("--right-camera", o->right_camera,
                 "calibration of the right photograph's camera, when it differs");
  sub.add_option("--preset", o->preset, "fast | standard | precise (default standard)");
  sub.add_option("--range-pole", o->range_pole,
                 "distance between the two target centres of the vertical range pole, m");
  sub.add_option("--azimuth", o->azimuth,
                 "compass bearing of the reference line, degrees clockwise from north");
  sub.add_option("--reference-line", o->reference_line,
                 "U1,V1,U2,V2: the reference line's two pixels in the left image");
  sub.add_option("--declination", o->declination, "magnetic declination, degrees, east positive");
  sub.add_option("--gcp", o->gcp,
                 "ground control points, CSV id,u,v,X,Y,Z (u, v in the left image)");
  sub.add_option("--baseline", o->baseline, "measured distance between the camera stations, m");
  sub.add_option("--out", o->out, "the 3D image: MODEL.ply or MODEL.obj")->required();
  sub.add_option("--report", o->report, "accuracy report (rockface-reconstruction/1 JSON)");
  return [o] { return run(*o); };
}

const VerbRegistrar reg{"reconstruct",
                        "two-view reconstruction: a scaled, oriented 3D image from a stereo pair",
                        setup_reconstruct};

}  // namespace
}  // namespace rockface::app

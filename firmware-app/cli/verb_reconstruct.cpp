// `rockface reconstruct LEFT RIGHT --camera CAMERA.json [--right-camera CAMERA.json]
//  [--preset P] [--range-pole LENGTH_M] [--azimuth DEG --reference-line U1,V1,U2,V2
//  [--declination DEG]] [--gcp GCP.csv] [--baseline M] --out MODEL.ply [--report REPORT.json]`
#include <cstdio>
#include <iostream>
#include <memory>

#include "core/photogrammetry/estimators/registration.h"
#include "firmware-app/cli/registration_cli.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/reconstruct/reconstruct_pair.h"

namespace rockface::app {
namespace {

// Stage names on stderr as they change: a 24 Mpx pair takes a while.
class StageProgress final : public Progress {
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

int run_reconstruct(const PairReconstructionRequest& o) {
  StageProgress progress;
  const photogrammetry::ReconstructionResult result = reconstruct_pair_files(o, progress);
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
    std::printf("control points: %s\n",
                photogrammetry::control_points_summary(*result.control_points).c_str());
  std::printf("predicted depth precision sigma_Z = %.4g %s at %.4g %s\n", result.accuracy.sigma_z,
              unit, result.distance, unit);
  for (const auto& w : result.accuracy.warnings) std::printf("warning: %s\n", w.c_str());
  return 0;
}

VerbRun setup_reconstruct(CLI::App& sub) {
  auto o = std::make_shared<PairReconstructionRequest>();
  sub.add_option("LEFT", o->left, "left photograph")->required();
  sub.add_option("RIGHT", o->right, "right photograph")->required();
  sub.add_option("--camera", o->camera, "calibration of the camera (rockface-camera/1)")
      ->required();
  sub.add_option("--right-camera", o->right_camera,
                 "calibration of the right photograph's camera, when it differs");
  sub.add_option("--preset", o->preset, "fast | standard | precise (default standard)");
  add_registration_options(sub, o->registration);
  sub.add_option("--out", o->out, "the 3D image: MODEL.ply or MODEL.obj")->required();
  sub.add_option("--report", o->report, "accuracy report (rockface-reconstruction/1 JSON)");
  return [o] { return run_reconstruct(*o); };
}

const VerbRegistrar reconstruct_verb{
    "reconstruct", "two-view reconstruction: a scaled, oriented 3D image from a stereo pair",
    setup_reconstruct};

}  // namespace
}  // namespace rockface::app

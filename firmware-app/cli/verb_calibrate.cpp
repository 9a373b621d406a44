// `rockface calibrate --pattern chessboard:COLSxROWS:SQUARE_M IMAGE... --out CAMERA.json`
// (also circles:COLSxROWS:SPACING_M).
#include <cstdio>
#include <iostream>

#include "core/photogrammetry/camera/calibration.h"
#include "firmware-app/cli/verb_registry.h"
#include "storage/scene/camera_json.h"

namespace rockface::app {
namespace {

struct CalibrateOptions {
  std::string pattern;
  std::vector<std::string> images;
  std::string out;
  std::string body, lens, focus;
};

VerbRun setup_calibrate(CLI::App& sub) {
  auto opts = std::make_shared<CalibrateOptions>();
  sub.add_option("--pattern", opts->pattern,
                 "chessboard:COLSxROWS:SQUARE_M (inner corners, square side in metres) or "
                 "circles:COLSxROWS:SPACING_M")
      ->required();
  sub.add_option("IMAGE", opts->images,
                 "views of the pattern, all from one body, lens and focal setting")
      ->required();
  sub.add_option("--out", opts->out, "camera file to write (rockface-camera/1)")->required();
  sub.add_option("--body", opts->body, "camera body, e.g. \"Nikon D7500\"");
  sub.add_option("--lens", opts->lens, "lens and focal setting, e.g. \"18-55 @ 24 mm\"");
  sub.add_option("--focus", opts->focus, "focus setting, e.g. \"locked\"");
  return [opts] {
    const auto pattern = photogrammetry::parse_calibration_pattern(opts->pattern);
    const auto out = photogrammetry::calibrate_from_images(opts->images, pattern);
    for (const auto& image : out.images)
      if (!image.pattern_found) std::cout << "no pattern found: " << image.path << "\n";
    for (const auto& v : out.result.views) {
      char line[256];
      std::snprintf(line, sizeof line, "%-32s %7.3f px%s\n", v.name.c_str(), v.rms_px,
                    v.outlier ? "  outlier: left out, retake this view" : "");
      std::cout << line;
    }
    photogrammetry::CameraIntrinsics cam = out.result.intrinsics;
    cam.body = opts->body;
    cam.lens = opts->lens;
    cam.focus = opts->focus;
    storage::save_camera_json(opts->out, cam);
    char summary[256];
    std::snprintf(summary, sizeof summary,
                  "RMS %.3f px over %d view(s); fx %.2f fy %.2f cx %.2f cy %.2f; written to %s\n",
                  out.result.rms_px, out.result.views_used(), cam.fx, cam.fy, cam.cx, cam.cy,
                  opts->out.c_str());
    std::cout << summary;
    return 0;
  };
}

const VerbRegistrar calibrate_verb{
    "calibrate", "camera calibration from views of a chessboard or circle grid", setup_calibrate};

}  // namespace
}  // namespace rockface::app

// `rockface calibrate --pattern chessboard:COLSxROWS:SQUARE_M IMAGE... --out CAMERA.json
//  [--project PROJECT.rockface]` (also circles:COLSxROWS:SPACING_M). With a
// project, the calibration joins its library (issue 42) under the body, lens
// and focal setting the views' EXIF name, so that the photographs that
// camera takes get it (storage/project/calibration_library.h).
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "camera/exif.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/photogrammetry/camera/calibration.h"
#include "core/photogrammetry/camera/calibration_coverage.h"
#include "firmware-app/cli/verb_registry.h"
#include "storage/project/project_store.h"
#include "storage/scene/camera_json.h"

namespace rockface::app {
namespace {

struct CalibrateOptions {
  std::string pattern;
  std::vector<std::string> images;
  std::string out;
  std::string body, lens, focus;
  std::string project;
};

// The body, lens and focal setting of the views, from the first view's
// EXIF; every view must be of the same (a calibration is of one setting).
camera::ExifInfo views_camera(const std::vector<std::string>& images) {
  camera::ExifInfo first;
  std::string first_path;
  for (const auto& path : images) {
    const camera::ExifInfo e = camera::read_exif_file(path);
    if (e.empty()) continue;
    if (first_path.empty()) {
      first = e;
      first_path = path;
      continue;
    }
    if (e.model != first.model || e.serial != first.serial || e.lens != first.lens ||
        e.focal_length_mm != first.focal_length_mm)
      throw InputError(path, "taken with another body, lens or focal setting than " + first_path +
                                 ": a calibration is of one camera at one setting");
  }
  return first;
}

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
  sub.add_option("--project", opts->project,
                 "also store it in this project's calibrations (created when missing), under the "
                 "body, lens and focal setting of the views' EXIF");
  return [opts] {
    const auto pattern = photogrammetry::parse_calibration_pattern(opts->pattern);
    // Views of several cameras are refused before the long work.
    const camera::ExifInfo exif =
        opts->project.empty() ? camera::ExifInfo{} : views_camera(opts->images);
    const auto out = photogrammetry::calibrate_from_images(opts->images, pattern);
    for (const auto& image : out.images)
      if (!image.pattern_found) std::cout << "no pattern found: " << image.path << "\n";
    for (const auto& v : out.result.views) {
      char line[256];
      std::snprintf(line, sizeof line, "%-32s %7.3f px%s\n", v.name.c_str(), v.rms_px,
                    v.outlier ? "  outlier: left out, retake this view" : "");
      std::cout << line;
    }
    // Said before the figures are stored: the user can retake views now.
    const auto coverage = photogrammetry::calibration_coverage(out.views, out.result, out.size);
    if (coverage.poor()) std::cout << "warning: " << coverage.warning() << "\n";
    photogrammetry::CameraIntrinsics cam = out.result.intrinsics;
    cam.body = opts->body;
    cam.lens = opts->lens;
    cam.focus = opts->focus;
    storage::save_camera_json(opts->out, cam);
    if (!opts->project.empty()) {
      storage::ProjectInfo info;
      info.name = std::filesystem::path(opts->project).stem().string();
      storage::ProjectStore store = storage::ProjectStore::open_or_create(opts->project, info);
      if (store.read_only())
        throw InputError(opts->project,
                         "cannot store the calibration: " + store.read_only_reason());
      storage::CameraBody body{0, exif.make, exif.model, exif.serial};
      if (body.model.empty()) body.model = opts->body.empty() ? "unknown" : opts->body;
      if (body.make.empty()) body.make = "unknown";
      storage::Calibration c;
      c.body_id = store.save_camera_body(body);
      c.intrinsics = cam;
      // The library matches a photograph's EXIF lens: the views' own, when
      // they name it (the --lens text stays in the camera file).
      if (!exif.lens.empty()) c.intrinsics.lens = exif.lens;
      c.focal_setting_mm = exif.focal_length_mm.value_or(0);
      c.method = opts->pattern;
      const storage::RecordId id = store.save_calibration(c);
      photogrammetry::PhotoCamera described = camera::photo_camera(exif);
      described.width = cam.width;
      described.height = cam.height;
      std::cout << "stored in " << opts->project << " as calibration " << id << " of "
                << described.described() << "\n";
    }
    std::cout << "RMS " << format_fixed(out.result.rms_px, 3, " px") << " over "
              << out.result.views_used() << " view(s); fx " << format_fixed(cam.fx, 2) << " fy "
              << format_fixed(cam.fy, 2) << " cx " << format_fixed(cam.cx, 2) << " cy "
              << format_fixed(cam.cy, 2) << "; written to " << opts->out << "\n";
    return 0;
  };
}

const VerbRegistrar calibrate_verb{
    "calibrate", "camera calibration from views of a chessboard or circle grid", setup_calibrate};

}  // namespace
}  // namespace rockface::app

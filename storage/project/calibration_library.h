#pragma once
// The project's calibrations as a library (issue 42): one per camera body
// (make, model, serial number), lens and focal setting, and a photograph
// given the calibration of the camera that took it, read from its EXIF.
// Before, the tablet took the project's newest calibration whatever body
// and lens had taken the pair.
//
// A calibration fits a photograph when the image size is the same (a
// calibration is in pixels of one size), and the body, the lens and the
// focal setting are the same wherever both sides know them (a zoom lens is
// taped at its setting: 0.5 mm apart is another setting). Of those that
// fit, the newest is taken.
#include <optional>
#include <string>

#include "core/photogrammetry/camera/photo_camera.h"
#include "storage/project/project_store.h"

namespace rockface::storage {

using photogrammetry::PhotoCamera;

struct CalibrationChoice {
  std::optional<Calibration> calibration;
  // When none fits: what the photograph needs and what to do, for the
  // geologist ("no calibration of ... in the project: calibrate ...").
  std::string refusal;
};

CalibrationChoice choose_calibration(ProjectStore& store, const PhotoCamera& photo);

// Whether `calibration` (of `body`, when it has one) fits the photograph;
// `why` names the first difference when it does not.
bool calibration_fits(const Calibration& calibration, const std::optional<CameraBody>& body,
                      const PhotoCamera& photo, std::string* why = nullptr);

// The camera that took a capture, kept with it as its settings
// camera_make, camera_model, camera_serial, camera_lens and
// camera_focal_mm (issue 42: the tablet knew the body's serial over USB,
// chose its calibration by it, and stored nothing of it). Empty fields are
// left out.
void record_camera(Capture& capture, const PhotoCamera& photo);

// The camera a capture records (settings camera_*), or nothing when the
// capture was stored without it (before this record existed).
std::optional<PhotoCamera> recorded_camera(const Capture& capture);

}  // namespace rockface::storage

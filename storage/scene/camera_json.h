#pragma once
// The camera file (SCENE.md, format rockface-camera/1): one calibration of a
// body + lens + focal setting, OpenCV's Brown model.
//
//   { "format": "rockface-camera/1", "model": "opencv-brown",
//     "width": 6000, "height": 4000, "fx": 8930.1, "fy": 8929.7, "cx": 3001.2, "cy": 1998.4,
//     "distortion": [k1, k2, p1, p2, k3], "rms_px": 0.21,
//     "body": "Nikon D7500", "lens": "18-55 @ 24 mm", "focus": "locked" }
//
// Reading checks every field and throws InputError naming the file and the
// field ("site.camera.json: fx: must be positive").
#include <string>

#include "core/photogrammetry/camera/camera_model.h"

namespace rockface::storage {

photogrammetry::CameraIntrinsics parse_camera_json(const std::string& text,
                                                   const std::string& source);
photogrammetry::CameraIntrinsics load_camera_json(const std::string& path);

std::string camera_json_text(const photogrammetry::CameraIntrinsics& camera);
// Written atomically (temporary file, then rename).
void save_camera_json(const std::string& path, const photogrammetry::CameraIntrinsics& camera);

}  // namespace rockface::storage

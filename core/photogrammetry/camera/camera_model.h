#pragma once
// The pinhole camera with Brown distortion (OpenCV's model: k1, k2, p1, p2,
// k3) and the pose of a camera station. Shared by calibration, the mock
// camera's renderer, reconstruction and registration.
//
// Pixel coordinates follow OpenCV: (0, 0) is the centre of the top-left
// pixel. Camera axes: z forward, x right, y down.
#include <array>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rockface::photogrammetry {

struct CameraIntrinsics {
  int width = 0, height = 0;               // pixels
  double fx = 0, fy = 0, cx = 0, cy = 0;   // pixels
  std::array<double, 5> distortion{};      // k1, k2, p1, p2, k3
  double rms_px = 0;                       // calibration RMS reprojection error, 0 if unknown
  // Provenance of a calibration (SCENE.md camera format); free text.
  std::string body, lens, focus;

  Eigen::Matrix3d K() const {
    Eigen::Matrix3d k;
    k << fx, 0, cx, 0, fy, cy, 0, 0, 1;
    return k;
  }
  bool has_distortion() const {
    for (double d : distortion)
      if (d != 0) return true;
    return false;
  }
};

// A camera station: world-to-camera rotation and the centre in world
// coordinates. x_cam = R (x_world - centre).
struct CameraPose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();

  Eigen::Vector3d to_camera(const Eigen::Vector3d& x_world) const { return R * (x_world - centre); }
  Eigen::Vector3d translation() const { return -R * centre; }  // t of [R | t]
};

}  // namespace rockface::photogrammetry

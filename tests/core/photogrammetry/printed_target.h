#pragma once
// A printed range-pole target seen by a pinhole camera, drawn by a small ray
// caster of its own (not camera/synthetic_renderer): each pixel is
// supersampled, every sample's ray is cut with the target's plane and takes
// the white disk's, the black ring's or the background's grey. So the
// detector is tried on targets of any design, tilt and size, with their
// centres known exactly.
#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/photogrammetry/camera/camera_model.h"

namespace rockface::test {

struct PrintedTarget {
  Eigen::Vector3d centre;          // camera frame, m
  Eigen::Vector3d normal;          // unit, toward the camera
  double white_radius = 0.05;      // m
  double ring_ratio = 2.0;         // ring's outer diameter / the disk's
  double white = 240, black = 14;  // grey levels as printed, in full light
};

// Pixel (0, 0) is the centre of the top-left pixel (SCENE.md).
inline Eigen::Vector2d project_point(const Eigen::Vector3d& p,
                                     const photogrammetry::CameraIntrinsics& cam) {
  return {cam.fx * p.x() / p.z() + cam.cx, cam.fy * p.y() / p.z() + cam.cy};
}

// Paints `t` into the 8-bit grey `image`, `supersample` x `supersample` rays a pixel.
inline void paint_target(cv::Mat& image, const PrintedTarget& t,
                         const photogrammetry::CameraIntrinsics& cam, int supersample = 8) {
  const double outer = t.white_radius * t.ring_ratio;
  // Bounding box of the ring's image, from points on its outline.
  const Eigen::Vector3d a = t.normal.unitOrthogonal(), b = t.normal.cross(a);
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (int k = 0; k < 64; ++k) {
    const double phi = 2 * M_PI * k / 64;
    const Eigen::Vector2d p =
        project_point(t.centre + outer * (std::cos(phi) * a + std::sin(phi) * b), cam);
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  }
  const int c0 = std::max(0, static_cast<int>(std::floor(x0)) - 2);
  const int c1 = std::min(image.cols - 1, static_cast<int>(std::ceil(x1)) + 2);
  const int r0 = std::max(0, static_cast<int>(std::floor(y0)) - 2);
  const int r1 = std::min(image.rows - 1, static_cast<int>(std::ceil(y1)) + 2);
  const double plane = t.normal.dot(t.centre);
  for (int y = r0; y <= r1; ++y)
    for (int x = c0; x <= c1; ++x) {
      const double background = image.at<uchar>(y, x);
      double sum = 0;
      for (int i = 0; i < supersample; ++i)
        for (int j = 0; j < supersample; ++j) {
          const double u = x - 0.5 + (j + 0.5) / supersample;
          const double v = y - 0.5 + (i + 0.5) / supersample;
          const Eigen::Vector3d ray((u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, 1.0);
          const double r = (plane / t.normal.dot(ray) * ray - t.centre).norm();
          sum += r <= t.white_radius ? t.white : r <= outer ? t.black : background;
        }
      image.at<uchar>(y, x) = cv::saturate_cast<uchar>(sum / (supersample * supersample));
    }
}

}  // namespace rockface::test

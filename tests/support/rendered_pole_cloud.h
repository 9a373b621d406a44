#pragma once
// A coloured point cloud of a rendered face with its range pole, as a
// scanner with a camera gives one (issue 43): the left station's rendered
// picture and depth (camera/synthetic_renderer.h) taken back into 3D pixel
// by pixel (every `stride`-th pixel in each direction: the density), each
// point the colour of its pixel and moved by the scanner's noise, then
// carried into a local frame by a known similarity (a drone model in its
// software's units, a scanner's own frame). The truth is the scene's: the
// pole's target centres (camera::range_pole_targets) carried by the same
// similarity, never anything the detector computed.
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "camera/synthetic_renderer.h"
#include "camera/synthetic_scene.h"
#include "core/common/progress.h"

namespace rockface::testing {

// local = scale R site + t.
struct LocalFrame {
  double scale = 1;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return scale * (R * p) + t; }
};

struct RenderedPoleCloud {
  std::vector<Eigen::Vector3d> points;               // the local frame
  std::vector<std::array<std::uint8_t, 3>> colours;  // RGB
  std::array<Eigen::Vector3d, 2> targets;  // true centres, lower and upper, the local frame
  Eigen::Vector3d toward_scanner = Eigen::Vector3d::Zero();  // unit, the local frame
  double spacing = 0;  // the sampling's median footprint on the surface, the local frame's units
};

inline RenderedPoleCloud rendered_pole_cloud(const camera::SyntheticScene& scene, int stride,
                                             double noise_m, const LocalFrame& frame,
                                             unsigned seed = 43) {
  NoProgress quiet;
  const photogrammetry::CameraIntrinsics k = camera::rendered_intrinsics(scene);
  const camera::SyntheticView view = camera::render_view(scene, 0, k, true, quiet);
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, noise_m);
  RenderedPoleCloud c;
  std::vector<double> footprint;
  for (int v = 0; v < view.depth.rows; v += stride)
    for (int u = 0; u < view.depth.cols; u += stride) {
      const double z = view.depth.at<float>(v, u);
      if (!(z > 0)) continue;  // nothing hit: no return
      const Eigen::Vector3d in_camera((u - k.cx) / k.fx * z, (v - k.cy) / k.fy * z, z);
      Eigen::Vector3d site = view.pose.R.transpose() * in_camera + view.pose.centre;
      site += Eigen::Vector3d(noise(random), noise(random), noise(random));
      c.points.push_back(frame.apply(site));
      const cv::Vec3b bgr = view.image.at<cv::Vec3b>(v, u);
      c.colours.push_back({bgr[2], bgr[1], bgr[0]});
      footprint.push_back(stride * z / k.fx * frame.scale);
    }
  std::nth_element(footprint.begin(), footprint.begin() + static_cast<long>(footprint.size() / 2),
                   footprint.end());
  c.spacing = footprint[footprint.size() / 2];
  const auto truth = camera::range_pole_targets(scene);
  for (std::size_t i = 0; i < 2 && i < truth.size(); ++i)
    c.targets[i] = frame.apply(truth[i].centre);
  c.toward_scanner =
      frame.R * (scene.stations[0].position - scene.stations[0].look_at).normalized();
  return c;
}

}  // namespace rockface::testing

#include "camera/synthetic_renderer.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "tests/camera/test_scene.h"

namespace rockface::camera {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

const SyntheticRender& rendered() {
  static const SyntheticRender r = [] {
    NoProgress quiet;
    return render_scene(test::small_tunnel_scene(), quiet);
  }();
  return r;
}

// Centre of the white inner disk of a target, measured in the image alone:
// grey-level weighted moments inside a circle that lies on the black ring
// (so nothing of the rock around the target enters). Black and white levels
// are taken from the window itself.
Vector2d white_disk_centroid(const cv::Mat& bgr, const Vector2d& near, double ring_radius_px) {
  cv::Mat grey;
  cv::extractChannel(bgr, grey, 1);
  const double mask_r = 0.75 * ring_radius_px;  // between white edge (0.5) and black edge (1.0)
  const int x0 = static_cast<int>(std::floor(near.x() - mask_r)) - 1;
  const int y0 = static_cast<int>(std::floor(near.y() - mask_r)) - 1;
  const int x1 = static_cast<int>(std::ceil(near.x() + mask_r)) + 1;
  const int y1 = static_cast<int>(std::ceil(near.y() + mask_r)) + 1;
  std::vector<uchar> values;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      if (std::hypot(x - near.x(), y - near.y()) <= mask_r) values.push_back(grey.at<uchar>(y, x));
  std::sort(values.begin(), values.end());
  const double black = values[values.size() / 20];
  const double white = values[values.size() - 1 - values.size() / 50];
  double sw = 0, sx = 0, sy = 0;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      if (std::hypot(x - near.x(), y - near.y()) > mask_r) continue;
      const double w = std::clamp((grey.at<uchar>(y, x) - black) / (white - black), 0.0, 1.0);
      sw += w;
      sx += w * x;
      sy += w * y;
    }
  return {sx / sw, sy / sw};
}

Vector2d project(const Vector3d& x, const photogrammetry::CameraPose& pose,
                 const photogrammetry::CameraIntrinsics& cam) {
  const Vector3d c = pose.to_camera(x);
  std::vector<cv::Point3d> in{{c.x(), c.y(), c.z()}};
  std::vector<cv::Point2d> out;
  const cv::Matx33d K(cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1);
  const cv::Vec<double, 5> d(cam.distortion[0], cam.distortion[1], cam.distortion[2],
                             cam.distortion[3], cam.distortion[4]);
  cv::projectPoints(in, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, d, out);
  return {out[0].x, out[0].y};
}

TEST(SyntheticRenderer, StationPoseHasNoRollAndLooksAtTheTarget) {
  const SyntheticStation st{{2, 3, 1}, {5, 9, 4}};
  const auto pose = station_pose(st, "s");
  const Vector3d ahead = pose.to_camera(st.look_at);
  EXPECT_NEAR(ahead.x(), 0, 1e-12);
  EXPECT_NEAR(ahead.y(), 0, 1e-12);
  EXPECT_GT(ahead.z(), 0);
  // Image x horizontal, image up (-y) toward +z.
  EXPECT_NEAR(pose.R.row(0).z(), 0, 1e-12);
  EXPECT_LT(pose.R.row(1).z(), 0);
  EXPECT_NEAR(pose.R.determinant(), 1, 1e-12);
  EXPECT_THROW(station_pose({{0, 0, 0}, {0, 0, 5}}, "imaging.stations[1]"), InputError);
  EXPECT_THROW(station_pose({{1, 1, 1}, {1, 1, 1}}, "imaging.stations[0]"), InputError);
}

TEST(SyntheticRenderer, SameSceneGivesTheSameImagesBitForBit) {
  auto scene = test::small_tunnel_scene();
  scene.effects.noise_sigma = 2.0;
  scene.effects.blur_px = 0.7;
  NoProgress quiet;
  const auto cam = rendered_intrinsics(scene);
  const auto a = render_view(scene, 1, cam, true, quiet);
  const auto b = render_view(scene, 1, cam, true, quiet);
  ASSERT_EQ(a.image.size(), b.image.size());
  EXPECT_EQ(cv::norm(a.image, b.image, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.depth, b.depth, cv::NORM_INF), 0.0);
  // A different texture seed gives a different picture: the sameness above
  // is not that of a constant image.
  scene.texture_seed = 8;
  const auto c = render_view(scene, 1, cam, false, quiet);
  EXPECT_GT(cv::norm(a.image, c.image, cv::NORM_L1), 1e6);
}

TEST(SyntheticRenderer, TargetCentresFromTruthLandOnTheRenderedTargets) {
  const auto& r = rendered();
  const auto scene = test::small_tunnel_scene();
  ASSERT_EQ(r.targets.size(), 2u);
  for (size_t t = 0; t < r.targets.size(); ++t)
    for (int s = 0; s < 2; ++s) {
      const auto& target = r.targets[t];
      ASSERT_TRUE(target.visible[s]) << "target " << t << " view " << s;
      // The truth's image centre is the projection of the true 3-D centre.
      const Vector2d projected = project(target.centre, r.poses[s], r.intrinsics);
      EXPECT_LT((projected - target.image[s]).norm(), 1e-9);
      const double depth = r.poses[s].to_camera(target.centre).z();
      const double ring_px = scene.range_pole->target_diameter / 2 * r.intrinsics.fx / depth;
      ASSERT_GT(ring_px, 10.0);  // large enough for a moment centroid
      const Vector2d measured = white_disk_centroid(r.images[s], target.image[s], ring_px);
      // Expected error: the perspective shift of an imaged disk's centroid
      // off its projected centre, f r^2 / Z^2 sin(tilt), is below 0.02 px for
      // a 6 cm disk at 8 m tilted ~10 degrees; anti-aliasing leaves a few
      // hundredths of a pixel. The bound is 0.1 px.
      EXPECT_LT((measured - target.image[s]).norm(), 0.1)
          << "target " << t << " view " << s << " measured " << measured.transpose() << " truth "
          << target.image[s].transpose();
    }
  // The two targets are exactly `length` apart, vertically.
  EXPECT_NEAR((r.targets[1].centre - r.targets[0].centre).norm(), 2.0, 1e-12);
}

TEST(SyntheticRenderer, DepthMapPutsEveryPixelOnARenderedSurface) {
  const auto& r = rendered();
  const auto scene = test::small_tunnel_scene();
  const auto& cam = r.intrinsics;
  const cv::Matx33d K(cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1);
  const cv::Vec<double, 5> d(cam.distortion[0], cam.distortion[1], cam.distortion[2],
                             cam.distortion[3], cam.distortion[4]);
  int checked = 0, background = 0;
  double worst = 0;
  for (int v = 0; v < cam.height; v += 7)
    for (int u = 0; u < cam.width; u += 7) {
      const float z = r.depth_left.at<float>(v, u);
      if (z == 0.f) {
        ++background;
        continue;
      }
      std::vector<cv::Point2d> px{{double(u), double(v)}}, n;
      cv::undistortPoints(px, n, K, d, cv::noArray(), cv::noArray(),
                          cv::TermCriteria(cv::TermCriteria::COUNT, 30, 0));
      const Vector3d x =
          r.poses[0].centre + r.poses[0].R.transpose() * Vector3d(n[0].x * z, n[0].y * z, z);
      // Distance to the nearest patch plane, or to the pole / target surfaces.
      double best = 1e9;
      for (const auto& p : scene.patches) {
        const Vector3d nrm =
            (p.polygon[1] - p.polygon[0]).cross(p.polygon[2] - p.polygon[0]).normalized();
        best = std::min(best, std::abs(nrm.dot(x - p.polygon[0])));
      }
      for (const auto& t : r.targets) best = std::min(best, std::abs(t.normal.dot(x - t.centre)));
      const Vector2d radial = x.head<2>() - scene.range_pole->base.head<2>();
      best = std::min(best, std::abs(radial.norm() - SyntheticDrawing::kPoleRadius));
      worst = std::max(worst, best);
      ++checked;
    }
  EXPECT_GT(checked, 5000);
  EXPECT_GT(background, 0);  // the sky above the face stays empty
  // float32 depth at 10-15 m keeps about 1e-6 relative: 2e-5 m; the bound
  // allows ten times that.
  EXPECT_LT(worst, 2e-4);
}

TEST(SyntheticRenderer, TrueTracesRunOverDarkPixels) {
  const auto& r = rendered();
  ASSERT_FALSE(r.traces.empty());
  cv::Mat grey;
  cv::cvtColor(r.images[0], grey, cv::COLOR_BGR2GRAY);
  cv::Mat background;
  cv::medianBlur(grey, background, 15);  // the rock around, without the thin trace
  std::vector<double> ratios;
  for (const auto& trace : r.traces) {
    for (const auto& p : trace.left_image) {
      const int u = static_cast<int>(std::lround(p.x())), v = static_cast<int>(std::lround(p.y()));
      if (u < 8 || v < 8 || u >= grey.cols - 8 || v >= grey.rows - 8) continue;
      ratios.push_back((grey.at<uchar>(v, u) + 1.0) / (background.at<uchar>(v, u) + 1.0));
    }
  }
  ASSERT_GT(ratios.size(), 100u);
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  // A trace darkens the rock by 85 % at its centre and is at least 2.4 px
  // wide here, so the pixel under the true line is far darker than its
  // surroundings; the median ratio stays well under one half (targets and
  // the pole crossing a trace are a small minority).
  EXPECT_LT(ratios[ratios.size() / 2], 0.5);
  // World polylines lie on their joint plane.
  const auto scene = test::small_tunnel_scene();
  for (const auto& trace : r.traces) {
    const auto joint = std::find_if(scene.joints.begin(), scene.joints.end(),
                                    [&](const auto& j) { return j.id == trace.joint; });
    ASSERT_NE(joint, scene.joints.end());
    for (const auto& x : trace.world) EXPECT_NEAR(joint->normal.dot(x - joint->point), 0, 1e-9);
  }
}

TEST(SyntheticRenderer, RockTextureHasMatchableDetailEverywhereOnTheFace) {
  const auto& r = rendered();
  cv::Mat grey, mean, sq;
  cv::cvtColor(r.images[0], grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(grey, CV_32F);
  cv::blur(grey, mean, {7, 7});
  cv::blur(grey.mul(grey), sq, {7, 7});
  int face = 0, flat = 0;
  for (int v = 50; v < 450; v += 5)
    for (int u = 50; u < 750; u += 5) {
      if (r.depth_left.at<float>(v, u) < 9.5f) continue;  // the face only (not floor, pole)
      ++face;
      const double sd = std::sqrt(
          std::max(0.f, sq.at<float>(v, u) - mean.at<float>(v, u) * mean.at<float>(v, u)));
      if (sd < 3.0) ++flat;
    }
  ASSERT_GT(face, 1000);
  // Block matching needs a few grey levels of local contrast in a 7x7
  // window; a flat colour would fail everywhere.
  EXPECT_LT(flat, face / 20) << flat << " of " << face << " windows are flat";
}

TEST(SyntheticRenderer, EffectsOnlyWhenSwitchedOn) {
  auto scene = test::small_tunnel_scene();
  scene.effects.distortion = false;
  EXPECT_FALSE(rendered_intrinsics(scene).has_distortion());
  EXPECT_TRUE(rendered_intrinsics(test::small_tunnel_scene()).has_distortion());
  NoProgress quiet;
  const auto clean = render_view(scene, 0, rendered_intrinsics(scene), false, quiet);
  scene.effects.exposure = 0.5;
  const auto dark = render_view(scene, 0, rendered_intrinsics(scene), false, quiet);
  EXPECT_NEAR(cv::mean(dark.image)[1], 0.5 * cv::mean(clean.image)[1], 1.0);  // rounding of 8 bits
}

}  // namespace
}  // namespace rockface::camera

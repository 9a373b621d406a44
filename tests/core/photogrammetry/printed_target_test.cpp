// Range-pole targets as printed by others: a white disk inside a black ring
// of any width (outer diameter 1.3 to 3 times the disk's), in front of light
// or dark rock, tilted, partly shadowed, blurred. Drawn by the test's own ray
// caster (printed_target.h), so the true centre is known exactly. And rock
// texture without any target: nothing may be found.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/common/units.h"
#include "core/photogrammetry/targets/circular_target.h"
#include "tests/core/photogrammetry/noise_texture.h"
#include "tests/core/photogrammetry/printed_target.h"

namespace rp = rockface::photogrammetry;
using rockface::test::PrintedTarget;

namespace {

rp::CameraIntrinsics test_camera() {
  rp::CameraIntrinsics c;
  c.width = 640;
  c.height = 480;
  c.fx = c.fy = 800;
  c.cx = 319.5;
  c.cy = 239.5;
  return c;
}

enum class Rock { light, dark };

// Rock texture stretched to a grey range: light limestone or dark basalt.
cv::Mat rock(Rock kind, int seed) {
  const rp::CameraIntrinsics cam = test_camera();
  cv::Mat t = rockface::test::noise_texture(cam.width, cam.height, seed, 1.5, 8.0);
  cv::Mat out;
  if (kind == Rock::light)
    t.convertTo(out, CV_8U, 100.0 / 255, 120);  // 120 .. 220
  else
    t.convertTo(out, CV_8U, 65.0 / 255, 5);  // 5 .. 70: as dark as the ring's ink
  return out;
}

enum class Condition { face_on, tilted_60, shadowed, blurred_2px };

std::string name(Condition c) {
  switch (c) {
    case Condition::face_on:
      return "face-on";
    case Condition::tilted_60:
      return "tilted 60 deg";
    case Condition::shadowed:
      return "partly shadowed";
    case Condition::blurred_2px:
      return "blurred 2 px";
  }
  return "";
}

struct Scene {
  cv::Mat image;
  PrintedTarget target;
  Eigen::Vector2d centre_px;  // truth
};

// A target 60 px across (the ring's outer diameter, face-on) 2 m away,
// off the optical axis.
Scene printed_scene(double ring_ratio, Rock rock_kind, Condition condition, int seed) {
  const rp::CameraIntrinsics cam = test_camera();
  Scene s;
  s.image = rock(rock_kind, seed);
  PrintedTarget& t = s.target;
  t.centre = Eigen::Vector3d(0.21, -0.13, 2.0);
  t.ring_ratio = ring_ratio;
  t.white_radius = 30.0 * t.centre.z() / cam.fx / ring_ratio;
  const Eigen::Vector3d to_camera = -t.centre.normalized();
  const double tilt = condition == Condition::tilted_60 ? 60.0 : 0.0;
  t.normal = Eigen::AngleAxisd(rockface::deg_to_rad(tilt), Eigen::Vector3d::UnitY()) * to_camera;
  rockface::test::paint_target(s.image, t, cam);
  s.centre_px = rockface::test::project_point(t.centre, cam);
  if (condition == Condition::shadowed) {
    // A shadow edge across the target, off its centre and slanted: the
    // shadowed side gets 45 % of the light (white and ring and rock alike).
    for (int y = 0; y < s.image.rows; ++y)
      for (int x = 0; x < s.image.cols; ++x)
        if ((x - s.centre_px.x() - 6) + 0.3 * (y - s.centre_px.y()) > 0)
          s.image.at<uchar>(y, x) = cv::saturate_cast<uchar>(0.45 * s.image.at<uchar>(y, x));
  }
  if (condition == Condition::blurred_2px) cv::GaussianBlur(s.image, s.image, cv::Size(0, 0), 2.0);
  return s;
}

// Distance from the truth of the nearer of the observation's two centre
// candidates (the pole's two views choose between them; face-on they agree).
double centre_error_px(const rp::TargetObservation& o, const Eigen::Vector2d& truth,
                       const rp::CameraIntrinsics& cam) {
  double best = 1e9;
  for (const auto& n : o.centre_normalised)
    best = std::min(
        best, (Eigen::Vector2d(cam.fx * n.x() + cam.cx, cam.fy * n.y() + cam.cy) - truth).norm());
  return best;
}

}  // namespace

TEST(PrintedTargets, FoundWhateverTheRingWidthBackgroundTiltShadowOrBlur) {
  const rp::CameraIntrinsics cam = test_camera();
  int seed = 100;
  for (double ratio : {1.3, 1.5, 2.0, 3.0})
    for (Rock rock_kind : {Rock::light, Rock::dark})
      for (Condition condition : {Condition::face_on, Condition::tilted_60, Condition::shadowed,
                                  Condition::blurred_2px}) {
        const Scene s = printed_scene(ratio, rock_kind, condition, ++seed);
        SCOPED_TRACE("ring ratio " + std::to_string(ratio) + ", " +
                     (rock_kind == Rock::light ? "light" : "dark") + " rock, " + name(condition));
        const auto found = rp::detect_targets(s.image, cam);
        ASSERT_EQ(found.size(), 1u);
        const double error = centre_error_px(found[0], s.centre_px, cam);
        // Sharp edges: the ray caster's 8 x 8 supersampling is the only
        // blur; the sub-pixel edge along ~200 rays puts the centre within
        // 0.02 px (measured), issue 16 asks for 0.1. A 2 px Gaussian blur is
        // symmetric about the centre and only mixes rock into the ring's
        // outer side: measured 0.02 px as well, so the same bound holds.
        EXPECT_LT(error, 0.1);
        if (rock_kind == Rock::light && condition == Condition::face_on) {
          // The ring's outer edge against light rock, located along rays to
          // about half a pixel, relative to the disk's outline from a
          // thresholded contour (good to about half a pixel too): on the
          // 10 px white radius of the 3.0 design, up to 0.1 in ratio.
          EXPECT_NEAR(found[0].ring_ratio, ratio, 0.1);
        }
      }
}

TEST(PrintedTargets, ThinRingFoundOnAShadowedDarkRockAt60DegreesWhenSharp) {
  // The case, in the worst combination of its conditions that keeps
  // the edge sharp.
  const rp::CameraIntrinsics cam = test_camera();
  Scene s = printed_scene(1.5, Rock::dark, Condition::tilted_60, 7);
  const auto found = rp::detect_targets(s.image, cam);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_LT(centre_error_px(found[0], s.centre_px, cam), 0.1);  // as above: sharp edge
}

TEST(PrintedTargets, NoTargetInAHundredFramesOfRockTexture) {
  // Textures from fine to coarse grain, light, dark and full-range, with
  // dark joint traces: every bright blob of rock ringed by darker rock is a
  // candidate the detector must turn down. ROCKFACE_TARGET_FREE_FRAMES runs
  // more frames by hand (docs/fuzzing.md).
  const rp::CameraIntrinsics cam = test_camera();
  const char* more = std::getenv("ROCKFACE_TARGET_FREE_FRAMES");
  const int frames = more ? std::max(100, std::atoi(more)) : 100;
  int false_positives = 0;
  for (int frame = 0; frame < frames; ++frame) {
    const double fine = 1.0 + 0.25 * (frame % 9);   // 1 .. 3 px grain
    const double coarse = 4.0 + 2.0 * (frame % 7);  // 4 .. 16 px
    cv::Mat t = rockface::test::noise_texture(cam.width, cam.height, 5000 + frame, fine, coarse);
    switch (frame % 3) {
      case 0:
        t.convertTo(t, CV_8U, 100.0 / 255, 120);
        break;  // light rock
      case 1:
        break;  // full range
      case 2:
        t.convertTo(t, CV_8U, 65.0 / 255, 5);
        break;  // dark rock
    }
    cv::RNG rng(frame);
    for (int k = 0; k < 3; ++k)
      cv::line(t, {rng.uniform(0, cam.width), rng.uniform(0, cam.height)},
               {rng.uniform(0, cam.width), rng.uniform(0, cam.height)}, cv::Scalar(10),
               rng.uniform(2, 6), cv::LINE_AA);
    const auto found = rp::detect_targets(t, cam);
    false_positives += static_cast<int>(found.size());
    for (const auto& f : found)
      ADD_FAILURE() << "frame " << frame << ": a target at (" << f.centre_px.x() << ", "
                    << f.centre_px.y() << "), " << f.white_diameter_px << " px";
  }
  RecordProperty("frames", frames);
  RecordProperty("false_positives", false_positives);
  EXPECT_EQ(false_positives, 0);
}

// Circular targets: the perspective bias of the ellipse centre and its
// correction, sub-pixel detection, and the errors when a target is missing.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/photogrammetry/camera/camera_cv.h"
#include "core/photogrammetry/targets/circular_target.h"

namespace rp = rockface::photogrammetry;

namespace {

rp::CameraIntrinsics test_camera() {
  rp::CameraIntrinsics c;
  c.width = 800;
  c.height = 600;
  c.fx = c.fy = 900;
  c.cx = 399.5;
  c.cy = 299.5;
  return c;
}

// Image of a circle of radius r at `centre` with unit `normal`, normalised coordinates.
std::vector<cv::Point2f> circle_image(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                                      double r, const rp::CameraIntrinsics& cam) {
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
  std::vector<cv::Point2f> pts;
  for (int k = 0; k < 360; ++k) {
    const double a = rockface::deg_to_rad(k);
    const Eigen::Vector3d p = centre + r * (std::cos(a) * u + std::sin(a) * v);
    pts.emplace_back(static_cast<float>(cam.fx * p.x() / p.z() + cam.cx),
                     static_cast<float>(cam.fy * p.y() / p.z() + cam.cy));
  }
  return pts;
}

}  // namespace

TEST(CircleFromConic, CorrectsTheEllipseCentreBiasOfAnObliqueCircle) {
  const rp::CameraIntrinsics cam = test_camera();
  // A 0.2 m disk 1.5 m away, off-axis and turned 55 deg from the line of sight.
  const Eigen::Vector3d centre(0.35, -0.2, 1.5);
  const Eigen::Vector3d to_camera = -centre.normalized();
  const Eigen::Vector3d normal =
      Eigen::AngleAxisd(rockface::deg_to_rad(55), Eigen::Vector3d::UnitY()) * to_camera;
  const auto pts = circle_image(centre, normal, 0.1, cam);
  const cv::RotatedRect e = cv::fitEllipse(pts);
  const Eigen::Vector2d truth(cam.fx * centre.x() / centre.z() + cam.cx,
                              cam.fy * centre.y() / centre.z() + cam.cy);
  const double bias = (Eigen::Vector2d(e.center.x, e.center.y) - truth).norm();
  // At this obliquity the ellipse centre is off by well over a pixel: the
  // correction matters.
  EXPECT_GT(bias, 0.5);

  const Eigen::Matrix3d K = cam.K();
  const rp::CircleFromConic c = rp::circle_from_conic(K.transpose() * rp::ellipse_conic(e) * K);
  double best_centre = 1e9, best_normal = 1e9;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector2d px(cam.fx * c.centre[k].x() + cam.cx, cam.fy * c.centre[k].y() + cam.cy);
    if ((px - truth).norm() < best_centre) {
      best_centre = (px - truth).norm();
      best_normal = rockface::rad_to_deg(std::acos(std::min(1.0, c.normal[k].dot(normal))));
    }
  }
  // The ellipse is fitted to 360 exact points in float: the conic is good to
  // ~1e-4 px, so the corrected centre matches to far better than 0.01 px and
  // the normal to a few hundredths of a degree.
  EXPECT_LT(best_centre, 0.01);
  EXPECT_LT(best_normal, 0.1);
}

TEST(CircleFromConic, FaceOnCircleHasOneCentre) {
  const rp::CameraIntrinsics cam = test_camera();
  const Eigen::Vector3d centre(0, 0, 2);
  const auto pts = circle_image(centre, -Eigen::Vector3d::UnitZ(), 0.1, cam);
  const Eigen::Matrix3d K = cam.K();
  const rp::CircleFromConic c =
      rp::circle_from_conic(K.transpose() * rp::ellipse_conic(cv::fitEllipse(pts)) * K);
  // Both candidate centres coincide with the principal point within the
  // float rounding of the fit (1e-5 in normalised units ~ 0.01 px).
  for (int k = 0; k < 2; ++k) EXPECT_LT(c.centre[k].norm(), 1e-5);
}

TEST(DetectTargets, FindsADrawnTargetToSubPixel) {
  const rp::CameraIntrinsics cam = test_camera();
  cv::Mat image(cam.height, cam.width, CV_8UC1, cv::Scalar(140));
  // Anti-aliased disks at a sub-pixel centre (OpenCV draws with 4 fractional bits).
  const int shift = 4;
  const cv::Point2d centre(312.3125, 205.6875);
  const cv::Point c16(static_cast<int>(centre.x * 16), static_cast<int>(centre.y * 16));
  cv::circle(image, c16, 20 * 16, cv::Scalar(10), cv::FILLED, cv::LINE_AA, shift);
  cv::circle(image, c16, 10 * 16, cv::Scalar(245), cv::FILLED, cv::LINE_AA, shift);
  const auto found = rp::detect_targets(image, cam);
  ASSERT_EQ(found.size(), 1u);
  // The edge is located along ~120 rays; anti-aliasing is the only error:
  // the centre is good to a few hundredths of a pixel.
  EXPECT_NEAR(found[0].centre_px.x(), centre.x, 0.05);
  EXPECT_NEAR(found[0].centre_px.y(), centre.y, 0.05);
  // Target diameter is the black disk: twice the white one. cv::circle's
  // anti-aliased disk of radius 10 reaches half a pixel further, so the white
  // edge at mid-grey lies at ~10.5 px: 42 px across, to half a pixel.
  EXPECT_NEAR(found[0].diameter_px, 42.0, 0.5);
}

TEST(DetectTargets, RockTextureAloneGivesNoTarget) {
  const rp::CameraIntrinsics cam = test_camera();
  cv::Mat image(cam.height, cam.width, CV_8UC1);
  cv::RNG rng(3);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(image, image, cv::Size(0, 0), 2.0);
  cv::normalize(image, image, 0, 255, cv::NORM_MINMAX);
  EXPECT_TRUE(rp::detect_targets(image, cam).empty());
}

TEST(FindRangePole, NamesWhereItLookedWhenNoTargetIsFound) {
  const rp::CameraIntrinsics cam = test_camera();
  const cv::Mat grey(cam.height, cam.width, CV_8UC1, cv::Scalar(120));
  rp::RelativeOrientation ro;
  try {
    rp::find_range_pole(grey, grey, cam, cam, ro);
    FAIL() << "expected an InputError";
  } catch (const rockface::InputError& e) {
    EXPECT_EQ(e.where(), "range pole");
    EXPECT_NE(e.reason().find("no target found in the left image"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("800x600"), std::string::npos) << e.what();
  }
}

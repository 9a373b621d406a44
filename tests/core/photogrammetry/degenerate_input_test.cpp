// Pairs that cannot be reconstructed: each gives a clear InputError naming
// what is wrong, never a crash or a meaningless model.
#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/photogrammetry/camera/camera_cv.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "tests/core/photogrammetry/noise_texture.h"

namespace rp = rockface::photogrammetry;

namespace {

rp::CameraIntrinsics camera() {
  rp::CameraIntrinsics c;
  c.width = 640;
  c.height = 480;
  c.fx = c.fy = 600;
  c.cx = 319.5;
  c.cy = 239.5;
  return c;
}

// A rock-like texture: noise blurred at two scales.
cv::Mat texture(int seed) {
  cv::Mat bgr;
  cv::cvtColor(rockface::test::noise_texture(640, 480, seed, 1.2, 6.0), bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

std::string error_of(const cv::Mat& left, const cv::Mat& right) {
  rockface::NoProgress progress;
  try {
    rp::reconstruct(left, right, camera(), camera(), rp::preset_fast(), {}, progress);
  } catch (const rockface::InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(DegenerateInput, IdenticalImages) {
  const cv::Mat t = texture(1);
  const std::string e = error_of(t, t.clone());
  EXPECT_NE(e.find("identical"), std::string::npos) << e;
}

TEST(DegenerateInput, NoOverlap) {
  const std::string e = error_of(texture(1), texture(2));
  EXPECT_NE(e.find("do not overlap"), std::string::npos) << e;
}

TEST(DegenerateInput, PureRotationBetweenTheShots) {
  // The camera turned 6 deg on the spot: the right image is the left one
  // warped by the homography K R K^-1; no base, no depth.
  const cv::Mat left = texture(1);
  const cv::Matx33d K = rp::camera_matrix(camera());
  cv::Matx33d R;
  cv::Rodrigues(cv::Vec3d(0.01, 0.105, 0.0), R);
  cv::Mat right;
  cv::warpPerspective(left, right, cv::Mat(K * R * K.inv()), left.size(), cv::INTER_LINEAR,
                      cv::BORDER_REFLECT);
  const std::string e = error_of(left, right);
  EXPECT_NE(e.find("pure rotation"), std::string::npos) << e;
}

TEST(DegenerateInput, AllBlackImage) {
  const cv::Mat black = cv::Mat::zeros(480, 640, CV_8UC3);
  const std::string e = error_of(texture(1), black);
  EXPECT_NE(e.find("right image"), std::string::npos) << e;
  EXPECT_NE(e.find("blank, black"), std::string::npos) << e;
}

TEST(DegenerateInput, ImageSizeDiffersFromCalibration) {
  const cv::Mat small = cv::Mat::zeros(240, 320, CV_8UC3);
  const std::string e = error_of(small, small);
  EXPECT_NE(e.find("calibrated at 640x480"), std::string::npos) << e;
}

TEST(DegenerateInput, CancelStopsTheWork) {
  rockface::CancelFlag cancel;
  cancel.cancel();
  const cv::Mat t = texture(1);
  EXPECT_THROW(rp::reconstruct(t, t, camera(), camera(), rp::preset_fast(), {}, cancel),
               rockface::Cancelled);
}

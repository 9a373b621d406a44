// Why a pick found no surface, read from the photograph (issue 39): each
// cause on a photograph made to have it — the truth is how the test drew
// the image, not what the contrast check measures.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/measure/no_surface_cause.h"

namespace rockface::measure {
namespace {

// A rock-like texture: white noise blurred to a few pixels' grain, scaled
// to `amplitude` grey levels rms around `mean`, plus sensor noise.
cv::Mat face(double mean, double amplitude, double noise, int seed) {
  cv::RNG rng(seed);
  cv::Mat grain(400, 600, CV_32F);
  rng.fill(grain, cv::RNG::NORMAL, 0, 1);
  cv::GaussianBlur(grain, grain, cv::Size(0, 0), 2.0);
  cv::Scalar m, s;
  cv::meanStdDev(grain, m, s);
  cv::Mat sensor(grain.size(), CV_32F);
  rng.fill(sensor, cv::RNG::NORMAL, 0, noise);
  cv::Mat f = mean + (grain - m[0]) * (amplitude / s[0]) + sensor;
  cv::Mat out;
  f.convertTo(out, CV_8U);  // saturates to 0-255 as a camera's JPEG does
  cv::Mat bgr;
  cv::cvtColor(out, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

const Eigen::Vector2d kMiddle(300, 200);

TEST(NoSurfaceCause, ADarkPartOfTheFaceIsSaidToBeTooDark) {
  // 12 grey levels with 0.8 of texture: an unlit corner of the face.
  const std::string why = no_surface_cause(face(12, 0.8, 0.8, 1), "left", kMiddle);
  EXPECT_NE(why.find("left photograph is too dark to match"), std::string::npos) << why;
  EXPECT_NE(why.find("light that part of the face"), std::string::npos) << why;
}

TEST(NoSurfaceCause, AUniformBrightPatchHasNoTexture) {
  // Shotcrete: mid grey, no grain, the sensor's noise only.
  const std::string why = no_surface_cause(face(140, 0.0, 1.0, 2), "right", kMiddle);
  EXPECT_NE(why.find("right photograph has no texture to match"), std::string::npos) << why;
}

TEST(NoSurfaceCause, AClippedPatchIsBurntOut) {
  const std::string why = no_surface_cause(face(252, 1.0, 1.0, 3), "left", kMiddle);
  EXPECT_NE(why.find("is burnt out"), std::string::npos) << why;
}

TEST(NoSurfaceCause, AWellLitTexturedPatchBlamesTheMatchNotTheLight) {
  // 25 grey levels of grain at mid grey: matchable; the hole is the
  // pair's (the other photograph, an occlusion), not the light's. Dark
  // but textured (mean 40, 6 levels) is no light problem either.
  for (const auto& [mean, amplitude] : {std::pair{120.0, 25.0}, std::pair{40.0, 6.0}}) {
    const std::string why = no_surface_cause(face(mean, amplitude, 1.0, 4), "left", kMiddle);
    EXPECT_NE(why.find("were not matched there"), std::string::npos) << mean << ": " << why;
  }
}

TEST(NoSurfaceCause, APickAtTheBorderOrWithoutAPhotographStillGetsACause) {
  // The window is cut by the border: still read from what is left.
  EXPECT_NE(no_surface_cause(face(12, 0.8, 0.8, 5), "left", {0, 0}).find("too dark"),
            std::string::npos);
  EXPECT_NE(no_surface_cause(cv::Mat(), "left", kMiddle).find("were not matched there"),
            std::string::npos);
}

}  // namespace
}  // namespace rockface::measure

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/photogrammetry/reconstruction/accuracy.h"
#include "core/photogrammetry/reconstruction/preset.h"

namespace rp = rockface::photogrammetry;

TEST(Accuracy, NormalCaseDepthPrecision) {
  rp::AccuracyInputs in;
  in.distance = 10;
  in.base = 1.6;
  in.focal_px = 2200;
  in.disparity_sigma_px = 0.3;
  in.inliers = 1000;
  in.overlap = 0.8;
  const rp::AccuracyPrediction p = rp::predict_accuracy(in);
  // sigma_Z = Z^2 sigma_d / (B f) = 100 * 0.3 / (1.6 * 2200), exactly.
  EXPECT_DOUBLE_EQ(p.sigma_z, 100 * 0.3 / (1.6 * 2200));
  EXPECT_DOUBLE_EQ(p.base_ratio, 0.16);
  EXPECT_TRUE(p.warnings.empty());
}

TEST(Accuracy, WarnsAboutTheCapture) {
  rp::AccuracyInputs in;
  in.distance = 20;
  in.base = 1.0;  // 1/20: too narrow
  in.focal_px = 2000;
  in.disparity_sigma_px = 0.3;
  in.inliers = 50;
  in.overlap = 0.3;
  in.smallest_target_px = 6.5;
  const auto p = rp::predict_accuracy(in);
  ASSERT_EQ(p.warnings.size(), 4u);
  EXPECT_NE(p.warnings[0].find("base/distance is 1/20.0"), std::string::npos) << p.warnings[0];
  EXPECT_NE(p.warnings[1].find("tie points"), std::string::npos);
  EXPECT_NE(p.warnings[2].find("overlap"), std::string::npos);
  EXPECT_NE(p.warnings[3].find("target too small: 6.5 px"), std::string::npos);

  in.base = 6;  // 1/3.3: too wide
  in.inliers = 5000;
  in.overlap = 0.9;
  in.smallest_target_px = 12;
  const auto wide = rp::predict_accuracy(in);
  ASSERT_EQ(wide.warnings.size(), 1u);
  EXPECT_NE(wide.warnings[0].find("wider than 1/5"), std::string::npos);
}

TEST(Presets, KnobsGrowFromFastToPrecise) {
  const auto f = rp::reconstruction_preset(rockface::Preset::fast),
             s = rp::reconstruction_preset(rockface::Preset::standard),
             p = rp::reconstruction_preset(rockface::Preset::precise);
  EXPECT_LT(f.dense_max_width, s.dense_max_width);
  EXPECT_LT(s.dense_max_width, p.dense_max_width);
  EXPECT_LT(f.max_features, s.max_features);
  EXPECT_LE(s.max_disparities, p.max_disparities);
  EXPECT_EQ(s.name, "standard");
  EXPECT_THROW(rp::reconstruction_preset(rockface::parse_preset("best", "--preset")),
               rockface::InputError);
  EXPECT_DOUBLE_EQ(rp::working_scale(6000, 1500), 0.25);
  EXPECT_DOUBLE_EQ(rp::working_scale(1200, 1600), 1.0);
  EXPECT_DOUBLE_EQ(rp::working_scale(6000, 0), 1.0);
}

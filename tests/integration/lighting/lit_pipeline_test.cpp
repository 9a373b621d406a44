// The pipeline on the face as a tunnel lights it: what still holds (the
// pole found, the scale right) and what is refused, by name.
#include <gtest/gtest.h>

#include "tests/support/lit_face.h"

using namespace rockface;
using namespace rockface::testing;

namespace {

TruthComparison expect_registered(const LitFaceOutcome& o) {
  EXPECT_TRUE(o.truth.has_value()) << o.refusal;
  return o.truth.value_or(TruthComparison{});
}

}  // namespace

TEST(LitPipeline, FlashIso3200Jpeg80KeepsThePoleAndTheScale) {
  camera::SyntheticEffects e;
  e.flash = camera::SyntheticFlash{1.0};
  e.sensor = camera::SyntheticSensor{3200};
  e.jpeg_quality = 80;
  const LitFaceOutcome o = reconstruct_lit_face(lit_face(e));
  const TruthComparison t = expect_registered(o);
  // Both targets found and centred as in daylight: ~35 px across, edges
  // along ~200 rays, the flash only raises their contrast; ISO 3200 noise
  // (~1 grey level) and JPEG 80 move the centre by a few hundredths of a px.
  EXPECT_LT(t.worst_target_px, 0.1);
  // The flash lights each view from its own camera, so the shading moves
  // between the views (measured spread 0.16, view_shading.h) and dense
  // matching runs on brightness-normalised images.
  EXPECT_TRUE(o.shading_normalised) << "shading spread " << o.shading.spread;
  // The fast preset's scale on this face is -0.4 % in daylight (its dense
  // matching at 1000 px); here measured -0.17 % (-1.1 % before the
  // normalisation, tools/bench tunnel_lighting_bench). Stated error: 0.6 %,
  // daylight's error and half as much again for the noise and JPEG.
  EXPECT_LT(std::abs(t.scale_error), 0.006);
  // North from the compass line picked on that surface: measured 0.64 deg
  // (0.5 before). Stated 1 deg.
  EXPECT_LT(std::abs(t.north_error_deg), 1.0);
  // The facets' dips: measured 0.68 deg (9.4 deg unnormalised; daylight
  // 0.35). Stated 1.5 deg: twice what is measured, far below the bias.
  EXPECT_LT(t.worst_facet_deg, 1.5);
}

TEST(LitPipeline, AFlashThatClipsTheNearRockNoLongerTiltsTheFacets) {
  camera::SyntheticEffects e;
  e.flash = camera::SyntheticFlash{2.0};
  const LitFaceOutcome o = reconstruct_lit_face(lit_face(e));
  const TruthComparison t = expect_registered(o);
  // Measured spread 0.15 against the limit 0.045: normalised, and said so.
  EXPECT_TRUE(o.shading_normalised) << "shading spread " << o.shading.spread;
  bool warned = false;
  for (const auto& w : o.warnings)
    warned |= w.find("light the face differently") != std::string::npos;
  EXPECT_TRUE(warned);
  // Unnormalised the facets came out 18.4 deg off and the scale -3.0 %;
  // normalised measured 0.29 deg and -0.16 %. Stated: 1 deg (three times
  // what is measured, daylight's 0.35 deg plus the clipped rock's loss of
  // texture) and 0.6 % (daylight's -0.4 % and half as much again).
  EXPECT_LT(t.worst_facet_deg, 1.0);
  EXPECT_LT(std::abs(t.scale_error), 0.006);
}

TEST(LitPipeline, ViewsLitAlikeAreMatchedAsTheyAre) {
  const LitFaceOutcome o = reconstruct_lit_face(lit_face(camera::SyntheticEffects{}));
  expect_registered(o);
  // Daylight: the same rock is equally bright in both views up to the
  // noise (measured spread 0.007, limit 0.045): no normalisation, so the
  // surface is the one matched before the check existed, and no warning.
  ASSERT_TRUE(o.shading.measured());
  EXPECT_LT(o.shading.spread, 0.02);
  EXPECT_FALSE(o.shading_normalised);
  for (const auto& w : o.warnings)
    EXPECT_EQ(w.find("light the face differently"), std::string::npos) << w;
}

TEST(LitPipeline, DustBeyondTheLimitIsRefusedByName) {
  camera::SyntheticEffects e;
  e.sensor = camera::SyntheticSensor{800};
  // Visibility 25 m: the face at 10 m keeps exp(-3.912 * 10 / 25) = 21 % of
  // its contrast, 1.4 grey levels of texture (image_contrast.h: 2 needed).
  e.dust = camera::SyntheticDust{3.912 / 25.0, 0.35};
  const LitFaceOutcome o = reconstruct_lit_face(lit_face(e));
  std::printf("refused: %s\n", o.refusal.c_str());
  ASSERT_FALSE(o.truth.has_value()) << "a face in dust of 25 m visibility was not refused";
  EXPECT_NE(o.refusal.find("left image"), std::string::npos) << o.refusal;
  EXPECT_NE(o.refusal.find("dust haze"), std::string::npos) << o.refusal;
}

TEST(LitPipeline, DustWithinTheLimitStillRegisters) {
  camera::SyntheticEffects e;
  e.sensor = camera::SyntheticSensor{800};
  e.dust = camera::SyntheticDust{3.912 / 40.0, 0.35};  // 2.5 grey levels of texture left
  const TruthComparison t = expect_registered(reconstruct_lit_face(lit_face(e)));
  // Measured -0.65 % (daylight -0.4 %): the haze flattens the texture the
  // dense matching sees. Stated error 1 %.
  EXPECT_LT(std::abs(t.scale_error), 0.01);
}

TEST(LitPipeline, NoiseOutweighingTheTextureIsRefusedByName) {
  camera::SyntheticEffects e;
  // ISO 51200 on a 40000 e- sensor: 60 e- at full scale, ~4.5 grey levels
  // of noise on 7 of texture; measured unrefused it came out 2 % in scale
  // and 6 deg in north.
  e.sensor = camera::SyntheticSensor{51200};
  const LitFaceOutcome o = reconstruct_lit_face(lit_face(e));
  std::printf("refused: %s\n", o.refusal.c_str());
  ASSERT_FALSE(o.truth.has_value());
  EXPECT_NE(o.refusal.find("sensor noise"), std::string::npos) << o.refusal;
}

TEST(LitPipeline, AnUnderExposedLowerTargetIsNamed) {
  camera::SyntheticEffects e;
  // A weak flash and strong vignetting: the lower target, 280 px below the
  // centre, gets 60 % of the light of the upper one; lamps between the
  // pole and the face light the rock, not the targets (which face away).
  e.flash = camera::SyntheticFlash{0.11};
  e.vignetting = 3.0;
  e.lamps.push_back({Eigen::Vector3d(-2.0, 8.0, 0.5), 4.0});
  e.lamps.push_back({Eigen::Vector3d(2.0, 8.0, 0.5), 4.0});
  const LitFaceOutcome o = reconstruct_lit_face(lit_face(e));
  std::printf("refused: %s\n", o.refusal.c_str());
  ASSERT_FALSE(o.truth.has_value()) << "registered with an under-exposed target";
  EXPECT_NE(o.refusal.find("range pole"), std::string::npos) << o.refusal;
  EXPECT_NE(o.refusal.find("lower target under-exposed"), std::string::npos) << o.refusal;
}

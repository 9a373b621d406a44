// The analysis's effects in words (issue 39): the report printed the stored
// keys ("imaging.noise_sigma"); every name the analysis and the synthetic
// camera store has its words, and no word left is a key.
#include <regex>

#include <gtest/gtest.h>

#include "core/analysis/effect_words.h"

namespace rockface::analysis {
namespace {

TEST(EffectWords, EveryStoredNameHasItsWords) {
  // The names SceneEffects::listed, the wedges' loads, the scene analysis and
  // camera::SyntheticEffects::simulated (prefixed by the replay) store.
  const std::vector<std::string> names{"gravity",
                                       "water",
                                       "seismic",
                                       "insitu_stress",
                                       "forces",
                                       "bolts",
                                       "shotcrete",
                                       "joint_law",
                                       "dynamics after failure",
                                       "imaging.distortion",
                                       "imaging.noise_sigma",
                                       "imaging.blur_px",
                                       "imaging.exposure",
                                       "imaging.flash",
                                       "imaging.lamps",
                                       "imaging.vignetting",
                                       "imaging.sensor",
                                       "imaging.jpeg_quality",
                                       "imaging.wet",
                                       "imaging.shotcrete",
                                       "imaging.dust"};
  const std::regex key(R"([a-z]+(\.|_)[a-z_]+)");
  for (const auto& n : names) {
    const std::string words = effect_in_words(n);
    EXPECT_FALSE(std::regex_search(words, key)) << n << " -> " << words;
    EXPECT_FALSE(words.empty()) << n;
  }
  EXPECT_EQ(effect_in_words("imaging.noise_sigma"), "sensor noise");
  EXPECT_EQ(effect_in_words("insitu_stress"), "in-situ stress");
  // The camera's shotcrete is a patch on the photograph, not a load.
  EXPECT_NE(effect_in_words("imaging.shotcrete"), effect_in_words("shotcrete"));
}

TEST(EffectWords, AnUnknownNameIsSpacedNotPrintedAsAKey) {
  EXPECT_EQ(effect_in_words("imaging.rain_drops"), "rain drops");
  EXPECT_EQ(effect_in_words("thermal_load"), "thermal load");
}

TEST(EffectWords, TheCameraFollowsTheAnalysisAfterItsLabel) {
  EXPECT_EQ(effects_in_words({"gravity", "water", "imaging.noise_sigma", "imaging.blur_px"}),
            "gravity, water pressure; simulated camera: sensor noise, blur");
  EXPECT_EQ(effects_in_words({}), "-");
  EXPECT_EQ(effects_in_words({"imaging.dust"}), "simulated camera: dust");
}

}  // namespace
}  // namespace rockface::analysis

#include "camera/capture_guidance.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace rockface::camera {
namespace {

ExifInfo shot(double focal, double focus, double f_number = 8, bool flash = false) {
  ExifInfo e;
  e.model = "NIKON D7500";
  e.focal_length_mm = focal;
  e.focus_distance_m = focus;
  e.f_number = f_number;
  e.flash_fired = flash;
  return e;
}

TEST(CaptureGuidance, MatchingPairPassesWithoutNotes) {
  EXPECT_TRUE(check_pair(shot(24, 10.0), shot(24, 10.0)).empty());
  EXPECT_NO_THROW(require_same_optics(shot(24, 10.0), shot(24, 10.05)));  // within EXIF steps
}

TEST(CaptureGuidance, DifferentFocalLengthIsRefusedWithBothValues) {
  try {
    require_same_optics(shot(24, 10), shot(35, 10));
    FAIL() << "a pair at 24 and 35 mm was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "stereo pair");
    EXPECT_NE(e.reason().find("24 mm"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("35 mm"), std::string::npos) << e.what();
  }
}

TEST(CaptureGuidance, RefocusIsRefused) {
  try {
    require_same_optics(shot(24, 10), shot(24, 6));
    FAIL() << "a refocused pair was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.reason().find("refocused"), std::string::npos) << e.what();
  }
}

TEST(CaptureGuidance, ApertureAndFlashAreWarningsNotRefusals) {
  const auto notes = check_pair(shot(24, 10, 8), shot(24, 10, 11, true));
  ASSERT_EQ(notes.size(), 2u);
  for (const auto& n : notes) EXPECT_EQ(n.severity, GuidanceNote::Severity::warning);
  EXPECT_NO_THROW(require_same_optics(shot(24, 10, 8), shot(24, 10, 11, true)));
}

TEST(CaptureGuidance, BaseLengthIsAnEighthToAFifthOfTheDistance) {
  const auto h = base_length_hint(10.0);
  EXPECT_DOUBLE_EQ(h.min_m, 1.25);
  EXPECT_DOUBLE_EQ(h.max_m, 2.0);
  EXPECT_NE(h.text.find("1.25 to 2.00 m"), std::string::npos) << h.text;
  EXPECT_THROW(base_length_hint(0), InputError);
  EXPECT_THROW(base_length_hint(-3), InputError);
}

}  // namespace
}  // namespace rockface::camera

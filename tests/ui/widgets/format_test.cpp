// Figures as the tablet shows them: unit, precision and the cases a field
// figure runs into (negative zero, 359.97°, a million points, nothing known).
#include <cmath>

#include <gtest/gtest.h>

#include "ui/app/text_check.h"
#include "ui/widgets/format.h"

namespace {

namespace f = rockface::ui::format;

TEST(Format, AnglesToATenthOfADegreeAndAzimuthsWithThreeDigits) {
  EXPECT_EQ(f::text(f::Angle{60.2349}), "60.2°");
  EXPECT_EQ(f::text(f::Angle{-0.01}), "0.0°");  // not "-0.0°"
  EXPECT_EQ(f::azimuth(5), "005.0°");
  EXPECT_EQ(f::azimuth(359.97), "000.0°");  // rounds to 360.0, which is north
  EXPECT_EQ(f::azimuth(-10), "350.0°");
  EXPECT_EQ(f::dip_and_direction(60.04, 199.94), "60.0° / 199.9°");
}

TEST(Format, LengthsInTheUnitThatFits) {
  EXPECT_EQ(f::text(f::Length{0.0021}), "2.1 mm");
  EXPECT_EQ(f::text(f::Length{0.013}), "13 mm");
  EXPECT_EQ(f::text(f::Length{0.85}), "0.85 m");
  EXPECT_EQ(f::text(f::Length{9.856444348058652}), "9.86 m");
  EXPECT_EQ(f::text(f::Length{123.456}), "123.5 m");
  EXPECT_EQ(f::text(f::Length{1250}), "1.25 km");
  EXPECT_EQ(f::plus_minus(f::Length{0.014137}), "± 14 mm");
}

TEST(Format, AreasVolumesAndFactorsOfSafety) {
  EXPECT_EQ(f::text(f::Area{2.5}), "2.50 m²");
  EXPECT_EQ(f::text(f::Volume{0.7391}), "0.739 m³");
  EXPECT_EQ(f::text(f::Volume{12.34}), "12.3 m³");
  EXPECT_EQ(f::text(f::Volume{0.0004}), "0.4 litres");
  EXPECT_EQ(f::text(f::FactorOfSafety{0.4987}), "0.50");
  EXPECT_EQ(f::text(f::FactorOfSafety{1e9}), "over 100");
}

TEST(Format, CountsAreIntegersWithTheirNoun) {
  EXPECT_EQ(f::count(1, "trace", "traces"), "1 trace");
  EXPECT_EQ(f::count(3, "trace", "traces"), "3 traces");
  EXPECT_EQ(f::count(0, "block", "blocks"), "0 blocks");
  EXPECT_EQ(f::count(150327, "point", "points"), "150,327 points");
  EXPECT_EQ(f::count(2345678, "point", "points"), "2.3 million points");
}

TEST(Format, DurationsFractionsRatiosPixels) {
  EXPECT_EQ(f::text(f::Duration{0.017}), "17 ms");
  EXPECT_EQ(f::text(f::Duration{3.25}), "3.2 s");
  EXPECT_EQ(f::text(f::Duration{125}), "2 min 05 s");
  EXPECT_EQ(f::text(f::Fraction{0.9006}), "90 %");
  EXPECT_EQ(f::one_in(0.18263278019891738), "1 : 5.5");
  EXPECT_EQ(f::pixels(0.030973252195296275), "0.03 px");
}

TEST(Format, UnknownFiguresSayWhy) {
  EXPECT_EQ(f::unknown(), "—");
  EXPECT_EQ(f::unknown("needs three or more targets"), "— (needs three or more targets)");
  EXPECT_EQ(f::text_or(std::optional<f::Angle>{}, "no relief"), "— (no relief)");
  EXPECT_EQ(f::text(f::Length{std::nan("")}), "—");
}

TEST(Format, PathsLoseTheirFoldersAndKeysBecomeWords) {
  EXPECT_EQ(f::file_name("/home/geo/site/face.rockface"), "face.rockface");
  EXPECT_EQ(f::without_folders("replay /tmp/x/tunnel-face-demo.scene.json"),
            "replay tunnel-face-demo.scene.json");
  EXPECT_EQ(f::without_folders("(/tmp/a/b.rockface: no tunnel) walk 1/8 to 1/5"),
            "(b.rockface: no tunnel) walk 1/8 to 1/5");
  EXPECT_EQ(f::in_words("range_pole_compass"), "range pole and compass line");
  EXPECT_EQ(f::in_words("some_new_kind"), "some new kind");
  // What a registration did, claiming no more (issue 42).
  EXPECT_EQ(f::registered_by("range_pole_compass"),
            "scaled and oriented by range pole and compass line");
  EXPECT_EQ(f::registered_by("range_pole"),
            "scaled and levelled by range pole; no north (no compass line)");
  EXPECT_EQ(f::registered_by("ground_control"), "scaled and oriented by control points");
  EXPECT_EQ(f::registered_by("none"),
            "not scaled or oriented (no range pole, control points or baseline)");
  EXPECT_EQ(f::date_time("2026-11-26T03:45:12Z"), "2026-11-26 03:45");
}

// No figure format gives a string the screen walk would refuse.
TEST(Format, NoFormattedFigureLooksLikeAKeyOrHasTooManyDigits) {
  for (const double v : {1e-9, 0.000123456789, 0.98327071179, 1.0, 12345.6789, 98765432.1}) {
    for (const std::string& s :
         {f::text(f::Angle{v}), f::text(f::Length{v}), f::text(f::Area{v}), f::text(f::Volume{v}),
          f::text(f::FactorOfSafety{v}), f::text(f::Duration{v}), f::text(f::Fraction{v}),
          f::pixels(v), f::factor(v), f::one_in(v), f::azimuth(v)}) {
      EXPECT_FALSE(rockface::ui::overlong_number(s)) << s;
      EXPECT_FALSE(rockface::ui::looks_like_key(s)) << s;
    }
  }
}

}  // namespace

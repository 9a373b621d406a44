// The one number formatter (core/common/number_format.h): decimals,
// significant digits, units, and the same text as the streams and printf
// calls it replaces, byte for byte.
#include "core/common/number_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

namespace rockface {
namespace {

TEST(NumberFormat, FixedDecimals) {
  EXPECT_EQ(format_fixed(12.345, 1), "12.3");
  EXPECT_EQ(format_fixed(12.35, 0), "12");
  EXPECT_EQ(format_fixed(199.9, 0), "200");
  EXPECT_EQ(format_fixed(0.5, 3), "0.500");
  EXPECT_EQ(format_fixed(-1.25, 2), "-1.25");
  EXPECT_EQ(format_fixed(2, -1), "2") << "negative decimals are none";
}

TEST(NumberFormat, SignificantDigits) {
  EXPECT_EQ(format_significant(0.012345, 3), "0.0123");
  EXPECT_EQ(format_significant(1234567, 3), "1.23e+06");
  EXPECT_EQ(format_significant(2.5, 6), "2.5") << "trailing zeros dropped";
  EXPECT_EQ(format_significant(120, 3), "120");
  EXPECT_EQ(format_significant(7.25, 0), "7") << "no digits is one, as printf says";
}

TEST(NumberFormat, RoundTripReadsBackAsTheSameDouble) {
  EXPECT_EQ(format_round_trip(0.1), "0.10000000000000001");
  EXPECT_EQ(format_round_trip(2.5), "2.5");
  EXPECT_EQ(format_round_trip(1234.5, " m"), "1234.5 m");
  for (const double v : {0.1 + 0.2, 1.0 / 3, 5211870.123456789, -7.5e-7, 6.02e23, 1e-300})
    EXPECT_EQ(std::stod(format_round_trip(v)), v) << format_round_trip(v);
}

TEST(NumberFormat, ZeroPaddedToAWidth) {
  EXPECT_EQ(format_zero_padded(45, 5, 1, "°"), "045.0°");
  EXPECT_EQ(format_zero_padded(7.4, 2, 0), "07");
  EXPECT_EQ(format_zero_padded(359.94, 5, 1), "359.9");
  EXPECT_EQ(format_zero_padded(1234.5, 3, 1), "1234.5") << "a longer value is never cut";
  EXPECT_EQ(format_zero_padded(-2.5, 6, 1), "-002.5") << "the sign counts in the width";
}

TEST(NumberFormat, TheUnitFollowsAsGiven) {
  EXPECT_EQ(format_fixed(0.853, 2, " m"), "0.85 m");
  EXPECT_EQ(format_fixed(60.24, 1, "°"), "60.2°");
  EXPECT_EQ(format_significant(1.0 / 250, 3, " s"), "0.004 s");
  EXPECT_EQ(format_fixed(87.4, 0, " %"), "87 %");
}

TEST(NumberFormat, SignOfZeroAndNonFiniteValuesAsPrintf) {
  EXPECT_EQ(format_fixed(-0.04, 1), "-0.0");
  EXPECT_EQ(format_fixed(std::numeric_limits<double>::quiet_NaN(), 2), "nan");
  EXPECT_EQ(format_fixed(std::numeric_limits<double>::infinity(), 2, " m"), "inf m");
  EXPECT_EQ(format_significant(-std::numeric_limits<double>::infinity(), 3), "-inf");
}

TEST(NumberFormat, AVeryLongNumberIsWhole) {
  const std::string text = format_fixed(1e300, 2);
  EXPECT_EQ(text.size(), 301u + 3u);
  EXPECT_EQ(text.substr(0, 2), "10");
  EXPECT_EQ(text.substr(text.size() - 3), ".00");
}

// The text the private formatters made with streams, for every value and
// precision they used: the one formatter must not change a byte of a report.
TEST(NumberFormat, SameTextAsTheStreams) {
  const double values[] = {0.0,  -0.0,      1e-9,    0.0049,  0.005,   0.125,  2.5,
                           -2.5, 12.3456,   99.95,   359.97,  1234.5,  1e7,    -1e-4,
                           1e21, 0.1 + 0.2, 1.0 / 3, 2.0 / 3, 6.02e23, -7.5e-7};
  for (const double v : values)
    for (int p = 0; p <= 10; ++p) {
      std::ostringstream fixed;
      fixed.setf(std::ios::fixed);
      fixed.precision(p);
      fixed << v;
      EXPECT_EQ(format_fixed(v, p), fixed.str()) << v << " to " << p << " decimals";
      std::ostringstream general;
      general.precision(p);
      general << v;
      EXPECT_EQ(format_significant(v, p), general.str()) << v << " to " << p << " digits";
    }
  // Bearings and dip directions were written "%05.1f", "%03.0f", "%02.0f".
  for (const double v : values)
    for (const auto& [width, decimals] : {std::pair{5, 1}, std::pair{3, 0}, std::pair{2, 0}}) {
      char printed[512];
      std::snprintf(printed, sizeof printed, "%0*.*f", width, decimals, v);
      EXPECT_EQ(format_zero_padded(v, width, decimals), printed) << v << " in " << width;
    }
  // tunnel_files wrote its tables with a stream of precision 17.
  for (const double v : values) {
    std::ostringstream seventeen;
    seventeen.precision(17);
    seventeen << v;
    EXPECT_EQ(format_round_trip(v), seventeen.str()) << v;
  }
}

}  // namespace
}  // namespace rockface

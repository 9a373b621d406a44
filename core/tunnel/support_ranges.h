#pragma once
// The ranges a geologist sets pattern bolts in, the ranges of the loads on
// a wedge, and the bound on the number of joint sets of one wedge analysis. Every reader of these
// values (the scene's wedges.support, `wedges --bolts`, analyse_wedges itself) checks them against
// the same numbers and says the range when it refuses one.
//
// Why ranges and not just "positive": the work of a wedge analysis grows
// with the number of bolts of the pattern (as 1 / spacing^2) and with the
// cube of the number of sets. A spacing of 5 mm took 26 s and 633 MB and
// one of 1 mm never ended (issue 41); no support design has either.
#include <cmath>
#include <string>

#include "core/common/number_format.h"

namespace rockface::tunnel {

struct SupportRange {
  double lo = 0, hi = 0;  // closed
  const char* unit = "";
  bool contains(double v) const { return std::isfinite(v) && v >= lo && v <= hi; }
  // "[0.3, 10] m"
  std::string text() const {
    // Appended piece by piece: GCC 12's -Wrestrict misreads a string literal
    // put before a std::string here.
    std::string t(1, '[');
    t += format_significant(lo, 6);
    t += ", ";
    t += format_significant(hi, 6);
    t += "] ";
    t += unit;
    return t;
  }
};

// Bolt length: from a short split set (0.3 m) to a long cable bolt (30 m).
inline constexpr SupportRange kBoltLengthRange{0.3, 30.0, "m"};
// Pattern spacing: from a dense pattern of 0.3 m (about 11 bolts per m^2)
// to a spot-bolting grid of 10 m. UnWedge's pattern default is 1 m.
inline constexpr SupportRange kBoltSpacingRange{0.3, 10.0, "m"};
// Capacity per bolt: from 1 kN (a friction bolt in soft rock) to 10 MN
// (far above a twin-strand cable's ~0.5 MN).
inline constexpr SupportRange kBoltCapacityRange{1e3, 1e7, "N"};
// Bond strength per metre of anchorage: 1 kN/m (poor grout in weak rock)
// to 100 MN/m (far above resin in strong rock, ~0.5 MN/m).
inline constexpr SupportRange kBoltBondRange{1e3, 1e8, "N/m"};
// Shotcrete's shear strength: 0.1 MPa (young shotcrete) to 10 MPa (strong
// fibre-reinforced), as the designer's support classes take it
// (storage/support/support_classes_json.cpp). 1e308 was taken and printed
// in 309 digits (issue 41).
inline constexpr SupportRange kShotcreteShearRange{1e5, 1e7, "Pa"};

// The loads on a wedge: a rock's density (pumice to the heaviest ores,
// 500-8000 kg/m^3, with room), a pseudo-static acceleration's size (design
// coefficients stay under 0.5 g), water's unit weight (fresh to brine,
// 9.8-12 kN/m^3, with room).
inline constexpr SupportRange kRockDensityRange{100, 20000, "kg/m^3"};
inline constexpr SupportRange kSeismicRange{0, 49.05, "m/s^2"};  // 5 g
inline constexpr SupportRange kWaterUnitWeightRange{1000, 100000, "N/m^3"};

// At most this many distinct joint sets in one wedge analysis (after sets
// within the orientation uncertainty of each other are merged): 12 sets
// give 220 triples of 8 pyramids each, a few seconds; a rock mass has
// rarely more than 5 sets (Barton's Jn counts "four or more sets" as one
// class). 40 sets took 97 s and 1.65 GB, 60 never ended (issue 41).
inline constexpr int kMaxWedgeSets = 12;

// "0.001 m is outside [0.3, 10] m (the range of a bolt pattern's spacing)".
inline std::string outside_range_text(double v, const SupportRange& r, const char* what) {
  return format_significant(v, 6) + " " + r.unit + " is outside " + r.text() + " (the range of " +
         what + ")";
}

}  // namespace rockface::tunnel

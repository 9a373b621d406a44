// Issue 41: the work of a wedge analysis is bounded by validated inputs.
// A bolt spacing of millimetres (the pattern's bolts grow as 1 / spacing^2)
// is refused naming the field and its range; sets within the orientation
// uncertainty of each other are one set (a set listed twice gave every
// wedge twice; three sets repeated never ended); more distinct sets than
// kMaxWedgeSets are refused naming the bound.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/error.h"
#include "core/geometry/orientation.h"
#include "core/tunnel/support_ranges.h"
#include "core/tunnel/wedge_analysis.h"
#include "tests/support/refusal.h"

namespace rockface::tunnel {
namespace {

using rockface::test::refusal;
constexpr double kRad = std::numbers::pi / 180.0;

std::vector<WedgeJointSet> three_sets() {
  return {{"J1", geometry::plane_normal_deg(60, 0), 30 * kRad, 0},
          {"J2", geometry::plane_normal_deg(60, 120), 30 * kRad, 0},
          {"J3", geometry::plane_normal_deg(60, 240), 30 * kRad, 0}};
}

TunnelFrame north_axis() {
  return axis_frame(0, 0, Eigen::Vector3d::Zero(), "axis");
}

WedgeAnalysis analyse(const std::vector<WedgeJointSet>& sets, const WedgeOptions& o = {}) {
  return analyse_wedges(rectangle_profile(6, 6, 0), north_axis(), Eigen::Vector3d::Zero(), sets, o);
}

WedgeOptions with_bolts(double length, double spacing, double capacity) {
  WedgeOptions o;
  PatternBolts b;
  b.length = length;
  b.spacing = spacing;
  b.capacity = capacity;
  o.bolts = b;
  return o;
}

TEST(WedgeBounds, BoltSpacingOfMillimetresIsRefusedWithItsRange) {
  EXPECT_EQ(refusal([] { analyse(three_sets(), with_bolts(3, 1e-3, 1e5)); }),
            "wedges.support.bolts.spacing: 0.001 m is outside [0.3, 10] m (the range of a bolt "
            "pattern's spacing)");
  EXPECT_EQ(refusal([] { analyse(three_sets(), with_bolts(3, 1e-320, 1e5)); }).substr(0, 29),
            "wedges.support.bolts.spacing:");
  EXPECT_EQ(refusal([] { analyse(three_sets(), with_bolts(1e5, 1, 1e5)); }),
            "wedges.support.bolts.length: 100000 m is outside [0.3, 30] m (the range of a bolt's "
            "length)");
  EXPECT_EQ(refusal([] { analyse(three_sets(), with_bolts(3, 1, 1e308)); }).substr(0, 30),
            "wedges.support.bolts.capacity:");
  // The ends of each range are a geologist's settings: accepted.
  EXPECT_EQ(refusal([] {
              analyse(three_sets(),
                      with_bolts(kBoltLengthRange.hi, kBoltSpacingRange.lo, kBoltCapacityRange.lo));
            }),
            "accepted");
}

TEST(WedgeBounds, ASetListedTwiceIsOneSetAndGivesEachWedgeOnce) {
  const WedgeAnalysis once = analyse(three_sets());
  std::vector<WedgeJointSet> twice = three_sets();
  WedgeJointSet again = twice[1];
  again.id = "J2b";
  twice.push_back(again);
  const WedgeAnalysis a = analyse(twice);
  ASSERT_FALSE(once.wedges.empty());
  ASSERT_EQ(a.wedges.size(), once.wedges.size());
  for (std::size_t i = 0; i < a.wedges.size(); ++i) {
    // One digit per set listed; the set left out is not involved ('2').
    EXPECT_EQ(a.wedges[i].code, once.wedges[i].code + "2");
    // The same wedge: the same planes, so the same volume to rounding.
    EXPECT_NEAR(a.wedges[i].mass.volume, once.wedges[i].mass.volume,
                1e-12 * once.wedges[i].mass.volume);
  }
  bool said = false;
  for (const auto& n : a.notes)
    said = said || n.find("sets J2 and J2b are one set") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(WedgeBounds, ThreeSetsRepeatedAreThreeSets) {
  // Each repetition 0.5 degrees off (within the 1 degree uncertainty).
  std::vector<WedgeJointSet> sets;
  for (int r = 0; r < 6; ++r)
    for (int s = 0; s < 3; ++s)
      sets.push_back({"J" + std::to_string(s + 1) + "." + std::to_string(r),
                      geometry::plane_normal_deg(60 + 0.1 * r, 120.0 * s), 30 * kRad, 0});
  const WedgeAnalysis a = analyse(sets);
  EXPECT_EQ(a.wedges.size(), analyse(three_sets()).wedges.size());
  for (const auto& w : a.wedges) EXPECT_EQ(w.code.size(), sets.size());
}

TEST(WedgeBounds, MoreDistinctSetsThanTheBoundAreRefused) {
  std::vector<WedgeJointSet> sets;
  for (int s = 0; s <= kMaxWedgeSets; ++s)
    sets.push_back({"J" + std::to_string(s + 1),
                    geometry::plane_normal_deg(30 + 4.0 * s, 360.0 * s / (kMaxWedgeSets + 1)),
                    30 * kRad, 0});
  EXPECT_EQ(refusal([&] { analyse(sets); }),
            "sets: 13 distinct joint sets; a wedge analysis takes at most 12 (its work grows with "
            "the cube of the number of sets): choose the sets that matter");
}

TEST(WedgeBounds, OneSetThreeTimesIsNotThreeSets) {
  std::vector<WedgeJointSet> sets(3, three_sets()[0]);
  EXPECT_EQ(refusal([&] { analyse(sets); }),
            "sets: a wedge needs three distinct joint sets; 3 given are 1 within 1.0 deg of each "
            "other");
}

// A density or a seismic acceleration of 1e308 overflowed the weight and
// was blamed on the shotcrete: each load is named in its own message.
TEST(WedgeBounds, EachLoadBeyondItsRangeIsRefusedByItsOwnName) {
  WedgeOptions heavy;
  heavy.density = 1e308;
  EXPECT_EQ(refusal([&] { analyse(three_sets(), heavy); }),
            "rock.density: 1e+308 kg/m^3 is outside [100, 20000] kg/m^3 (the range of a rock's "
            "density)");
  WedgeOptions quake;
  quake.seismic = Eigen::Vector3d(0, 1e308, 0);
  EXPECT_EQ(refusal([&] { analyse(three_sets(), quake); }),
            "effects.seismic.acceleration: 1e+308 m/s^2 is outside [0, 49.05] m/s^2 (the range of "
            "a pseudo-static acceleration's size)");
  WedgeOptions design;
  design.seismic = Eigen::Vector3d(0, 0.98, 0);
  EXPECT_EQ(refusal([&] { analyse(three_sets(), design); }), "accepted");
}

}  // namespace
}  // namespace rockface::tunnel

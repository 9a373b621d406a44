// The support the classifications call for: the Q-system chart (Grimstad &
// Barton 1993, NGI 2015) with Barton's bolt length and unsupported span,
// its category boundaries approached from both sides and met exactly, and
// Bieniawski's Table 4.6 row by RMR class with its boundaries and the span
// caveat.
#include <cmath>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/rockmass/q_support_chart.h"
#include "core/rockmass/rmr_support_guidelines.h"

namespace rockface::rockmass {
namespace {

// Formulas evaluated in double: a few ulps.
constexpr double kFormulaAbs = 1e-12;

// The Q of boundary k at De, from the line's own formula De = a Q^0.4.
double boundary_q(int k, double de) {
  const double at_q1 = q_chart_boundary_de(k, 1.0);  // a
  return std::pow(de / at_q1, 2.5);
}

TEST(QSupportChart, BoltLengthAndUnsupportedSpanAreBartonsFormulas) {
  // A 10 m major road tunnel (ESR 1.0): L = 2 + 0.15 x 10 / 1 = 3.5 m.
  const QSupport road = q_support({4.0, 10.0, 1.0});
  EXPECT_NEAR(road.bolt_length_m, 3.5, kFormulaAbs);
  EXPECT_NEAR(road.equivalent_dimension, 10.0, kFormulaAbs);
  // A 13 m minor road tunnel (ESR 1.3): the same De and bolt length.
  const QSupport minor = q_support({4.0, 13.0, 1.3});
  EXPECT_NEAR(minor.equivalent_dimension, 10.0, kFormulaAbs);
  EXPECT_NEAR(minor.bolt_length_m, 3.5, kFormulaAbs);
  // Largest unsupported span 2 ESR Q^0.4: Q = 1, ESR 1.6 -> 3.2 m;
  // Q = 10, ESR 1 -> 2 x 10^0.4 = 5.0238 m.
  EXPECT_NEAR(q_support({1.0, 5.0, 1.6}).max_unsupported_span_m, 3.2, kFormulaAbs);
  EXPECT_NEAR(q_support({10.0, 5.0, 1.0}).max_unsupported_span_m, 5.0237728630191596, 1e-12);
}

TEST(QSupportChart, TheFirstBoundaryIsTheLargestUnsupportedSpan) {
  // Q = 10, ESR 1: 5.02 m may stand unsupported. A 4 m drift is category 1,
  // a 7 m one category 2 (spot bolting); neither near a line.
  const QSupport narrow = q_support({10.0, 4.0, 1.0});
  EXPECT_EQ(narrow.category.number, 1);
  EXPECT_FALSE(narrow.marginal);
  EXPECT_GE(narrow.max_unsupported_span_m, 4.0);
  const QSupport wide = q_support({10.0, 7.0, 1.0});
  EXPECT_EQ(wide.category.number, 2);
  EXPECT_FALSE(wide.marginal);
  EXPECT_LT(wide.max_unsupported_span_m, 7.0);
  EXPECT_NEAR(q_chart_boundary_de(1, 10.0), wide.max_unsupported_span_m, kFormulaAbs);
}

TEST(QSupportChart, CategoriesAlongDeTenAreTheChartsReading) {
  // Read across the chart at De = 10 (a 10 m road tunnel, ESR 1), between
  // the limits Q = 55.9 | 10 | 4 | 1 | 0.4 | 0.1 | 0.022 | 0.004.
  const std::pair<double, int> reading[] = {{100, 1}, {20, 2},   {6, 3},    {2, 4},    {0.6, 5},
                                            {0.2, 6}, {0.05, 7}, {0.01, 8}, {0.002, 9}};
  for (const auto& [q, expected] : reading) {
    const QSupport s = q_support({q, 10.0, 1.0});
    EXPECT_EQ(s.category.number, expected) << "Q " << q;
    EXPECT_FALSE(s.marginal) << "Q " << q;
  }
  // What each asks for.
  const QSupport six = q_support({0.2, 10.0, 1.0});
  EXPECT_STREQ(six.category.ribs, "RRS I");
  EXPECT_DOUBLE_EQ(six.category.shotcrete_min_m, 0.12);
  EXPECT_DOUBLE_EQ(six.category.shotcrete_max_m, 0.15);
  EXPECT_TRUE(six.category.systematic_bolting);
  ASSERT_TRUE(six.bolt_spacing_shotcreted_m);
  // Between the chart's spacing lines 1.5 m (Q 0.1) and 1.7 m (Q 0.4).
  EXPECT_GT(*six.bolt_spacing_shotcreted_m, 1.5);
  EXPECT_LT(*six.bolt_spacing_shotcreted_m, 1.7);
  EXPECT_FALSE(six.bolt_spacing_unshotcreted_m);
  const QSupport seven = q_support({0.05, 10.0, 1.0});
  EXPECT_STREQ(seven.category.ribs, "RRS II");
  EXPECT_GT(seven.category.shotcrete_min_m, six.category.shotcrete_min_m);
  const QSupport spot = q_support({20, 10.0, 1.0});
  EXPECT_FALSE(spot.bolt_spacing_shotcreted_m);  // no sprayed concrete in category 2
  ASSERT_TRUE(spot.bolt_spacing_unshotcreted_m);
  EXPECT_DOUBLE_EQ(*spot.bolt_spacing_unshotcreted_m, 3.0);  // the chart's 3 m line, Q >= 10
  EXPECT_TRUE(q_support({0.002, 10.0, 1.0}).category.special_evaluation);
  // Q = 1 lies on the 2.0 m spacing line of the shotcreted area (and on
  // the boundary 4|5: category 5, marginal).
  const QSupport one = q_support({1.0, 10.0, 1.0});
  ASSERT_TRUE(one.bolt_spacing_shotcreted_m);
  EXPECT_DOUBLE_EQ(*one.bolt_spacing_shotcreted_m, 2.0);
}

// The 2015 legend's energy absorption of the fibre reinforced sprayed
// concrete, row by row: "Sfr (E500)+B" in category 4, "Sfr (E700)+B" in 5,
// "Sfr (E700)+RRS I+B" in 6, "Sfr (E1000)+RRS II+B" in 7, "CCA or Sfr
// (E1000)+RRS III+B" in 8; none where the legend gives no Sfr class (1-3, 9).
// Read at De = 10 across the chart (the categories of the test above).
TEST(QSupportChart, TheLegendsEnergyAbsorptionClassByCategory) {
  const struct {
    double q;
    int category;
    const char* energy_class;
    int joules;
  } legend[] = {{100, 1, "", 0},          {20, 2, "", 0},           {6, 3, "", 0},
                {2, 4, "E500", 500},      {0.6, 5, "E700", 700},    {0.2, 6, "E700", 700},
                {0.05, 7, "E1000", 1000}, {0.01, 8, "E1000", 1000}, {0.002, 9, "", 0}};
  for (const auto& row : legend) {
    const QSupport s = q_support({row.q, 10.0, 1.0});
    ASSERT_EQ(s.category.number, row.category) << "Q " << row.q;
    EXPECT_STREQ(s.category.energy_class, row.energy_class) << "category " << row.category;
    EXPECT_EQ(s.category.energy_absorption_j, row.joules) << "category " << row.category;
    // A class only with fibre reinforced sprayed concrete in the category.
    EXPECT_EQ(row.joules > 0, s.category.shotcrete_max_m > 0 && row.category >= 4);
  }
}

TEST(QSupportChart, EveryBoundaryFromBothSidesAndOnTheLine) {
  for (const double de : {2.0, 10.0, 35.0}) {
    for (int k = 1; k <= 8; ++k) {
      const double qb = boundary_q(k, de);
      // 30 % off the line: clearly on its side (the nearest other line is
      // at least a factor 2.5 away in Q), not marginal.
      const QSupport above = q_support({qb * 1.3, de, 1.0});
      const QSupport below = q_support({qb / 1.3, de, 1.0});
      EXPECT_EQ(above.category.number, k) << "De " << de << " k " << k;
      EXPECT_EQ(below.category.number, k + 1) << "De " << de << " k " << k;
      EXPECT_FALSE(above.marginal);
      EXPECT_FALSE(below.marginal);
      // 5 % off: the same sides, both marginal, each naming the other.
      const QSupport near_above = q_support({qb * 1.05, de, 1.0});
      const QSupport near_below = q_support({qb / 1.05, de, 1.0});
      EXPECT_EQ(near_above.category.number, k);
      EXPECT_EQ(near_below.category.number, k + 1);
      EXPECT_TRUE(near_above.marginal);
      EXPECT_TRUE(near_below.marginal);
      EXPECT_EQ(near_above.nearest_other, k + 1);
      EXPECT_EQ(near_below.nearest_other, k);
      // log10(1.05) = 0.0212 from the line; the line's Q from pow: 1e-12.
      EXPECT_NEAR(near_above.margin_log10, std::log10(1.05), 1e-12);
      // On the line: the heavier category, marginal, margin 0.
      const QSupport on = q_support({qb, de, 1.0});
      EXPECT_EQ(on.category.number, k + 1) << "De " << de << " k " << k;
      EXPECT_TRUE(on.marginal);
      EXPECT_EQ(on.margin_log10, 0.0);
      EXPECT_NE(on.marginal_note.find("heavier"), std::string::npos) << on.marginal_note;
    }
  }
}

TEST(QSupportChart, SweepingQAcrossALineChangesTheCategoryOnce) {
  // 2001 points across boundary 4|5 at De = 12 over a factor 2 each side:
  // one change, at the line, and every point within 10 % of it marginal.
  const double qb = boundary_q(4, 12.0);
  int changes = 0, last = 0;
  for (int i = -1000; i <= 1000; ++i) {
    const double q = qb * std::pow(2.0, i / 1000.0);
    const QSupport s = q_support({q, 12.0, 1.0});
    if (last != 0 && s.category.number != last) ++changes;
    last = s.category.number;
    if (std::abs(std::log10(q / qb)) < std::log10(1.1) - 1e-9) {
      EXPECT_TRUE(s.marginal) << q;
    }
  }
  EXPECT_EQ(changes, 1);
}

TEST(QSupportChart, EsrTableAndRefusals) {
  ASSERT_TRUE(esr_for("road_rail_major"));
  EXPECT_DOUBLE_EQ(esr_for("road_rail_major")->esr, 1.0);
  EXPECT_DOUBLE_EQ(esr_for("road_rail_minor")->esr, 1.3);
  EXPECT_DOUBLE_EQ(esr_for("permanent_mine")->esr, 1.6);
  EXPECT_DOUBLE_EQ(esr_for("public")->esr, 0.8);
  EXPECT_FALSE(esr_for("motorway"));
  try {
    q_support({0.0, 10.0, 1.0});
    FAIL() << "Q = 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "Q");
  }
  EXPECT_THROW(q_support({1.0, -3.0, 1.0}), InputError);
  EXPECT_THROW(q_support({1.0, 10.0, NAN}), InputError);
  // Off the chart: answered, and said.
  EXPECT_FALSE(q_support({2000, 10.0, 1.0}).notes.empty());
}

TEST(RmrSupportGuidelines, EachClassGivesItsRow) {
  const std::pair<double, int> by_rmr[] = {{90, 1}, {70, 2}, {50, 3}, {30, 4}, {10, 5}};
  for (const auto& [rmr, c] : by_rmr) {
    const RmrSupport s = rmr_support_guidelines(rmr, 10.0);
    EXPECT_EQ(s.row.rock_class, c) << rmr;
    EXPECT_FALSE(s.marginal) << rmr;
    EXPECT_FALSE(s.span_caveat) << rmr;
  }
  const RmrSupportRow& ii = rmr_support_row(2);
  EXPECT_DOUBLE_EQ(*ii.bolt_length_min_m, 3.0);
  EXPECT_DOUBLE_EQ(*ii.bolt_spacing_max_m, 2.5);
  EXPECT_DOUBLE_EQ(ii.shotcrete_crown_max_m, 0.05);
  EXPECT_FALSE(ii.steel_ribs);
  const RmrSupportRow& iii = rmr_support_row(3);
  EXPECT_DOUBLE_EQ(*iii.bolt_length_min_m, 4.0);
  EXPECT_DOUBLE_EQ(*iii.bolt_spacing_min_m, 1.5);
  EXPECT_DOUBLE_EQ(*iii.bolt_spacing_max_m, 2.0);
  EXPECT_TRUE(iii.systematic_bolts);
  const RmrSupportRow& iv = rmr_support_row(4);
  EXPECT_TRUE(iv.steel_ribs);
  EXPECT_DOUBLE_EQ(*iv.bolt_length_max_m, 5.0);
  const RmrSupportRow& v = rmr_support_row(5);
  EXPECT_DOUBLE_EQ(*v.bolt_length_max_m, 6.0);
  EXPECT_DOUBLE_EQ(v.shotcrete_crown_max_m, 0.20);
  EXPECT_NE(std::string(v.steel_sets).find("0.75 m"), std::string::npos);
  EXPECT_FALSE(rmr_support_row(1).bolt_length_min_m);  // spot bolting only
  EXPECT_THROW(rmr_support_row(6), InputError);
}

TEST(RmrSupportGuidelines, BoundariesAreMarginalOnTheTablesSide) {
  // 60 is class III (41-60), on the line to II.
  const RmrSupport on = rmr_support_guidelines(60, 10.0);
  EXPECT_EQ(on.row.rock_class, 3);
  EXPECT_TRUE(on.marginal);
  EXPECT_EQ(on.nearest_other, 2);
  EXPECT_EQ(on.margin_points, 0.0);
  // 61: class II by one point.
  const RmrSupport above = rmr_support_guidelines(61, 10.0);
  EXPECT_EQ(above.row.rock_class, 2);
  EXPECT_TRUE(above.marginal);
  EXPECT_EQ(above.nearest_other, 3);
  // 58 and 63: three points off, decided.
  EXPECT_FALSE(rmr_support_guidelines(57, 10.0).marginal);
  EXPECT_FALSE(rmr_support_guidelines(64, 10.0).marginal);
  EXPECT_EQ(rmr_support_guidelines(57, 10.0).row.rock_class, 3);
  EXPECT_EQ(rmr_support_guidelines(64, 10.0).row.rock_class, 2);
  EXPECT_THROW(rmr_support_guidelines(101, 10.0), InputError);
}

TEST(RmrSupportGuidelines, OtherSpansCarryTheCaveat) {
  EXPECT_FALSE(rmr_support_guidelines(50, 10.5).span_caveat);
  ASSERT_TRUE(rmr_support_guidelines(50, 14.0).span_caveat);
  EXPECT_NE(rmr_support_guidelines(50, 14.0).span_caveat->find("14.0 m"), std::string::npos);
  EXPECT_TRUE(rmr_support_guidelines(50, 6.0).span_caveat);
  EXPECT_TRUE(rmr_support_guidelines(50, std::nullopt).span_caveat);
}

}  // namespace
}  // namespace rockface::rockmass

// RMR89 and Q on a textbook case whose sums are worked by hand here from
// the printed tables, the refusal of an out-of-range entry by name, and a
// form left empty: the measured lines filled, the rest "not entered", no
// total.
#include <cmath>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/rockmass/q_system.h"
#include "core/rockmass/rmr89.h"

namespace rockface::rockmass {
namespace {

ClassificationForm textbook_form() {
  ClassificationForm f;
  f.ucs_mpa = 120;                          // A.1: 100-250 MPa -> 12
  f.aperture_mm = 0.5;                      // E: 0.1-1 mm -> 4
  f.roughness = Roughness::slightly_rough;  // E: 3
  f.infilling = Infilling::none;            // E: 6
  f.weathering = Weathering::slightly;      // E: 5
  f.groundwater = Groundwater::damp;        // A.5: 10
  f.jr = 1.5;                               // rough planar
  f.ja = 1.0;                               // unaltered walls
  f.jw = 1.0;                               // dry
  f.srf = 1.0;                              // medium stress
  f.esr = 1.0;                              // road tunnel
  f.span_m = 10.0;
  return f;
}

TEST(Rmr89, TextbookCaseSumsAsByHand) {
  MeasuredForRmr m;
  m.rqd_percent = 70;  // A.2: 50-75 -> 13
  m.spacing_m = 0.4;   // A.3: 0.2-0.6 m -> 10
  m.spacing_set = "S2";
  m.persistence_m = 2.0;                   // E: 1-3 m -> 4
  m.orientation = OrientationClass::fair;  // B tunnels: -5
  m.orientation_words = "S1: strike parallel to the axis, dip 20-45";
  const Rmr89 r = rmr89(m, textbook_form());
  // By hand: condition 4 + 4 + 3 + 6 + 5 = 22; basic 12 + 13 + 10 + 22 + 10 = 67;
  // adjusted 67 - 5 = 62: class II (61-80) good rock.
  ASSERT_TRUE(r.condition.rating);
  EXPECT_EQ(*r.condition.rating, 22);
  EXPECT_EQ(r.condition.source, Source::mixed);  // persistence measured, the rest entered
  ASSERT_TRUE(r.basic.value);
  EXPECT_EQ(*r.basic.value, 67);
  ASSERT_TRUE(r.adjusted.value);
  EXPECT_EQ(*r.adjusted.value, 62);
  ASSERT_TRUE(r.rock_class);
  EXPECT_EQ(*r.rock_class, 2);
  EXPECT_EQ(r.class_words, "II good rock");
  EXPECT_EQ(r.rqd.source, Source::measured);
  EXPECT_EQ(r.spacing.source, Source::measured);
  EXPECT_EQ(r.strength.source, Source::entered);
  EXPECT_EQ(r.groundwater.source, Source::entered);
  EXPECT_EQ(r.orientation.source, Source::measured);
  EXPECT_NE(r.rqd.table.find("A.2"), std::string::npos);
  EXPECT_NE(r.support.find("bolts in crown 3 m"), std::string::npos) << r.support;
}

TEST(Rmr89, TableBoundariesAreTheTables) {
  EXPECT_EQ(rmr_strength_ucs(250), 12);
  EXPECT_EQ(rmr_strength_ucs(250.1), 15);
  EXPECT_EQ(rmr_strength_ucs(0.5), 0);
  EXPECT_FALSE(rmr_strength_is50(0.8));  // the table asks for the UCS there
  EXPECT_EQ(*rmr_strength_is50(5), 12);
  EXPECT_EQ(rmr_rqd(90), 20);
  EXPECT_EQ(rmr_rqd(24), 3);
  EXPECT_EQ(rmr_spacing(2.5), 20);
  EXPECT_EQ(rmr_spacing(0.05), 5);
  EXPECT_EQ(rmr_inflow(0), 15);
  EXPECT_EQ(rmr_inflow(200), 0);
  EXPECT_EQ(rmr_class(81), 1);
  EXPECT_EQ(rmr_class(80), 2);
  EXPECT_EQ(rmr_class(20), 5);
}

TEST(QSystem, TextbookCaseAsByHand) {
  MeasuredForQ m;
  m.rqd_percent = 70;
  m.sets = 3;  // Jn 9
  m.random_joints = false;
  const QSystem q = q_system(m, textbook_form());
  // By hand: Q = (70 / 9) (1.5 / 1) (1 / 1) = 11.667: good (10-40).
  ASSERT_TRUE(q.q);
  EXPECT_NEAR(*q.q, 70.0 / 9.0 * 1.5, 1e-12);  // the same arithmetic: rounding only
  EXPECT_EQ(q.class_words, "good");
  EXPECT_EQ(q.jn.source, Source::measured);
  EXPECT_EQ(*q.jn.rating, 9);
  EXPECT_EQ(q.jr.source, Source::entered);
  // Barton's figures for span 10 m, ESR 1: largest unsupported span
  // 2 Q^0.4 = 5.35 m, bolts 2 + 1.5 = 3.5 m, roof pressure 98.1 (2/1.5) Q^-1/3.
  ASSERT_TRUE(q.max_unsupported_span_m);
  EXPECT_NEAR(*q.max_unsupported_span_m, 2 * std::pow(70.0 / 9.0 * 1.5, 0.4), 1e-9);
  EXPECT_NEAR(*q.bolt_length_m, 3.5, 1e-12);
  EXPECT_NEAR(*q.roof_pressure_kpa, 98.1 * 2 / 1.5 * std::pow(70.0 / 9.0 * 1.5, -1.0 / 3), 1e-9);
  EXPECT_NE(q.support.find("support needed"), std::string::npos) << q.support;
}

TEST(QSystem, JnFollowsTheSetsAndRandomJoints) {
  EXPECT_EQ(jn_from_sets(1, false), 2);
  EXPECT_EQ(jn_from_sets(2, true), 6);
  EXPECT_EQ(jn_from_sets(3, true), 12);
  EXPECT_EQ(jn_from_sets(5, false), 15);
  EXPECT_EQ(jn_words(3, true), "three sets plus random");
}

TEST(ClassificationForm, AnEnteredValueOutOfRangeIsRefusedByName) {
  ClassificationForm f = textbook_form();
  f.ja = 25;  // Ja's table ends at 20
  try {
    (void)q_system({}, f);
    FAIL() << "Ja 25 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "Ja");
    EXPECT_NE(e.reason().find("0.75-20"), std::string::npos) << e.reason();
  }
  f = textbook_form();
  f.ucs_mpa = -3;
  try {
    (void)rmr89({}, f);
    FAIL() << "UCS -3 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "ucs_mpa");
  }
  f = textbook_form();
  f.jw = std::nan("");
  EXPECT_THROW(validate(f), InputError);
}

TEST(ClassificationForm, AnEmptyFormGivesTheMeasuredLinesAndNoTotal) {
  MeasuredForRmr m;
  m.rqd_percent = 85;
  m.spacing_m = 0.7;
  m.spacing_set = "S1";
  m.persistence_m = 4;
  const ClassificationForm empty;
  ASSERT_TRUE(empty.empty());
  const Rmr89 r = rmr89(m, empty);
  EXPECT_EQ(r.rqd.source, Source::measured);
  EXPECT_EQ(*r.rqd.rating, 17);
  EXPECT_EQ(*r.spacing.rating, 15);
  EXPECT_EQ(r.strength.source, Source::not_entered);
  EXPECT_FALSE(r.strength.rating);
  EXPECT_EQ(r.condition.source, Source::not_entered);
  EXPECT_EQ(r.groundwater.source, Source::not_entered);
  EXPECT_FALSE(r.basic.value);
  EXPECT_FALSE(r.adjusted.value);
  EXPECT_FALSE(r.rock_class);
  EXPECT_EQ(r.basic.partial, 32);
  // Open: strength 0-15, condition 0-30, groundwater 0-15.
  EXPECT_EQ(r.basic.lowest, 32);
  EXPECT_EQ(r.basic.highest, 92);
  EXPECT_EQ(r.basic.missing.size(), 3u);

  MeasuredForQ mq;
  mq.rqd_percent = 85;
  mq.sets = 2;
  const QSystem q = q_system(mq, empty);
  EXPECT_FALSE(q.q);
  EXPECT_TRUE(q.class_words.empty());
  EXPECT_EQ(q.missing.size(), 4u);  // Jr, Ja, Jw, SRF
  // RQD/Jn = 21.25 known; the open factors' ends: Jr 0.5-5, Ja 0.75-20, Jw 0.05-1, SRF 0.5-400.
  EXPECT_NEAR(*q.q_lowest, 21.25 * 0.5 / 20 * 0.05 / 400, 1e-12);
  EXPECT_NEAR(*q.q_highest, 21.25 * 5 / 0.75 * 1 / 0.5, 1e-9);
}

}  // namespace
}  // namespace rockface::rockmass

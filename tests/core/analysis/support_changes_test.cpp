// A decision's changes applied to its class (core/analysis/support_changes.h):
// each figure with its unit converted, the FROM held against what the class
// gives, a whole bolt pattern added and taken away, changes applied in
// order, what the check does not use said; a WHAT the check cannot apply,
// a figure without its unit or with another quantity's, a FROM the class
// does not give and a value outside the class file's ranges refused by
// name.
#include <gtest/gtest.h>

#include "core/analysis/support_changes.h"
#include "core/common/error.h"

namespace rockface::analysis {
namespace {

SupportClass sc2() {
  SupportClass c;
  c.name = "SC2";
  c.round_length_m = 3;
  c.bolts = BoltPattern{4.0, 1.5, 150e3, std::nullopt};
  c.shotcrete_m = 0.1;
  c.shotcrete_shear_pa = 1e6;
  c.mesh = "K131 in crown";
  return c;
}

// The refusal's text, "" when none.
std::string refusal(const std::vector<SupportChange>& changes) {
  try {
    apply_support_changes(sc2(), changes, "--change");
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "--change");
    return e.reason();
  }
  return "";
}

// Figures typed with one or two decimals in mm, cm or kN against values
// held as metres and newtons: exact after the unit's scaling but for the
// last bit of a product (1e-12 relative).
constexpr double kScaledRel = 1e-12;

TEST(SupportChanges, FiguresInTheirUnitsChangeThePattern) {
  const ChangedPattern p =
      apply_support_changes(sc2(),
                            {{"Bolt  Length", "4 m", "6 m", "W3"},
                             {"bolt spacing", "1500 mm", "1,2 m", "W3"},  // a decimal comma
                             {"bolt capacity", "150 kN", "0.25 MN", "W3"},
                             {"shotcrete thickness", "10 cm", "150 mm", "water"},
                             {"round length", "3 m", "1.5 m", "fault zone ahead"}},
                            "--change");
  ASSERT_TRUE(p.pattern.bolts);
  EXPECT_NEAR(p.pattern.bolts->length_m, 6.0, 6.0 * kScaledRel);
  EXPECT_NEAR(p.pattern.bolts->spacing_m, 1.2, 1.2 * kScaledRel);
  EXPECT_NEAR(p.pattern.bolts->capacity_n, 250e3, 250e3 * kScaledRel);
  EXPECT_NEAR(p.pattern.shotcrete_m, 0.15, 0.15 * kScaledRel);
  EXPECT_NEAR(p.pattern.round_length_m, 1.5, 1.5 * kScaledRel);
  EXPECT_EQ(p.pattern.name, "SC2");
  // The round length does not enter the wedge and block check: said.
  ASSERT_EQ(p.notes.size(), 1u);
  EXPECT_NE(p.notes[0].find("round length"), std::string::npos) << p.notes[0];
}

TEST(SupportChanges, FaceBoltsAddedAndTakenAwayAsAWholePattern) {
  const ChangedPattern added = apply_support_changes(
      sc2(), {{"face bolts", "none", "12 m at 1.5 m, 200 kN", "face wedge W5"}}, "--change");
  ASSERT_TRUE(added.pattern.face.bolts);
  EXPECT_EQ(added.pattern.face.bolts->length_m, 12.0);
  EXPECT_EQ(added.pattern.face.bolts->spacing_m, 1.5);
  EXPECT_NEAR(added.pattern.face.bolts->capacity_n, 200e3, 200e3 * kScaledRel);
  // In order: the second change starts from the first's TO.
  const ChangedPattern twice =
      apply_support_changes(sc2(),
                            {{"face bolts", "none", "12 m at 1.5 m, 200 kN", "W5"},
                             {"face bolt length", "12 m", "9 m", "the rig's longest"}},
                            "--change");
  EXPECT_EQ(twice.pattern.face.bolts->length_m, 9.0);
  // The class's bolts taken away, and given again with their capacity kept.
  const ChangedPattern none =
      apply_support_changes(sc2(), {{"bolts", "4 m at 1.5 m", "none", "spot bolting"}}, "x");
  EXPECT_FALSE(none.pattern.bolts);
  const ChangedPattern kept =
      apply_support_changes(sc2(), {{"bolts", "4 m at 1.5 m, 150 kN", "5 m at 1 m", "W2"}}, "x");
  ASSERT_TRUE(kept.pattern.bolts);
  EXPECT_EQ(kept.pattern.bolts->length_m, 5.0);
  EXPECT_EQ(kept.pattern.bolts->spacing_m, 1.0);
  EXPECT_EQ(kept.pattern.bolts->capacity_n, 150e3);
  // Text fields in any case; the check does not use them: said.
  const ChangedPattern mesh =
      apply_support_changes(sc2(), {{"mesh", "k131 IN CROWN", "K131 full", "spalling"}}, "x");
  EXPECT_EQ(mesh.pattern.mesh, "K131 full");
  EXPECT_EQ(mesh.notes.size(), 1u);
}

TEST(SupportChanges, WhatTheCheckCannotApplyIsRefusedByName) {
  // An unknown WHAT: named, with the ones it takes.
  const std::string unknown = refusal({{"bolt lenght", "4 m", "6 m", "W3"}});
  EXPECT_NE(unknown.find("change 1 (\"bolt lenght\")"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("bolt length"), std::string::npos) << unknown;
  // A unit of another quantity, and no unit.
  const std::string mismatch =
      refusal({{"bolt spacing", "1.5 m", "1.2 m", "W3"}, {"bolt length", "4 m", "150 kN", "W3"}});
  EXPECT_NE(mismatch.find("change 2 (\"bolt length\")"), std::string::npos) << mismatch;
  EXPECT_NE(mismatch.find("is a force"), std::string::npos) << mismatch;
  EXPECT_NE(mismatch.find("not a length"), std::string::npos) << mismatch;
  EXPECT_NE(refusal({{"bolt length", "4 m", "6", "W3"}}).find("has no unit"), std::string::npos);
  EXPECT_NE(refusal({{"bolt length", "4 m", "six m", "W3"}}).find("not a figure"),
            std::string::npos);
  // A FROM the class does not give (the record would say something false),
  // said in the FROM's unit.
  const std::string from = refusal({{"shotcrete", "50 mm", "100 mm", "water"}});
  EXPECT_NE(from.find("the class gives 100 mm, not 50 mm"), std::string::npos) << from;
  EXPECT_NE(refusal({{"face shotcrete", "3 cm", "5 cm", "x"}}).find("gives none"),
            std::string::npos);
  // Outside the class file's ranges.
  EXPECT_NE(refusal({{"bolt spacing", "1.5 m", "5 mm", "x"}}).find("outside [0.3, 10] m"),
            std::string::npos);
  EXPECT_NE(refusal({{"shotcrete", "0.1 m", "0.8 m", "x"}}).find("outside"), std::string::npos);
  // A bolt figure on a pattern the class does not have.
  const std::string face = refusal({{"face bolt length", "none", "12 m", "W5"}});
  EXPECT_NE(face.find("no face bolts"), std::string::npos) << face;
  EXPECT_NE(face.find("face bolts: none -> LENGTH at SPACING"), std::string::npos) << face;
  // A new pattern without its capacity, where none can be kept.
  EXPECT_NE(refusal({{"face bolts", "none", "12 m at 1.5 m", "W5"}}).find("no capacity"),
            std::string::npos);
}

TEST(SupportChanges, ShotcreteWithoutAShearStrengthIsSaidNotCounted) {
  SupportClass c = sc2();
  c.shotcrete_m = 0;
  c.shotcrete_shear_pa.reset();
  const ChangedPattern p =
      apply_support_changes(c, {{"shotcrete", "none", "5 cm", "spalling"}}, "--change");
  EXPECT_NEAR(p.pattern.shotcrete_m, 0.05, 0.05 * kScaledRel);
  ASSERT_EQ(p.notes.size(), 1u);
  EXPECT_NE(p.notes[0].find("no shear strength"), std::string::npos) << p.notes[0];
  const ChangedPattern q =
      apply_support_changes(c,
                            {{"shotcrete", "none", "5 cm", "spalling"},
                             {"shotcrete shear strength", "none", "1 MPa", "the supplier's sheet"}},
                            "--change");
  EXPECT_TRUE(q.notes.empty());
  EXPECT_EQ(q.pattern.shotcrete_shear_pa, 1e6);
}

}  // namespace
}  // namespace rockface::analysis

// A visit matched to the designer's support classes: the class whose RMR
// and Q ranges hold the visit's figures, a figure at a range's end
// (proposed on the documented side, marginal), a visit with open lines on
// the form (no class from it, the lines named), the behaviour and wedge
// size criteria.
#include <gtest/gtest.h>

#include "core/analysis/support_classes.h"

namespace rockface::analysis {
namespace {

// Three classes by RMR [60, -), [40, 60), [-, 40) and Q [4, -), [1, 4),
// [-, 1), lightest first.
SupportClasses three_classes() {
  SupportClasses s;
  s.tunnel = "T1";
  const struct {
    const char* name;
    std::optional<double> rmr_min, rmr_max, q_min, q_max;
  } rows[] = {{"SC1", 60, std::nullopt, 4, std::nullopt},
              {"SC2", 40, 60, 1, 4},
              {"SC3", std::nullopt, 40, std::nullopt, 1}};
  for (const auto& r : rows) {
    SupportClass c;
    c.name = r.name;
    c.criteria.rmr = FigureRange{r.rmr_min, r.rmr_max};
    c.criteria.q = FigureRange{r.q_min, r.q_max};
    s.classes.push_back(c);
  }
  return s;
}

VisitFigures figures(std::optional<double> rmr, std::optional<double> q) {
  VisitFigures v;
  v.rmr = rmr;
  v.q = q;
  return v;
}

TEST(SupportClasses, TheClassWhoseRangesHoldTheVisitIsProposed) {
  const ClassProposal p = match_support_classes(three_classes(), figures(50, 2));
  ASSERT_TRUE(p.proposed);
  EXPECT_EQ(*p.proposed, "SC2");
  EXPECT_FALSE(p.marginal);
  ASSERT_EQ(p.matches.size(), 3u);
  EXPECT_EQ(p.matches[0].status, CriterionStatus::not_met);
  EXPECT_EQ(p.matches[1].status, CriterionStatus::met);
  EXPECT_EQ(p.matches[2].status, CriterionStatus::not_met);
}

TEST(SupportClasses, AFigureOnARangesEndGoesToItsDocumentedSideMarginally) {
  // RMR 60 is in [60, -) (SC1), not in [40, 60): SC1 by RMR; Q 5 puts it in
  // SC1 as well. Marginal, never SC2.
  const ClassProposal on = match_support_classes(three_classes(), figures(60, 5));
  ASSERT_TRUE(on.proposed);
  EXPECT_EQ(*on.proposed, "SC1");
  EXPECT_TRUE(on.marginal);
  EXPECT_EQ(on.matches[0].checks[0].status, CriterionStatus::marginal);
  EXPECT_EQ(on.matches[1].checks[0].status, CriterionStatus::not_met);
  // Just below: SC2, marginal; well below: SC2, decided.
  const ClassProposal below = match_support_classes(three_classes(), figures(59, 2));
  EXPECT_EQ(*below.proposed, "SC2");
  EXPECT_TRUE(below.marginal);
  const ClassProposal clear = match_support_classes(three_classes(), figures(55, 2));
  EXPECT_EQ(*clear.proposed, "SC2");
  EXPECT_FALSE(clear.marginal);
  // Q within 10 % of 4 from above is marginal; 4.5 (12 %) is not.
  EXPECT_TRUE(match_support_classes(three_classes(), figures(70, 4.3)).marginal);
  EXPECT_FALSE(match_support_classes(three_classes(), figures(70, 4.5)).marginal);
}

TEST(SupportClasses, OpenLinesProposeNoClassAndAreNamed) {
  VisitFigures v = figures(50, std::nullopt);
  v.q_missing = {"Jr", "Ja"};
  const ClassProposal p = match_support_classes(three_classes(), v);
  EXPECT_FALSE(p.proposed);
  EXPECT_EQ(p.matches[1].status, CriterionStatus::unknown);
  bool named = false;
  for (const auto& n : p.notes) named = named || n.find("Jr, Ja") != std::string::npos;
  EXPECT_TRUE(named);
  // A class that asks only RMR is still proposed from RMR alone.
  SupportClasses by_rmr = three_classes();
  for (auto& c : by_rmr.classes) c.criteria.q.reset();
  const ClassProposal r = match_support_classes(by_rmr, v);
  ASSERT_TRUE(r.proposed);
  EXPECT_EQ(*r.proposed, "SC2");
}

TEST(SupportClasses, BehaviourAndWedgeSizes) {
  SupportClasses s = three_classes();
  s.classes[1].criteria.behaviour = {kBehaviourStable};
  s.classes[1].criteria.max_wedge_volume_m3 = 2.0;
  VisitFigures v = figures(50, 2);
  // Not analysed: both unknown, no class.
  EXPECT_FALSE(match_support_classes(s, v).proposed);
  v.behaviour = kBehaviourStable;
  v.wedges_known = true;
  v.largest_wedge_volume_m3 = 1.5;
  EXPECT_EQ(*match_support_classes(s, v).proposed, "SC2");
  v.largest_wedge_volume_m3 = 3.0;
  const ClassProposal big = match_support_classes(s, v);
  EXPECT_FALSE(big.proposed);
  EXPECT_EQ(big.matches[1].status, CriterionStatus::not_met);
  v.largest_wedge_volume_m3.reset();  // none found: met
  v.behaviour = kBehaviourStructural;
  EXPECT_FALSE(match_support_classes(s, v).proposed);
}

}  // namespace
}  // namespace rockface::analysis

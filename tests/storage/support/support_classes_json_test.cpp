// The designer's support classes file: read into the classes with their
// units (kN to N, MPa to Pa), written back to the same classes, and refused
// by file, field and class name for overlapping ranges, a gap between
// neighbouring classes, a class without the range the others give, a
// second class of one name and a misspelt key. The decision's text round
// trip.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "storage/support/support_classes_json.h"

namespace rockface::storage {
namespace {

const char* kThree = R"({
  "format": "rockface-support-classes/1",
  "tunnel": "Main drive",
  "classes": [
    {"name": "SC1", "round_length_m": 4.0,
     "bolts": {"length_m": 3, "spacing_m": 2.5, "capacity_kn": 150},
     "criteria": {"rmr": [60, null], "q": [4, null]}},
    {"name": "SC2", "round_length_m": 3.0,
     "bolts": {"length_m": 4, "spacing_m": 1.5, "capacity_kn": 150, "bond_kn_per_m": 200},
     "shotcrete_m": 0.1, "shotcrete_shear_mpa": 1.0, "mesh": "K131 in crown",
     "face": {"shotcrete_m": 0.03, "words": "sealing"},
     "criteria": {"rmr": [40, 60], "q": [1, 4], "behaviour": ["stable", "structural"]}},
    {"name": "SC3", "round_length_m": 1.5, "target_fos": 2.0,
     "bolts": {"length_m": 5, "spacing_m": 1.0, "capacity_kn": 250},
     "shotcrete_m": 0.2, "shotcrete_shear_mpa": 2.0, "steel_sets": "TH 29 at 1.5 m",
     "face": {"bolts": {"length_m": 12, "spacing_m": 1.5, "capacity_kn": 200}},
     "criteria": {"rmr": [null, 40], "q": [null, 1], "max_wedge_volume_m3": 50}}
  ]
})";

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("no " + from + " in the sample");
  return text.replace(at, from.size(), to);
}

// The message of the refusal (file: field: reason).
std::string refusal(const std::string& text) {
  try {
    parse_support_classes(text, "classes.json");
  } catch (const InputError& e) {
    return e.where() + ": " + e.what();
  }
  return "";
}

TEST(SupportClassesFile, ReadsTheClassesInSiUnits) {
  const analysis::SupportClasses s = parse_support_classes(kThree, "classes.json");
  EXPECT_EQ(s.tunnel, "Main drive");
  ASSERT_EQ(s.classes.size(), 3u);
  const analysis::SupportClass& sc2 = s.classes[1];
  EXPECT_EQ(sc2.name, "SC2");
  ASSERT_TRUE(sc2.bolts);
  EXPECT_EQ(sc2.bolts->capacity_n, 150e3);
  EXPECT_EQ(*sc2.bolts->bond_n_per_m, 200e3);
  EXPECT_EQ(*sc2.shotcrete_shear_pa, 1e6);
  EXPECT_EQ(sc2.mesh, "K131 in crown");
  EXPECT_EQ(sc2.face.shotcrete_m, 0.03);
  EXPECT_EQ(*sc2.criteria.rmr->min, 40);
  EXPECT_EQ(*sc2.criteria.rmr->max, 60);
  EXPECT_EQ(sc2.criteria.behaviour.size(), 2u);
  EXPECT_FALSE(s.classes[0].criteria.rmr->max);  // open end
  EXPECT_EQ(analysis::target_fos(s.classes[2]), 2.0);
  EXPECT_EQ(analysis::target_fos(s.classes[0]), analysis::kDefaultTargetFos);
  EXPECT_EQ(s.classes[2].face.bolts->length_m, 12);
  // Written and read again: the same classes.
  const analysis::SupportClasses back =
      parse_support_classes(support_classes_json(s).dump(), "again");
  EXPECT_EQ(support_classes_json(back), support_classes_json(s));
}

TEST(SupportClassesFile, OverlappingRangesAreRefusedByName) {
  const std::string m = refusal(with(kThree, "\"rmr\": [40, 60]", "\"rmr\": [40, 65]"));
  EXPECT_NE(m.find("classes.json: classes[1].criteria.rmr"), std::string::npos) << m;
  EXPECT_NE(m.find("SC2"), std::string::npos) << m;
  EXPECT_NE(m.find("overlaps class SC1"), std::string::npos) << m;
  // An open end where a neighbour follows overlaps too.
  const std::string q = refusal(with(kThree, "\"q\": [1, 4]", "\"q\": [1, null]"));
  EXPECT_NE(q.find("classes[1].criteria.q"), std::string::npos) << q;
}

TEST(SupportClassesFile, AGapBetweenClassesIsRefusedByName) {
  const std::string m = refusal(with(kThree, "\"rmr\": [null, 40]", "\"rmr\": [null, 35]"));
  EXPECT_NE(m.find("classes[2].criteria.rmr"), std::string::npos) << m;
  EXPECT_NE(m.find("no class covers RMR [35, 40)"), std::string::npos) << m;
  EXPECT_NE(m.find("SC3"), std::string::npos) << m;
}

TEST(SupportClassesFile, AMissingRangeIsRefusedByName) {
  const std::string m = refusal(
      with(kThree, "\"q\": [null, 1], \"max_wedge_volume_m3\": 50", "\"max_wedge_volume_m3\": 50"));
  EXPECT_NE(m.find("classes[2].criteria.q"), std::string::npos) << m;
  EXPECT_NE(m.find("class SC3 gives no Q range"), std::string::npos) << m;
}

TEST(SupportClassesFile, OtherMistakesAreRefusedWhereTheyAre) {
  EXPECT_NE(refusal(with(kThree, "\"name\": \"SC3\"", "\"name\": \"SC1\""))
                .find("a second class named SC1"),
            std::string::npos);
  EXPECT_NE(refusal(with(kThree, "\"spacing_m\": 2.5", "\"spacing\": 2.5"))
                .find("classes[0].bolts.spacing: unknown field"),
            std::string::npos);
  EXPECT_NE(refusal(with(kThree, "\"capacity_kn\": 250", "\"capacity_kn\": 0.5"))
                .find("classes[2].bolts.capacity_kn"),
            std::string::npos);
  EXPECT_NE(refusal(with(kThree, ", \"shotcrete_shear_mpa\": 2.0", ""))
                .find("shotcrete_shear_mpa: missing"),
            std::string::npos);
  EXPECT_NE(
      refusal(with(kThree, "\"stable\", \"structural\"", "\"squeezing\"")).find("not a behaviour"),
      std::string::npos);
  EXPECT_NE(refusal("{\"classes\": []}").find("at least one class"), std::string::npos);
}

TEST(SupportDecisionText, RoundTrips) {
  analysis::SupportDecision d;
  d.class_name = "SC3";
  d.proposed = "SC2";
  d.changes.push_back({"bolt length", "4 m", "5 m", "wedge W3 apex 3.6 m"});
  d.reason = "water inflow at the left wall";
  d.decided_by = "A. Geologist";
  d.decided_at = "2026-11-28T23:00:00.000Z";
  d.checks = "1 of 4 wedges below FoS 1.5";
  const analysis::SupportDecision back =
      parse_support_decision(support_decision_json(d).dump(), "decision");
  EXPECT_EQ(support_decision_json(back), support_decision_json(d));
  EXPECT_THROW(parse_support_decision("{\"class\": \"SC3\"}", "decision"), InputError);
}

}  // namespace
}  // namespace rockface::storage

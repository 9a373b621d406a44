// A trace's compass reading in the picks (issue 27): `compass` {dip,
// dip_direction} read into the pick, and each bad field refused by its path.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "storage/scene/picks_json.h"

namespace {

std::string picks_with(const std::string& compass) {
  return R"({"format": "rockface-picks/1", "traces": [
      {"id": "T1", "photo": "left", "pixels": [[10, 10], [20, 30]]},
      {"id": "T2", "points": [[0, 0, 0], [1, 0, 1]], "compass": )" +
         compass + "}]}";
}

std::string refused_at(const std::string& compass) {
  try {
    rockface::storage::parse_picks(picks_with(compass), "PICKS.json");
  } catch (const rockface::InputError& e) {
    return e.where();
  }
  return "accepted";
}

}  // namespace

TEST(PicksCompass, AReadingIsReadIntoItsTrace) {
  const auto picks = rockface::storage::parse_picks(
      picks_with(R"({"dip": 74.5, "dip_direction": 111})"), "PICKS.json");
  ASSERT_EQ(picks.traces.size(), 2u);
  EXPECT_FALSE(picks.traces[0].compass);
  ASSERT_TRUE(picks.traces[1].compass);
  EXPECT_EQ(picks.traces[1].compass->dip_deg, 74.5);
  EXPECT_EQ(picks.traces[1].compass->dip_direction_deg, 111);
  // The ends of the ranges are readings (360 is north, as 0).
  EXPECT_EQ(refused_at(R"({"dip": 0, "dip_direction": 360})"), "accepted");
  EXPECT_EQ(refused_at(R"({"dip": 90, "dip_direction": 0})"), "accepted");
}

TEST(PicksCompass, EachBadFieldIsNamed) {
  EXPECT_EQ(refused_at(R"({"dip": 95, "dip_direction": 111})"),
            "PICKS.json: traces[1].compass.dip");
  EXPECT_EQ(refused_at(R"({"dip": -2, "dip_direction": 111})"),
            "PICKS.json: traces[1].compass.dip");
  EXPECT_EQ(refused_at(R"({"dip": NaN, "dip_direction": 111})"),
            "PICKS.json: traces[1].compass.dip");
  EXPECT_EQ(refused_at(R"({"dip": null, "dip_direction": 111})"),
            "PICKS.json: traces[1].compass.dip");
  EXPECT_EQ(refused_at(R"({"dip": "74", "dip_direction": 111})"),
            "PICKS.json: traces[1].compass.dip");
  EXPECT_EQ(refused_at(R"({"dip_direction": 111})"), "PICKS.json: traces[1].compass.dip");
  EXPECT_EQ(refused_at(R"({"dip": 74, "dip_direction": 400})"),
            "PICKS.json: traces[1].compass.dip_direction");
  EXPECT_EQ(refused_at(R"({"dip": 74, "dip_direction": -1})"),
            "PICKS.json: traces[1].compass.dip_direction");
  EXPECT_EQ(refused_at(R"({"dip": 74})"), "PICKS.json: traces[1].compass.dip_direction");
  EXPECT_EQ(refused_at(R"({"dip": 74, "dip_direction": 111, "dipdir": 111})"),
            "PICKS.json: traces[1].compass.dipdir");
  EXPECT_EQ(refused_at("[74, 111]"), "PICKS.json: traces[1].compass");
}

// Issue 41: every object of a profile file and a picks file refuses a key it
// does not know, naming its path, as the rock-mass form and the scene's
// sections do: a misspelt key is said, never ignored.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/common/error.h"
#include "storage/scene/picks_json.h"
#include "storage/tunnel/tunnel_files.h"
#include "tests/support/refusal.h"

namespace {

using rockface::test::refusal;

std::string profile_with(const std::string& extra_top, const std::string& extra_line,
                         const std::string& extra_arc) {
  return R"({"format": "rockface-tunnel-profile/1", )" + extra_top + R"("segments": [
      {"line": {)" +
         extra_line + R"("from": [-3, -1.5], "to": [3, -1.5]}},
      {"arc": {)" +
         extra_arc + R"("centre": [0, -1.5], "radius": 3, "start_deg": 0, "end_deg": 180}}]})";
}

std::string picks_with(const std::string& extra_trace, const std::string& extra_area,
                       const std::string& extra_point) {
  return R"({"format": "rockface-picks/1",
      "traces": [{)" +
         extra_trace + R"("id": "T1", "photo": "left", "pixels": [[1, 2], [3, 4]]}],
      "areas": [{)" +
         extra_area + R"("id": "A1", "photo": "left", "polygon": [[1, 2], [3, 4], [5, 1]]}],
      "points": [{)" +
         extra_point + R"("id": "P1", "photo": "left", "pixel": [1, 2]}]})";
}

}  // namespace

TEST(UnknownFields, ProfileRefusesAMisspeltKeyInEveryObject) {
  using rockface::storage::parse_profile_json;
  EXPECT_EQ(refusal([] { parse_profile_json(profile_with("", "", ""), "P.json"); }), "accepted");
  EXPECT_EQ(refusal([] { parse_profile_json(profile_with(R"("nme": "x", )", "", ""), "P.json"); }),
            "P.json: nme: unknown field (format, name, ray_centre, segments)");
  EXPECT_EQ(
      refusal([] { parse_profile_json(profile_with("", R"("form": [0, 0], )", ""), "P.json"); }),
      "P.json: segments[0].line.form: unknown field (from, to)");
  EXPECT_EQ(refusal([] { parse_profile_json(profile_with("", "", R"("end_dg": 1, )"), "P.json"); }),
            "P.json: segments[1].arc.end_dg: unknown field (centre, radius, start_deg, end_deg)");
}

TEST(UnknownFields, PicksRefuseAMisspeltKeyInEveryObject) {
  using rockface::storage::parse_picks;
  EXPECT_EQ(refusal([] { parse_picks(picks_with("", "", ""), "K.json"); }), "accepted");
  EXPECT_NE(refusal([] {
              parse_picks(picks_with(R"("jiont": "J1", )", "", ""), "K.json");
            }).find("K.json: traces[0].jiont: unknown field (id, joint,"),
            std::string::npos);
  EXPECT_NE(refusal([] {
              parse_picks(picks_with("", R"("rockside": "upper", )", ""), "K.json");
            }).find("K.json: areas[0].rockside: unknown field (id, photo,"),
            std::string::npos);
  EXPECT_NE(refusal([] {
              parse_picks(picks_with("", "", R"("raduis": 3, )"), "K.json");
            }).find("K.json: points[0].raduis: unknown field (id, photo,"),
            std::string::npos);
  EXPECT_EQ(refusal([] {
              parse_picks(R"({"format": "rockface-picks/1", "set": 3, "traces": []})", "K.json");
            }),
            "K.json: set: unknown field (format, traces, areas, points, sets)");
}

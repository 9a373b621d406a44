// Issue 41: the scene's wedges.support.bolts values are read within the
// range a geologist sets them in (core/tunnel/support_ranges.h), and a
// refusal names the file, the field and the range: a spacing of 5 mm made
// a 100 MB answer and one of 1 mm never ended.
#include <gtest/gtest.h>

#include <string>

#include "storage/scene/scene.h"
#include "tests/support/refusal.h"

namespace {

using rockface::test::refusal;

std::string scene_with_bolts(const std::string& bolts) {
  return R"({"format": "rockface-scene/1",
    "joints": [ { "id": "A", "dip": 60, "dipdir": 10 }, { "id": "B", "dip": 60, "dipdir": 130 },
                { "id": "C", "dip": 60, "dipdir": 250 } ],
    "wedges": { "profile": { "shape": "circle", "radius": 3 }, "axis": { "trend": 0, "plunge": 0 },
                "support": { "bolts": )" +
         bolts + R"( } } })";
}

}  // namespace

TEST(SceneWedgesJson, BoltValuesOutsideAGeologistsRangeAreRefusedByName) {
  using rockface::storage::parse_scene;
  EXPECT_EQ(refusal([] {
              parse_scene(scene_with_bolts(R"({"length": 3, "spacing": 1.5, "capacity": 1e5})"),
                          "S.json");
            }),
            "accepted");
  EXPECT_EQ(refusal([] {
              parse_scene(scene_with_bolts(R"({"length": 3, "spacing": 0.005, "capacity": 1e5})"),
                          "S.json");
            }),
            "S.json: wedges.support.bolts.spacing: 0.005 m is outside [0.3, 10] m (the range of a "
            "bolt pattern's spacing)");
  EXPECT_EQ(refusal([] {
              parse_scene(scene_with_bolts(R"({"length": 3, "spacing": 1e-320, "capacity": 1e5})"),
                          "S.json");
            }).substr(0, 38),
            "S.json: wedges.support.bolts.spacing: ");
  EXPECT_EQ(refusal([] {
              parse_scene(scene_with_bolts(R"({"length": 3, "spacing": 1, "capacity": 1e308})"),
                          "S.json");
            }),
            "S.json: wedges.support.bolts.capacity: 1e+308 N is outside [1000, 1e+07] N (the range "
            "of a bolt's capacity)");
  EXPECT_EQ(
      refusal([] {
        parse_scene(
            scene_with_bolts(R"({"length": 3, "spacing": 1, "capacity": 1e5, "bond_strength": 1})"),
            "S.json");
      }),
      "S.json: wedges.support.bolts.bond_strength: 1 N/m is outside [1000, 1e+08] N/m (the "
      "range of a bolt's bond strength)");
}

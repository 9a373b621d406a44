// Issue 41: a NUL in a name ("abc\u0000def") cut every message that quoted
// it ("rockface: abc"); every text read through the Reader (names, ids,
// file names) is refused naming the field and saying that a NUL is not
// allowed.
#include <gtest/gtest.h>

#include <string>

#include "storage/scene/scene.h"
#include "tests/support/refusal.h"

TEST(JsonReader, ANulInANameIsRefusedNamingTheField) {
  using rockface::storage::parse_scene;
  using rockface::test::refusal;
  const std::string joints = R"("joints": [ { "id": "J1", "dip": 60, "dipdir": 10 } ])";
  EXPECT_EQ(refusal([&] {
              parse_scene(R"({"format": "rockface-scene/1", "name": "abc", )" + joints + "}",
                          "S.json");
            }),
            "accepted");
  EXPECT_EQ(refusal([&] {
              parse_scene(
                  R"({"format": "rockface-scene/1", "name": "abc\u0000def", )" + joints + "}",
                  "S.json");
            }),
            "S.json: name: contains a NUL character (\\u0000 at byte 3), which is not allowed in "
            "a name or a text");
  EXPECT_EQ(
      refusal([&] {
        parse_scene(
            R"({"format": "rockface-scene/1", "joints": [ { "id": "J\u00001", "dip": 60, "dipdir": 10 } ]})",
            "S.json");
      }),
      "S.json: joints[0].id: contains a NUL character (\\u0000 at byte 1), which is not "
      "allowed in a name or a text");
}

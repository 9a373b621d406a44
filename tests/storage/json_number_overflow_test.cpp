// Issue 41: a number beyond double's range (1e309) in a scene, a profile, a
// picks file, a rock-mass form, a visit file or support classes, and a picks form given as null,
// are bad input (InputError, exit 2) naming the file and where, not nlohmann's bare
// out_of_range.406 / .403 (exit 1): the file, the field path, and for an
// overflow the line and column.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/common/error.h"
#include "storage/scene/camera_json.h"
#include "storage/scene/picks_json.h"
#include "storage/scene/rockmass_form_json.h"
#include "storage/scene/scene.h"
#include "storage/scene/visit_file_json.h"
#include "storage/support/support_classes_json.h"
#include "storage/tunnel/tunnel_files.h"
#include "tests/support/refusal.h"

namespace {

using rockface::test::refusal;

const char* kOverflow = "1e309 is beyond the range of a number (about 1.8e308; line 3, column 13)";

}  // namespace

TEST(JsonNumberOverflow, SceneNamesFileAndPosition) {
  const std::string m = refusal([] {
    rockface::storage::parse_scene(
        "{ \"format\": \"rockface-scene/1\",\n  \"joints\": [\n    {\"dip\": 1e309, \"dipdir\": "
        "90} ] }",
        "S.json");
  });
  EXPECT_EQ(m, std::string("S.json: joints[0].dip: ") + kOverflow) << m;
}

TEST(JsonNumberOverflow, ProfileNamesFileAndPosition) {
  const std::string m = refusal([] {
    rockface::storage::parse_profile_json(
        "{ \"format\": \"rockface-tunnel-profile/1\",\n  \"segments\": [\n    {\"xyz\": 1e309} ] }",
        "P.json");
  });
  EXPECT_EQ(m, std::string("P.json: segments[0].xyz: ") + kOverflow) << m;
}

TEST(JsonNumberOverflow, PicksNamesFileAndPosition) {
  const std::string m = refusal([] {
    rockface::storage::parse_picks(
        "{ \"format\": \"rockface-picks/1\",\n  \"traces\": [\n    {\"abc\": 1e309, \"b\": 2} ] }",
        "K.json");
  });
  EXPECT_EQ(m, std::string("K.json: traces[0].abc: ") + kOverflow) << m;
}

TEST(JsonNumberOverflow, RockMassFormNamesFileAndPosition) {
  const std::string m = refusal([] {
    rockface::storage::parse_rockmass_form("{ \"format\": \"x\",\n  \"ucs\":\n    -1e309 }",
                                           "F.json");
  });
  EXPECT_EQ(m,
            "F.json: ucs: -1e309 is beyond the range of a number (about 1.8e308; line 3, column 5)")
      << m;
}

// The visit file of a capture folder said only "not JSON (rockface-visit/1
// expected)": neither the field nor where.
TEST(JsonNumberOverflow, VisitFileNamesFileAndPosition) {
  const std::string m = refusal([] {
    rockface::storage::parse_visit_file(
        "{ \"format\": \"rockface-visit/1\",\n  \"compass\": {\"azimuth_deg\": 1,\n    "
        "\"declination_deg\": 1e309} }",
        "V.json");
  });
  EXPECT_EQ(
      m,
      "V.json: compass.declination_deg: 1e309 is beyond the range of a number (about 1.8e308; "
      "line 3, column 24)")
      << m;
  EXPECT_EQ(refusal([] {
              rockface::storage::parse_visit_file(
                  "{\"format\": \"rockface-visit/1\", \"range_pole_m\": NaN}", "V.json");
            }),
            "V.json: range_pole_m: must be finite, not NaN");
}

TEST(JsonNumberOverflow, SupportClassesNameFileAndPosition) {
  const std::string m = refusal([] {
    rockface::storage::parse_support_classes(
        "{ \"format\": \"rockface-support-classes/1\",\n  \"classes\": [\n    "
        "{\"round_length_m\": 1e309} ] }",
        "K.json");
  });
  EXPECT_EQ(m, std::string("K.json: classes[0].round_length_m: 1e309 is beyond the range of a "
                           "number (about 1.8e308; line 3, column 24)"))
      << m;
}

TEST(JsonNumberOverflow, CameraNamesFileAndPosition) {
  const std::string m = refusal([] {
    rockface::storage::parse_camera_json("{\"format\": \"rockface-camera/1\", \"fx\": 2e400}",
                                         "C.json");
  });
  EXPECT_EQ(m,
            "C.json: fx: 2e400 is beyond the range of a number (about 1.8e308; line 1, column 39)")
      << m;
}

TEST(JsonNumberOverflow, AnOverflowInsideAStringIsNoNumber) {
  // "1e309" as text is a name, not a number: the refusal points at the number.
  const std::string m = refusal([] {
    rockface::storage::parse_scene(
        "{ \"format\": \"rockface-scene/1\", \"name\": \"1e309 \\\" 9e999\",\n  \"j\": [\n    "
        "{\"dip\": 1e309} ] }",
        "S.json");
  });
  EXPECT_EQ(m, std::string("S.json: j[0].dip: ") + kOverflow) << m;
}

TEST(PicksNullForm, PixelsNullIsRefusedByItsField) {
  for (const char* form : {"pixels", "points", "ends"}) {
    const std::string m = refusal([&] {
      rockface::storage::parse_picks(std::string("{\"format\": \"rockface-picks/1\", \"traces\": "
                                                 "[{\"id\": \"T1\", \"photo\": \"left\", \"") +
                                         form + "\": null}]}",
                                     "K.json");
    });
    EXPECT_EQ(m, std::string("K.json: traces[0].") + form + ": must be an array, not null");
  }
}

// A chainage beyond the alignment's ends (issue 40): a section placed 100 m
// before the first station or 10 km past the last would be extrapolated
// along the end's tangent and analysed as if it were in the drive. It is
// refused, naming the field and the alignment's range; a chainage on the
// alignment (its ends included) is analysed.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "firmware-app/wedges/wedge_input.h"
#include "storage/scene/scene.h"

namespace rockface {
namespace {

// A straight level drive due north, chainage 0 to 3000, and a wedge
// section at `chainage`, given as the wedges' own chainage or (placed)
// as the tunnel's placement.
std::string tunnel_scene(double chainage, bool placed) {
  char c[64];
  std::snprintf(c, sizeof c, "%.17g", chainage);
  std::string s = R"({ "format": "rockface-scene/1",
  "datum": [512340.0, 5211800.0, 410.0],
  "joints": [
    { "id": "J1", "dip": 65, "dipdir": 20,  "friction": 32 },
    { "id": "J2", "dip": 60, "dipdir": 145, "friction": 30 },
    { "id": "J3", "dip": 55, "dipdir": 260, "friction": 30 } ],
  "tunnel": {
    "alignment": { "stations": [
      { "chainage": 0, "easting": 512340.0, "northing": 5211800.0, "elevation": 410.0 },
      { "chainage": 3000, "easting": 512340.0, "northing": 5214800.0, "elevation": 410.0 } ] },
    "profile": { "segments": [
      { "arc": { "centre": [0, 0], "radius": 3.0, "start_deg": -90, "end_deg": 90 } },
      { "arc": { "centre": [0, 0], "radius": 3.0, "start_deg": 90, "end_deg": 270 } } ] })";
  if (placed)
    s += std::string(R"(,
    "placement": { "chainage": )") +
         c + " }";
  s += R"( },
  "wedges": { "sets": ["J1", "J2", "J3"], "profile": "tunnel")";
  if (!placed) s += std::string(R"(, "chainage": )") + c;
  s += " } }\n";
  return s;
}

std::string refusal(const std::string& scene_text) {
  const storage::Scene scene = storage::parse_scene(scene_text, "S.json");
  try {
    app::wedge_run_from_scene(scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(WedgesAlignmentEnds, ChainageBeyondEitherEndIsRefusedByName) {
  for (bool placed : {false, true})
    for (double c : {-100.0, 13000.0, 3000.5}) {
      const std::string why = refusal(tunnel_scene(c, placed));
      const std::string field = placed ? "tunnel.placement.chainage" : "wedges.chainage";
      EXPECT_NE(why.find(field), std::string::npos) << c << ": " << why;
      EXPECT_NE(why.find("beyond the alignment"), std::string::npos) << c << ": " << why;
    }
}

TEST(WedgesAlignmentEnds, ChainageOnTheAlignmentIsAnalysed) {
  // The ends themselves, and within the table's centimetre rounding of them
  // (kChainageMismatchM): extrapolating 5 mm along the end's tangent moves
  // the section by 5 mm, far below what a wedge's size depends on.
  for (double c : {0.0, 1500.0, 3000.0, -0.005, 3000.005}) {
    const storage::Scene scene = storage::parse_scene(tunnel_scene(c, false), "S.json");
    const app::WedgeRun run = app::wedge_run_from_scene(scene);
    ASSERT_TRUE(run.chainage) << c;
    EXPECT_EQ(*run.chainage, c);
    EXPECT_FALSE(app::run_wedges(run).wedges.empty()) << c;
  }
}

}  // namespace
}  // namespace rockface

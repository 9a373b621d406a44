// A tunnel scene's wedges across a station of its alignment (issue 40: "the
// roof wedge is lost at chainage 1999.999999 and present at 2000"): a
// level drive due north with a station at 2000 where the alignment runs
// straight on, turns by 5 degrees or breaks its grade, with and without a
// datum, its section swept from 1999.99 to 2000.01 on a 0.5 mm grid and at
// 1999.999999, 2000 and 2000.000001. Every section has the same wedges,
// each the same size on either side of the station (the alignment's
// direction, not its position, sets a wedge's shape).
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "firmware-app/wedges/wedge_input.h"
#include "storage/scene/scene.h"

namespace rockface {
namespace {

constexpr double kE = 512340.0, kN = 5211800.0, kZ = 410.0;

std::string station(double chainage, double e, double n, double z) {
  char b[200];
  std::snprintf(b, sizeof b,
                "{ \"chainage\": %.17g, \"easting\": %.17g, \"northing\": %.17g, "
                "\"elevation\": %.17g }",
                chainage, e, n, z);
  return b;
}

// The sample's three sets around a circle of radius 3 m at `chainage`.
std::string tunnel_scene(const std::string& stations, double chainage, bool datum) {
  char c[64];
  std::snprintf(c, sizeof c, "%.17g", chainage);
  return std::string("{ \"format\": \"rockface-scene/1\",\n") +
         (datum ? "  \"datum\": [512340.0, 5211800.0, 410.0],\n" : "") + R"(
  "rock": { "density": 2650 },
  "joints": [
    { "id": "J1", "dip": 65, "dipdir": 20,  "friction": 32, "cohesion": 0 },
    { "id": "J2", "dip": 60, "dipdir": 145, "friction": 30, "cohesion": 0 },
    { "id": "J3", "dip": 55, "dipdir": 260, "friction": 30, "cohesion": 0 } ],
  "tunnel": {
    "alignment": { "stations": [ )" +
         stations + R"( ] },
    "profile": { "segments": [
      { "arc": { "centre": [0, 0], "radius": 3.0, "start_deg": -90, "end_deg": 90 } },
      { "arc": { "centre": [0, 0], "radius": 3.0, "start_deg": 90, "end_deg": 270 } } ] } },
  "wedges": { "sets": ["J1", "J2", "J3"], "profile": "tunnel", "chainage": )" +
         c + " } }\n";
}

std::map<std::string, double> volumes_at(const std::string& stations, double chainage, bool datum) {
  const storage::Scene scene =
      storage::parse_scene(tunnel_scene(stations, chainage, datum), "S.json");
  const tunnel::WedgeAnalysis a = app::run_wedges(app::wedge_run_from_scene(scene));
  for (const auto& n : a.none)
    EXPECT_EQ(n.reason.find("could not be built"), std::string::npos)
        << "chainage " << chainage << " " << n.code << ": " << n.reason;
  std::map<std::string, double> v;
  for (const auto& w : a.wedges) v[w.code] = w.mass.volume;
  return v;
}

TEST(WedgesChainageBoundary, AStationOfTheAlignmentLosesNoWedge) {
  const double turn = 5 * std::acos(-1.0) / 180;
  const std::string before = station(0, kE, kN, kZ) + ", " + station(2000, kE, kN + 2000, kZ);
  const std::map<std::string, std::string> alignments{
      {"straight on", before + ", " + station(3000, kE, kN + 3000, kZ)},
      {"a 5 degree corner",
       before + ", " +
           station(3000, kE + 1000 * std::sin(turn), kN + 2000 + 1000 * std::cos(turn), kZ)},
      {"a grade break", before + ", " + station(3000, kE, kN + 3000, kZ + 30)}};
  std::vector<double> chainages{1999.999999, 2000.0, 2000.000001};
  for (int k = -20; k <= 20; ++k) chainages.push_back(2000 + k * 5e-4);
  for (const auto& [name, stations] : alignments)
    for (bool datum : {true, false}) {
      SCOPED_TRACE(name + (datum ? ", datum at the start" : ", no datum"));
      const auto ahead = volumes_at(stations, 1999.99, datum);
      const auto behind = volumes_at(stations, 2000.01, datum);
      ASSERT_EQ(ahead.size(), 7u);
      // On one element the section only moves: the wedges are built about
      // it (their planes' offsets of metres), so their volumes agree to
      // rounding, 1e-9 relative.
      auto same = [](const std::map<std::string, double>& a,
                     const std::map<std::string, double>& b) {
        if (a.size() != b.size()) return false;
        for (const auto& [code, volume] : b)
          if (!a.count(code) || !(std::abs(a.at(code) - volume) <= 1e-9 * volume)) return false;
        return true;
      };
      for (double c : chainages) {
        const auto v = volumes_at(stations, c, datum);
        // Before the station the first element's direction holds, after
        // it the second's; at the station one of the two.
        const bool ok = c < 2000   ? same(v, ahead)
                        : c > 2000 ? same(v, behind)
                                   : same(v, ahead) || same(v, behind);
        EXPECT_TRUE(ok) << "chainage " << c << ": " << v.size() << " wedges";
      }
    }
}

}  // namespace
}  // namespace rockface

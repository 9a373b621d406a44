// A tunnel scene's wedges far along its alignment (issue 40: "the roof
// wedge (1.12 m3) is lost at chainage 1999.999999 and present at 2000"):
// a straight drive at a bearing of 35 degrees rising at 2 %, with the
// datum at its start, and the tunnel-wedges sample's sets, horseshoe,
// water table (level with the axis all along) and trace-length limit. On a
// straight element every section sees the same rock: the wedges at
// chainages 2000 - 1e-6, 2000, 1e4 and 1e5 are those at the datum
// (chainage 0), code by code, to rounding.
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "firmware-app/wedges/wedge_input.h"
#include "storage/scene/scene.h"
#include "tests/support/test_paths.h"

namespace rockface {
namespace {

constexpr double kE = 2600000.0, kN = 1200000.0, kZ = 450.0;
constexpr double kBearing = 35 * 3.14159265358979323846 / 180, kGrade = 0.02;

std::string number(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

std::string station(double chainage) {
  return "{ \"chainage\": " + number(chainage) +
         ", \"easting\": " + number(kE + chainage * std::sin(kBearing)) +
         ", \"northing\": " + number(kN + chainage * std::cos(kBearing)) +
         ", \"elevation\": " + number(kZ + kGrade * chainage) + " }";
}

// The tunnel-drive sample's design profile: the tunnel-wedges sample's
// horseshoe (crown radius 3 m, walls 5 m, springline 1 m above the axis,
// invert 1.5 m below) as a profile file.
const std::string kHorseshoe =
    std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-drive.profile.json";

std::string tunnel_scene(double chainage) {
  // The phreatic surface inclined with the drive, through the axis at
  // every chainage: every section has the same water on its wedges.
  const double dip_deg = std::atan(kGrade) * 180 / 3.14159265358979323846;
  return R"({ "format": "rockface-scene/1",
  "datum": [2600000.0, 1200000.0, 450.0],
  "rock": { "density": 2650 },
  "joints": [
    { "id": "J1", "dip": 65, "dipdir": 20,  "friction": 32, "cohesion": 0 },
    { "id": "J2", "dip": 60, "dipdir": 145, "friction": 30, "cohesion": 0 },
    { "id": "J3", "dip": 55, "dipdir": 260, "friction": 30, "cohesion": 0 } ],
  "analysis": { "preset": "standard", "orientation_uncertainty_deg": 2.0 },
  "effects": { "water": { "unit_weight": 9810, "phreatic_surface": {
    "point": [2600000.0, 1200000.0, 452.0], "dip": )" +
         number(dip_deg) + R"(, "dipdir": 215 } } },
  "tunnel": {
    "alignment": { "stations": [ )" +
         station(0) + ", " + station(150000) + R"( ] },
    "profile": ")" +
         kHorseshoe + R"(" },
  "wedges": { "sets": ["J1", "J2", "J3"], "profile": "tunnel", "trace_length": 6.0,
              "chainage": )" +
         number(chainage) + " } }\n";
}

tunnel::WedgeAnalysis wedges_at(double chainage) {
  const storage::Scene scene = storage::parse_scene(tunnel_scene(chainage), "S.json");
  return app::run_wedges(app::wedge_run_from_scene(scene));
}

TEST(WedgesFarAlongAlignment, TheWedgesAtAnyChainageAreThoseAtTheDatum) {
  const tunnel::WedgeAnalysis at_datum = wedges_at(0);
  ASSERT_GE(at_datum.wedges.size(), 4u);
  std::map<std::string, const tunnel::Wedge*> reference;
  for (const auto& w : at_datum.wedges) reference[w.code] = &w;
  for (double chainage : {2000 - 1e-6, 2000.0, 1e4, 1e5}) {
    SCOPED_TRACE("chainage " + number(chainage));
    const tunnel::WedgeAnalysis a = wedges_at(chainage);
    for (const auto& n : a.none)
      EXPECT_EQ(n.reason.find("could not be built"), std::string::npos)
          << n.code << ": " << n.reason;
    ASSERT_EQ(a.wedges.size(), at_datum.wedges.size());
    for (const auto& w : a.wedges) {
      ASSERT_TRUE(reference.count(w.code)) << w.code;
      const tunnel::Wedge& r = *reference.at(w.code);
      EXPECT_EQ(w.place, r.place) << w.code;
      // The wedges are built about the section (planes' offsets of
      // metres); the section's frame comes from the alignment's survey
      // coordinates of ~1e6 m, rounded to ~1e-10 m, which turns the frame
      // by ~1e-15 rad and moves a wedge's apex by ~1e-14 m: agreement to
      // 1e-9 relative is the issue's own bar, far above that.
      EXPECT_NEAR(w.mass.volume, r.mass.volume, 1e-9 * r.mass.volume) << w.code;
      EXPECT_NEAR(w.removable.margin, r.removable.margin, 1e-9) << w.code;
      ASSERT_EQ(w.fos.has_value(), r.fos.has_value()) << w.code;
      if (w.fos) {
        EXPECT_NEAR(*w.fos, *r.fos, 1e-9 * std::abs(*r.fos)) << w.code;
      }
      // Absolute apexes move with the section along the straight drive.
      const Eigen::Vector3d moved = w.apex - r.apex;
      const Eigen::Vector3d along(std::sin(kBearing), std::cos(kBearing), kGrade);
      EXPECT_NEAR(moved.dot(along.normalized()), chainage * along.norm(), 1e-6) << w.code;
      EXPECT_NEAR((moved - moved.dot(along.normalized()) * along.normalized()).norm(), 0, 1e-6)
          << w.code;
    }
  }
}

}  // namespace
}  // namespace rockface

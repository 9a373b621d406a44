// Far from the datum (issue 40): the tunnel-wedges sample's section moved
// 2 km, 10 km and 100 km from the scene's datum, or to E/N 5.2e6 with no
// datum, and a tunnel scene's section at chainage 2000 and 1999.999999,
// give the same wedges (codes, volumes, apexes moved with the section) as
// the same section at the datum.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "firmware-app/wedges/wedge_input.h"
#include "storage/scene/scene.h"

namespace rockface {
namespace {

std::string xyz(double x, double y, double z) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "[%.17g, %.17g, %.17g]", x, y, z);
  return buf;
}

// The tunnel-wedges sample (tools/samples): three sets around a horseshoe
// with water, the section's origin at `origin`, the datum at `datum` (none
// when not given).
std::string sample_scene(const Eigen::Vector3d& origin, const Eigen::Vector3d* datum) {
  std::string s = "{ \"format\": \"rockface-scene/1\",\n";
  if (datum) s += "  \"datum\": " + xyz(datum->x(), datum->y(), datum->z()) + ",\n";
  s += R"(  "rock": { "density": 2650 },
  "joints": [
    { "id": "J1", "dip": 65, "dipdir": 20,  "friction": 32, "cohesion": 0 },
    { "id": "J2", "dip": 60, "dipdir": 145, "friction": 30, "cohesion": 0 },
    { "id": "J3", "dip": 55, "dipdir": 260, "friction": 30, "cohesion": 0 } ],
  "analysis": { "preset": "standard", "orientation_uncertainty_deg": 2.0 },
  "effects": { "water": { "unit_weight": 9810, "phreatic_surface": { "point": )" +
       xyz(origin.x(), origin.y(), origin.z() + 12) + R"(, "dip": 0, "dipdir": 0 } } },
  "wedges": {
    "sets": ["J1", "J2", "J3"],
    "profile": { "shape": "horseshoe", "crown_radius": 3.0, "springline_v": 1.0,
                 "wall_radius": 5.0, "invert_v": -1.5 },
    "axis": { "trend": 35, "plunge": 2 },
    "origin": )" +
       xyz(origin.x(), origin.y(), origin.z()) + R"(,
    "trace_length": 6.0 } }
)";
  return s;
}

tunnel::WedgeAnalysis wedges_of(const std::string& scene_text) {
  const storage::Scene scene = storage::parse_scene(scene_text, "S.json");
  return app::run_wedges(app::wedge_run_from_scene(scene));
}

// The same wedges: every code of the reference, none lost or added, each
// volume to 1e-9 relative (the blocks are built about the section, so only
// the rounding of the section's absolute position, ~1e-16 x 5e6 m = 1e-9 m
// in the water's head, differs) and each apex moved with the section to
// 1e-6 m (the apex is absolute: 5.2e6 m carries ~1e-9 m of rounding, and
// the direction of the frame ~1e-15 rad over metres).
void expect_same_wedges(const tunnel::WedgeAnalysis& at_datum, const tunnel::WedgeAnalysis& moved,
                        const Eigen::Vector3d& shift, const std::string& what) {
  ASSERT_FALSE(at_datum.wedges.empty());
  ASSERT_EQ(moved.wedges.size(), at_datum.wedges.size()) << what;
  for (std::size_t i = 0; i < at_datum.wedges.size(); ++i) {
    const tunnel::Wedge& a = at_datum.wedges[i];
    const tunnel::Wedge& b = moved.wedges[i];
    EXPECT_EQ(b.code, a.code) << what;
    EXPECT_EQ(b.place, a.place) << what << " " << a.code;
    EXPECT_NEAR(b.mass.volume, a.mass.volume, 1e-9 * a.mass.volume) << what << " " << a.code;
    EXPECT_NEAR((b.apex - (a.apex + shift)).norm(), 0, 1e-6) << what << " " << a.code;
    EXPECT_NEAR(b.removable.margin, a.removable.margin, 1e-9) << what << " " << a.code;
  }
  for (const auto& n : moved.none)
    EXPECT_EQ(n.reason.find("could not be built"), std::string::npos) << what << " " << n.code;
}

TEST(WedgesFarFromDatum, SectionMovedAwayFromTheDatumKeepsEveryWedge) {
  const Eigen::Vector3d datum(2600000, 1200000, 450);
  const tunnel::WedgeAnalysis ref = wedges_of(sample_scene(datum, &datum));
  ASSERT_EQ(ref.wedges.size(), 7u) << "the sample's seven wedges at the datum";
  for (double km : {2.0, 5.0, 10.0, 100.0}) {
    // Along a direction that is neither the axis nor across it.
    const Eigen::Vector3d shift(600 * km, 800 * km, 0);
    expect_same_wedges(ref, wedges_of(sample_scene(datum + shift, &datum)), shift,
                       std::to_string(km) + " km from the datum");
  }
}

TEST(WedgesFarFromDatum, SurveyCoordinatesWithoutADatumKeepEveryWedge) {
  const Eigen::Vector3d datum(2600000, 1200000, 450);
  const tunnel::WedgeAnalysis ref = wedges_of(sample_scene(datum, &datum));
  const Eigen::Vector3d far(5.2e6, 5.2e6, 450);
  expect_same_wedges(ref, wedges_of(sample_scene(far, nullptr)), far - datum,
                     "E/N 5.2e6, no datum");
}

// A straight level drive due north from the datum, 3 km long, and its
// section at `chainage` (the sample's sets, a circle of radius 3 m).
std::string tunnel_scene(double chainage) {
  char c[64];
  std::snprintf(c, sizeof c, "%.17g", chainage);
  return std::string(R"({ "format": "rockface-scene/1",
  "datum": [512340.0, 5211800.0, 410.0],
  "rock": { "density": 2650 },
  "joints": [
    { "id": "J1", "dip": 65, "dipdir": 20,  "friction": 32, "cohesion": 0 },
    { "id": "J2", "dip": 60, "dipdir": 145, "friction": 30, "cohesion": 0 },
    { "id": "J3", "dip": 55, "dipdir": 260, "friction": 30, "cohesion": 0 } ],
  "tunnel": {
    "alignment": { "stations": [
      { "chainage": 0, "easting": 512340.0, "northing": 5211800.0, "elevation": 410.0 },
      { "chainage": 3000, "easting": 512340.0, "northing": 5214800.0, "elevation": 410.0 } ] },
    "profile": { "segments": [
      { "arc": { "centre": [0, 0], "radius": 3.0, "start_deg": -90, "end_deg": 90 } },
      { "arc": { "centre": [0, 0], "radius": 3.0, "start_deg": 90, "end_deg": 270 } } ] } },
  "wedges": { "sets": ["J1", "J2", "J3"], "profile": "tunnel", "chainage": )") +
         c + " } }\n";
}

TEST(WedgesFarFromDatum, TunnelSectionAtChainageTwoKilometresMatchesTheStart) {
  const tunnel::WedgeAnalysis ref = wedges_of(tunnel_scene(0));
  for (double c : {2000.0, 1999.999999}) {
    const Eigen::Vector3d shift(0, c, 0);
    expect_same_wedges(ref, wedges_of(tunnel_scene(c)), shift, "chainage " + std::to_string(c));
  }
}

}  // namespace
}  // namespace rockface

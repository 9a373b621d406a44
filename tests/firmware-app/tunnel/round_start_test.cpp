// Where a round starts (issue 46): at the previous face of its own heading,
// read in that heading's drive direction — two headings driven towards each
// other each start their rounds at their own last face, never at the
// nearest face of the other (firmware-app/tunnel/round_start.h), through
// the one path the command line (`rockface profile`), the field report, the
// tablet and the office share (visit_profile.h).
#include "firmware-app/tunnel/round_start.h"

#include <unistd.h>

#include <filesystem>
#include <map>

#include <gtest/gtest.h>

#include "firmware-app/tunnel/visit_profile.h"
#include "tests/support/two_headings.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;

// The rendered surfaces are planar facets at exact chainages (their walls
// start at walls_from, their faces are flat at `face`); the rays and the
// placing of vertices along a straight axis err by rounding only. 1e-6 m
// is far below the 0.5 m between the rendered sections, and a face taken
// from the wrong heading is metres off.
constexpr double kRoundingM = 1e-6;

TEST(RoundStart, EachRoundStartsAtThePreviousFaceOfItsOwnHeading) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-round-start-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::map<std::string, test::HeadingVisit> by_label;
  for (const auto& v : test::make_two_headings_project(dir / "p.rockface", "drive"))
    by_label[v.label] = v;
  {
    storage::ProjectStore store = storage::ProjectStore::open(dir / "p.rockface");
    struct Want {
      const char* label;
      double from;          // where the round starts
      const char* from_of;  // the visit whose face it is; "" for the 3D image's start
      double sense;         // the heading's drive direction
    };
    // The round ends 0.4 m short of the face, on the side the heading
    // comes from (visit_profile.cpp's kFaceClearM).
    for (const Want& w : {Want{"N1", 100, "", 1}, Want{"S1", 128, "", -1}, Want{"N2", 104, "N1", 1},
                          Want{"S2", 124, "S1", -1}, Want{"U1", 100, "", 1}}) {
      const test::HeadingVisit& v = by_label.at(w.label);
      const VisitProfile p = visit_profile(store, v.id, Preset::fast);
      EXPECT_EQ(p.sense, w.sense) << w.label;
      EXPECT_NEAR(p.round_to, v.face - w.sense * 0.4, kRoundingM) << w.label;
      EXPECT_NEAR(p.round_from, w.from, kRoundingM) << w.label;
      EXPECT_EQ(p.round_from_source,
                *w.from_of ? "face of visit " + std::to_string(by_label.at(w.from_of).id)
                           : std::string("start of the 3D image"))
          << w.label;
      // Walls in view from the round's start to its end: measured.
      EXPECT_NE(p.deviation.status, tunnel::DeviationStatus::no_walls_in_view) << w.label;
      EXPECT_NE(p.deviation.status, tunnel::DeviationStatus::outside_alignment) << w.label;
    }
  }
  fs::remove_all(dir);
}

PlacedFace face(storage::RecordId id, double chainage, const std::string& heading,
                const std::string& at) {
  return {id, chainage, heading, at};
}

// A named heading's direction is the trend of its faces' chainage in time;
// one face revisited out of turn does not turn it round; a heading with
// one visit, and the visits without a heading, go the tunnel's way.
TEST(RoundStart, AHeadingsDirectionIsReadFromItsVisitsInTimeOrder) {
  DriveFaces d;
  d.tunnel_drive = tunnel::Drive::ascending;
  // Stored out of date order: the dates decide, not the ids.
  d.faces = {face(1, 50, "South", "2026-03-05"), face(2, 56, "South", "2026-03-01"),
             face(3, 53, "South", "2026-03-03"), face(4, 55.5, "South", "2026-03-06"),
             face(5, 10, "North", "2026-03-01"), face(6, 70, "Bench", "2026-03-01"),
             face(7, 20, "", "2026-03-02"),      face(8, 15, "", "2026-03-03")};
  for (const auto& f : d.faces)
    if (!f.heading.empty()) d.headings[f.visit_id] = f.heading;
  // 56, 53, 50 in time, then 55.5 (a face revisited): still descending.
  EXPECT_EQ(d.sense_of("South"), -1.0);
  EXPECT_EQ(d.sense_of("North"), 1.0);
  EXPECT_EQ(d.sense_of(""), 1.0) << "visits without a heading go the tunnel's way, as before";
  d.tunnel_drive = tunnel::Drive::descending;
  EXPECT_EQ(d.sense_of("Bench"), -1.0);
  EXPECT_EQ(d.sense_of("South"), -1.0);
  d.tunnel_drive = tunnel::Drive::ascending;
  // South's round ending at 52.85 (descending) starts at 53, its own face,
  // not at 55.5 nor at North's or the unnamed visits' faces.
  const auto previous = d.previous_face(1, 50.15, -1.0);
  ASSERT_TRUE(previous);
  EXPECT_EQ(previous->visit_id, 3);
  // An unnamed visit's round: among the unnamed visits only.
  const auto unnamed = d.previous_face(7, 19.85, 1.0);
  ASSERT_TRUE(unnamed);
  EXPECT_EQ(unnamed->visit_id, 8);
  EXPECT_FALSE(d.previous_face(5, 9.85, 1.0)) << "North's first visit has no earlier face";
}

}  // namespace
}  // namespace rockface::app

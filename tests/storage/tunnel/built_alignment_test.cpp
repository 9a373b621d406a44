// Issue 41: a replay built the tunnel's alignment six times from one table
// (the table's check when read, the scene's check, the typed pole, the
// rendered round, the project's check, the placement), ~1 s of CPU each at
// 10^6 rows. The alignment is kept for the process (built_alignment.h):
// counted here, with what must still be built again (another datum, a
// changed table) and what must never be served stale.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/common/error.h"
#include "storage/scene/scene.h"
#include "storage/tunnel/built_alignment.h"
#include "storage/tunnel/tunnel_files.h"
#include "storage/tunnel/tunnel_records.h"
#include "tests/support/test_paths.h"

namespace rockface::storage {
namespace {

TunnelRecord straight_record() {
  TunnelRecord rec;
  rec.name = "drive";
  rec.stations = {{0, {2600000, 1200000, 450}}, {100, {2600000, 1200100, 450}}};
  rec.radii = {0};
  rec.polyline = false;
  return rec;
}

TEST(BuiltAlignment, ARecordAndItsCopiesBuildTheAlignmentOncePerDatum) {
  const TunnelRecord rec = straight_record();
  const Eigen::Vector3d datum(2600000, 1200000, 450);
  const std::size_t before = alignment_builds();
  const tunnel::Alignment first = rec.alignment(datum);
  const TunnelRecord copy = rec;  // as the replay copies the scene's record
  const tunnel::Alignment again = copy.alignment(datum);
  EXPECT_EQ(alignment_builds() - before, 1u);
  // The same alignment: the axis 50 m along lies 50 m north of the datum
  // (exactly: the stations are whole metres from it).
  EXPECT_EQ(again.point_at(50), first.point_at(50));
  EXPECT_EQ(again.point_at(50), Eigen::Vector3d(0, 50, 0));
  // The drive is only the copy's: a descending record looks south, and the
  // kept alignment still looks north for the ascending one.
  TunnelRecord descending = rec;
  descending.drive = tunnel::Drive::descending;
  EXPECT_EQ(descending.alignment(datum).tangent_at(50), Eigen::Vector3d(0, -1, 0));
  EXPECT_EQ(rec.alignment(datum).tangent_at(50), Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(alignment_builds() - before, 1u);
  // Another datum is another build.
  EXPECT_EQ(rec.alignment(Eigen::Vector3d::Zero()).point_at(50),
            Eigen::Vector3d(2600000, 1200050, 450));
  EXPECT_EQ(alignment_builds() - before, 2u);
}

TEST(BuiltAlignment, AStationChangedAfterTheBuildIsBuiltAgainNotServedStale) {
  TunnelRecord rec = straight_record();
  const Eigen::Vector3d datum(2600000, 1200000, 450);
  (void)rec.alignment(datum);
  TunnelRecord moved = rec;
  moved.stations[1].survey = {2600100, 1200000, 450};  // now due east
  EXPECT_EQ(moved.alignment(datum).point_at(50), Eigen::Vector3d(50, 0, 0));
  EXPECT_EQ(rec.alignment(datum).point_at(50), Eigen::Vector3d(0, 50, 0));
}

TEST(BuiltAlignment, ARadiusChangedAfterTheBuildIsBuiltAgain) {
  // A quarter circle of 100 m from the datum to 100 m east and north: the
  // same two stations make a right turn (centre 100 m east) with radius
  // +100 and a left turn (centre 100 m north) with -100, both 157.08 m.
  const double R = 100, quarter = R * std::numbers::pi / 2;
  TunnelRecord right;
  right.stations = {{0, {2600000, 1200000, 450}}, {quarter, {2600100, 1200100, 450}}};
  right.radii = {R};
  right.polyline = false;
  TunnelRecord left = right;
  left.radii = {-R};
  const Eigen::Vector3d datum(2600000, 1200000, 450);
  const double c = R * std::sqrt(0.5);  // the arcs' midpoints: R cos 45 from their centres
  // Within 1e-9 m: the arcs are evaluated from datum-relative coordinates
  // of 100 m, rounded to ~1e-14 m.
  EXPECT_NEAR((right.alignment(datum).point_at(quarter / 2) - Eigen::Vector3d(R - c, c, 0)).norm(),
              0, 1e-9);
  EXPECT_NEAR((left.alignment(datum).point_at(quarter / 2) - Eigen::Vector3d(c, R - c, 0)).norm(),
              0, 1e-9);
  EXPECT_NEAR((right.alignment(datum).point_at(quarter / 2) - Eigen::Vector3d(R - c, c, 0)).norm(),
              0, 1e-9);
}

TEST(BuiltAlignment, ABadTableIsRefusedEveryTimeNotKept) {
  TunnelRecord rec = straight_record();
  rec.stations[1].chainage = 0;  // a duplicate chainage
  const std::size_t before = alignment_builds();
  EXPECT_THROW((void)rec.alignment(Eigen::Vector3d::Zero()), InputError);
  EXPECT_THROW((void)rec.alignment(Eigen::Vector3d::Zero()), InputError);
  EXPECT_EQ(alignment_builds(), before);
}

TEST(BuiltAlignment, AReplaysUsesOfOneTableBuildItOncePerDatum) {
  // The tunnel-drive sample, read as the replay reads it: the alignment
  // file's check and the scene's check are one build (both relative to the
  // table's first station); the uses after it (the typed pole, the
  // rendered round, the project's check, the placement: all at the
  // scene's datum, on copies of the record) are one more.
  const std::size_t before = alignment_builds();
  const Scene scene =
      load_scene(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-drive.scene.json");
  ASSERT_TRUE(scene.tunnel && scene.has_datum);
  EXPECT_EQ(alignment_builds() - before, 1u);
  const TunnelRecord& rec = scene.tunnel->record;
  for (int use = 0; use < 4; ++use) {
    const TunnelRecord stored = rec;
    (void)stored.alignment(scene.datum);
  }
  EXPECT_EQ(alignment_builds() - before, 2u);
}

}  // namespace
}  // namespace rockface::storage

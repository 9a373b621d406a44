// Issue 41: a replay built the tunnel's alignment six times from one table
// (the scene's check, the typed pole, the rendered round, the project's
// check, the placement), ~1 s of CPU each at 10^6 rows. The table and the
// records made from it keep the alignment they built: counted here, with
// what must still be built again (another datum, a changed table).
#include <gtest/gtest.h>

#include <string>

#include "storage/scene/scene.h"
#include "tests/support/test_paths.h"
#include "storage/tunnel/tunnel_files.h"
#include "storage/tunnel/tunnel_records.h"

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
  const tunnel::Alignment first = rec.alignment(datum);
  const TunnelRecord copy = rec;  // as the replay copies the scene's record
  const tunnel::Alignment again = copy.alignment(datum);
  EXPECT_EQ(rec.built->builds(), 1u);
  // The same alignment: the axis 50 m along lies 50 m north of the datum.
  EXPECT_EQ(again.point_at(50), first.point_at(50));
  EXPECT_EQ(again.point_at(50), Eigen::Vector3d(0, 50, 0));
  // Another datum is another build; the drive is only the copy's.
  TunnelRecord descending = rec;
  descending.drive = tunnel::Drive::descending;
  EXPECT_EQ(descending.alignment(datum).tangent_at(50), Eigen::Vector3d(0, -1, 0));
  EXPECT_EQ(rec.alignment(datum).tangent_at(50), Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(rec.built->builds(), 1u);
  (void)rec.alignment(Eigen::Vector3d::Zero());
  EXPECT_EQ(rec.built->builds(), 2u);
}

TEST(BuiltAlignment, AStationChangedAfterTheBuildIsBuiltAgainNotServedStale) {
  TunnelRecord rec = straight_record();
  const Eigen::Vector3d datum(2600000, 1200000, 450);
  (void)rec.alignment(datum);
  TunnelRecord moved = rec;                            // shares the kept alignment
  moved.stations[1].survey = {2600100, 1200000, 450};  // now due east
  EXPECT_EQ(moved.alignment(datum).point_at(50), Eigen::Vector3d(50, 0, 0));
  EXPECT_EQ(rec.alignment(datum).point_at(50), Eigen::Vector3d(0, 50, 0));
}

TEST(BuiltAlignment, AReadSceneHasBuiltItsAlignmentOnceForItsDatum) {
  // The tunnel-drive sample: its alignment file checked when read, against
  // the scene's datum, and that build kept for what uses it afterwards.
  const Scene scene =
      load_scene(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-drive.scene.json");
  ASSERT_TRUE(scene.tunnel && scene.has_datum);
  const TunnelRecord& rec = scene.tunnel->record;
  EXPECT_EQ(rec.built->builds(), 1u);
  const TunnelRecord stored = rec;
  (void)stored.alignment(scene.datum);
  (void)rec.alignment(scene.datum);
  EXPECT_EQ(rec.built->builds(), 1u);
}

}  // namespace
}  // namespace rockface::storage

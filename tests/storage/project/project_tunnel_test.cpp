// The tunnel in the project (schema 5): the tunnel and the visits' places
// round-trip exactly, bad records are refused by field, and a project of
// schema 4 is upgraded keeping everything it held.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/error.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

TunnelRecord sample_tunnel() {
  TunnelRecord t;
  t.name = "Gotthard access tunnel, north drive";
  const Eigen::Vector3d d = test::sample_project().datum;
  // 100 m straight north, then a right-hand arc of radius 200 m (0.5 rad).
  const Eigen::Vector2d c(200, 100);
  t.stations = {{1000, d + Eigen::Vector3d(0, 0, 1)},
                {1100, d + Eigen::Vector3d(0, 100, 2)},
                {1200, d + Eigen::Vector3d(c.x() + 200 * std::cos(std::numbers::pi - 0.5),
                                           c.y() + 200 * std::sin(std::numbers::pi - 0.5), 3)}};
  t.radii = {0, 200};
  t.polyline = false;
  t.profile = tunnel::horseshoe_profile(5, 1.5, 10, -2.5);
  t.drive = tunnel::Drive::descending;
  t.underbreak_tolerance_m = 0.08;
  t.alignment_source = "align.csv";
  t.profile_source = "horseshoe.json";
  return t;
}

void expect_same_tunnel(const TunnelRecord& a, const TunnelRecord& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.stations.size(), b.stations.size());
  for (std::size_t i = 0; i < a.stations.size(); ++i) {
    EXPECT_EQ(a.stations[i].chainage, b.stations[i].chainage);
    EXPECT_EQ(a.stations[i].survey, b.stations[i].survey);  // REAL keeps every bit
  }
  EXPECT_EQ(a.radii, b.radii);
  EXPECT_EQ(a.polyline, b.polyline);
  EXPECT_EQ(a.drive, b.drive);
  EXPECT_EQ(a.underbreak_tolerance_m, b.underbreak_tolerance_m);
  EXPECT_EQ(a.alignment_source, b.alignment_source);
  EXPECT_EQ(a.profile_source, b.profile_source);
  ASSERT_EQ(a.profile.segments().size(), b.profile.segments().size());
  for (std::size_t i = 0; i < a.profile.segments().size(); ++i) {
    const auto &s = a.profile.segments()[i], &t = b.profile.segments()[i];
    EXPECT_EQ(s.kind, t.kind);
    EXPECT_EQ(s.from, t.from);
    EXPECT_EQ(s.to, t.to);
    if (s.kind == tunnel::ProfileSegment::Kind::arc) {
      EXPECT_EQ(s.centre, t.centre);
      EXPECT_EQ(s.ccw, t.ccw);
    }
  }
  EXPECT_EQ(a.profile.ray_centre(), b.profile.ray_centre());
  EXPECT_EQ(a.profile.name(), b.profile.name());
}

VisitPlacement by_ground_control(RecordId visit) {
  VisitPlacement p;
  p.visit_id = visit;
  p.method = VisitPlacement::Method::ground_control;
  p.chainage = 1123.456;
  p.offset_m = -0.21;
  p.height_m = 0.4;
  p.rms_m = 0.012;
  p.residuals = {{"MP 1123 L", {0.004, -0.01, 0.002}}, {"MP 1123 R", {-0.003, 0.008, 0.001}}};
  p.note = "targets of the monitoring section 1123";
  return p;
}

TEST(ProjectTunnel, TunnelAndPlacementsRoundTrip) {
  TempDir dir("tunnel");
  auto store = ProjectStore::create(dir / "t.rockface", test::sample_project());
  EXPECT_EQ(store.schema_version(), schema::kCurrentVersion);
  EXPECT_FALSE(store.load_tunnel());
  const TunnelRecord t = sample_tunnel();
  store.save_tunnel(t);
  const auto back = store.load_tunnel();
  ASSERT_TRUE(back);
  expect_same_tunnel(t, *back);
  // It makes the same alignment.
  const auto al = back->alignment(test::sample_project().datum);
  EXPECT_EQ(al.drive(), tunnel::Drive::descending);
  EXPECT_NEAR((al.point_at(1150) - t.alignment(test::sample_project().datum).point_at(1150)).norm(),
              0, 0);

  // Saving again replaces it (a polyline this time).
  TunnelRecord poly = t;
  poly.polyline = true;
  poly.radii.clear();
  poly.stations.pop_back();
  poly.profile = tunnel::circle_profile(4.2);
  store.save_tunnel(poly);
  expect_same_tunnel(poly, *store.load_tunnel());

  const RecordId v1 = store.begin_visit("tablet");
  const RecordId v2 = store.begin_visit("tablet");
  store.save_visit_placement(by_ground_control(v1));
  VisitPlacement typed;
  typed.visit_id = v2;
  typed.method = VisitPlacement::Method::chainage_compass;
  typed.chainage = 1119.5;
  typed.offset_m = 0;
  typed.compass_azimuth_deg = 352.5;
  store.save_visit_placement(typed);
  const auto p1 = store.load_visit_placement(v1);
  ASSERT_TRUE(p1);
  EXPECT_EQ(p1->method, VisitPlacement::Method::ground_control);
  EXPECT_EQ(p1->chainage, 1123.456);
  EXPECT_EQ(p1->height_m, std::optional<double>(0.4));
  ASSERT_EQ(p1->residuals.size(), 2u);
  EXPECT_EQ(p1->residuals[1].label, "MP 1123 R");
  EXPECT_EQ(p1->residuals[1].residual, Eigen::Vector3d(-0.003, 0.008, 0.001));
  const auto p2 = store.load_visit_placement(v2);
  ASSERT_TRUE(p2);
  EXPECT_EQ(p2->compass_azimuth_deg, std::optional<double>(352.5));
  EXPECT_FALSE(p2->rms_m);
  const auto all = store.list_visit_placements();
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].visit_id, v2);  // by chainage
  // Placing again replaces.
  VisitPlacement moved = by_ground_control(v1);
  moved.chainage = 1124;
  moved.residuals.pop_back();
  store.save_visit_placement(moved);
  EXPECT_EQ(store.load_visit_placement(v1)->residuals.size(), 1u);
  EXPECT_EQ(store.load_visit_placement(v1)->chainage, 1124);
  EXPECT_TRUE(store.check_integrity().ok);
}

TEST(ProjectTunnel, BadRecordsAreRefusedByField) {
  TempDir dir("tunnel-bad");
  auto store = ProjectStore::create(dir / "t.rockface", test::sample_project());
  TunnelRecord t = sample_tunnel();
  t.stations[2].chainage = 1100;
  try {
    store.save_tunnel(t);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tunnel.stations[2]"), std::string::npos) << e.what();
  }
  t = sample_tunnel();
  t.profile = tunnel::DesignProfile({tunnel::ProfileSegment::line({0, 0}, {1, 0})});
  EXPECT_THROW(store.save_tunnel(t), InputError);
  t = sample_tunnel();
  t.underbreak_tolerance_m = -0.1;
  EXPECT_THROW(store.save_tunnel(t), InputError);
  EXPECT_FALSE(store.load_tunnel());  // nothing half-saved

  const RecordId v = store.begin_visit("tablet");
  VisitPlacement p = by_ground_control(v);
  p.residuals.clear();
  EXPECT_THROW(store.save_visit_placement(p), InputError);
  p = by_ground_control(v + 99);  // no such visit
  try {
    store.save_visit_placement(p);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is there a visit"), std::string::npos) << e.what();
  }
  p = by_ground_control(v);
  p.chainage = std::nan("");
  EXPECT_THROW(store.save_visit_placement(p), InputError);
  EXPECT_FALSE(store.load_visit_placement(v));
}

TEST(ProjectTunnel, SchemaFourProjectIsUpgradedKeepingEverything) {
  TempDir dir("migration-5");
  const auto file = dir / "v4.rockface";
  RecordId visit = 0;
  std::vector<JointSet> sets;
  {
    // What rockface wrote at schema 4: version 1 upgraded to 4, then records.
    sqlite::Connection db(file, sqlite::Connection::Access::read_write_create);
    schema::create_version_1(db);
    schema::migrate_to(db, 4);
    ASSERT_EQ(schema::version_of(db), 4);
    db.exec(
        "INSERT INTO project VALUES (1, 'old site', 2690000.5, 1170000.25, 1100, 'LV95', "
        "'2026-01-01T00:00:00.000Z', 'rockface 0.4');"
        "INSERT INTO visit VALUES (1, '2026-01-02T08:00:00.000Z', 'tablet', 'round 41');"
        "INSERT INTO joint_set (id, visit_id, label, dip, dipdir, fisher_k, count, alpha95_deg) "
        "VALUES (1, 1, 'J1', 62, 118, 85, 24, 3.1);"
        "INSERT INTO action_log VALUES (1, '2026-01-02T08:00:00.000Z', 1, 'visit begun', '');",
        "test");
  }
  {
    auto store = ProjectStore::open(file);
    EXPECT_EQ(store.schema_version(), schema::kCurrentVersion);
    EXPECT_TRUE(store.check_integrity().ok);
    EXPECT_EQ(store.project().name, "old site");
    EXPECT_EQ(store.project().datum.x(), 2690000.5);
    ASSERT_EQ(store.list_visits().size(), 1u);
    EXPECT_EQ(store.list_visits()[0].note, "round 41");
    sets = store.list_joint_sets(1);
    ASSERT_EQ(sets.size(), 1u);
    EXPECT_EQ(sets[0].label, "J1");
    EXPECT_EQ(sets[0].fisher_k, 85);
    EXPECT_FALSE(store.list_actions().empty());
    // No tunnel yet, no placements; both can be added now.
    EXPECT_FALSE(store.load_tunnel());
    EXPECT_TRUE(store.list_visit_placements().empty());
    store.save_tunnel(sample_tunnel());
    store.save_visit_placement(by_ground_control(1));
    visit = 1;
  }
  auto again = ProjectStore::open(file);
  ASSERT_TRUE(again.load_tunnel());
  ASSERT_TRUE(again.load_visit_placement(visit));
  EXPECT_EQ(again.list_joint_sets(1).size(), 1u);
}

}  // namespace
}  // namespace rockface::storage

// The sets along the drive: five visits along 10 m in which one set turns
// by 20 deg, one appears in the last two visits and one vanishes; sets are
// matched by orientation whatever the visits called them and whichever
// sense their normals were written in.
#include "core/tunnel/drive_sets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/common/error.h"
#include "core/geometry/orientation.h"

namespace rockface::tunnel {
namespace {

// A visit's mean pole, nudged by a small deterministic rotation (< 0.5 deg,
// well inside the ~2.6 deg alpha95 of 30 poles at K = 100) as real visits
// scatter.
Eigen::Vector3d pole(double dip, double dipdir, int visit, bool flip = false) {
  const double a = 0.4 * std::sin(1.7 * visit + dip) * std::numbers::pi / 180;
  const Eigen::Vector3d axis = Eigen::Vector3d(std::cos(visit), std::sin(visit), 0.3).normalized();
  const Eigen::Vector3d n = Eigen::AngleAxisd(a, axis) * geometry::plane_normal_deg(dip, dipdir);
  return flip ? Eigen::Vector3d(-n) : n;
}

// Chainages 0, 2.5, 5, 7.5, 10. A (70/120) everywhere; B (40/300) steady to
// chainage 5, then turning: dip 50 at 7.5, 60 at 10 (20 deg in all); C
// (80/030) only at 7.5 and 10; D (15/200) only at 0 to 5. Names shuffle.
std::vector<VisitSets> five_visits(double sign = 1) {
  const double b_dip[5] = {40, 40, 40, 50, 60};
  std::vector<VisitSets> v;
  for (int i = 0; i < 5; ++i) {
    VisitSets visit;
    visit.visit_id = 100 + i;
    visit.chainage = sign * 2.5 * i;
    visit.sets.push_back({i % 2 ? "J2" : "J1", pole(70, 120, i, i == 3), 80, 25});
    visit.sets.push_back({i % 2 ? "J1" : "J2", pole(b_dip[i], 300, i), 100, 30});
    if (i >= 3) visit.sets.push_back({"J3", pole(80, 30, i), 60, 12});
    if (i <= 2) visit.sets.push_back({"J4", pole(15, 200, i, true), 50, 20});
    v.push_back(visit);
  }
  return v;
}

const SetTrack* track_near(const DriveSets& d, double dip, double dipdir) {
  for (const auto& t : d.tracks)
    if (std::acos(std::min(1.0, std::abs(t.points.front().normal.dot(
                                    geometry::plane_normal_deg(dip, dipdir))))) < 0.02)
      return &t;
  return nullptr;
}

TEST(DriveSets, TurnNewAndVanishedSetsAreFoundAtTheirChainage) {
  const DriveSets d = track_sets_along_drive(five_visits());
  ASSERT_EQ(d.tracks.size(), 4u);
  const SetTrack* a = track_near(d, 70, 120);
  const SetTrack* b = track_near(d, 40, 300);
  const SetTrack* c = track_near(d, 80, 30);
  const SetTrack* dd = track_near(d, 15, 200);
  ASSERT_TRUE(a && b && c && dd);
  // A: one track through all five visits despite the names and the flipped
  // normal, nothing flagged.
  EXPECT_EQ(a->points.size(), 5u);
  EXPECT_TRUE(a->events.empty());
  EXPECT_FALSE(a->turns || a->appears || a->vanishes);
  // B turns between chainage 5 and 7.5: 10 deg from its mean, against cones
  // of ~2.6 + ~1.5 deg.
  EXPECT_EQ(b->points.size(), 5u);
  EXPECT_TRUE(b->turns);
  ASSERT_FALSE(b->events.empty());
  EXPECT_EQ(b->events.front().kind, TrackEvent::Kind::turns);
  EXPECT_DOUBLE_EQ(b->events.front().chainage, 7.5);
  EXPECT_DOUBLE_EQ(b->events.front().previous_chainage, 5.0);
  // The angle is the dip change of 10 deg, give or take the 0.4 deg nudges.
  EXPECT_NEAR(b->events.front().angle_deg, 10, 1.0);
  EXPECT_GT(b->events.front().angle_deg, b->events.front().cone_deg);
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(b->points[static_cast<std::size_t>(i)].turned) << i;
  // The dip recorded per visit follows the turn.
  EXPECT_NEAR(b->points[4].dip_deg, 60, 0.5);
  // C is new at 7.5; D vanishes at 7.5 (last seen at 5).
  EXPECT_TRUE(c->appears);
  ASSERT_EQ(c->events.size(), 1u);
  EXPECT_DOUBLE_EQ(c->events[0].chainage, 7.5);
  EXPECT_DOUBLE_EQ(c->events[0].previous_chainage, 5.0);
  EXPECT_NE(c->events[0].message.find("appears at chainage 7.50"), std::string::npos)
      << c->events[0].message;
  EXPECT_TRUE(dd->vanishes);
  ASSERT_EQ(dd->events.size(), 1u);
  EXPECT_EQ(dd->events[0].kind, TrackEvent::Kind::vanishes);
  EXPECT_DOUBLE_EQ(dd->events[0].chainage, 7.5);
  EXPECT_DOUBLE_EQ(dd->events[0].previous_chainage, 5.0);
  // alpha95 of 30 poles at K = 100: cos a = 1 - (N - R)/R (20^(1/29) - 1).
  const double R = 30 - 29.0 / 100;
  const double a95 =
      std::acos(1 - (30 - R) / R * (std::pow(20.0, 1.0 / 29) - 1)) * 180 / std::numbers::pi;
  EXPECT_NEAR(b->points[0].alpha95_deg, a95, 1e-12);
  EXPECT_NEAR(fisher_alpha95_deg(100, 30), a95, 1e-12);
}

// The turning rule at its threshold: two visits of one set, 20 poles at
// K = 50 each, the second turned (its dip steeper, about the strike) by the
// two visits' alpha95 together (the running mean before it is the first
// visit alone) less or more 0.01 deg. alpha95 from Fisher's formula written
// out here. 0.01 deg is far above the rounding of the angle between two
// unit vectors (about 1e-7 deg) and below any change a geologist reads.
TEST(DriveSets, ASetTurnsJustBeyondTheTwoConesAndNotJustWithinThem) {
  const int n = 20;
  const double k = 50;
  const double r = n - (n - 1) / k;
  const double a95 =
      std::acos(1 - (n - r) / r * (std::pow(20.0, 1.0 / (n - 1)) - 1)) * 180 / std::numbers::pi;
  const double cone = 2 * a95;  // about 2 x 4.5 deg
  // Dip 40 towards 300: the strike (horizontal, across the dip direction)
  // is the axis that steepens the dip.
  const double dd = 300 * std::numbers::pi / 180, dip = 40 * std::numbers::pi / 180;
  const Eigen::Vector3d before(std::sin(dip) * std::sin(dd), std::sin(dip) * std::cos(dd),
                               std::cos(dip));
  const Eigen::Vector3d strike(-std::cos(dd), std::sin(dd), 0);
  for (const double margin : {-0.01, 0.01}) {
    const double turn = cone + margin;
    const Eigen::Vector3d after = Eigen::AngleAxisd(turn * std::numbers::pi / 180, strike) * before;
    const DriveSets d = track_sets_along_drive(
        {{1, 10.0, {{"J1", before, k, n}}}, {2, 12.5, {{"J1", after, k, n}}}});
    ASSERT_EQ(d.tracks.size(), 1u) << margin;
    const SetTrack& t = d.tracks[0];
    ASSERT_EQ(t.points.size(), 2u) << margin;
    EXPECT_NEAR(t.points[1].dip_deg, 40 + turn, 1e-6) << "the turn steepens the dip";
    EXPECT_NEAR(t.points[1].turn_cone_deg, cone, 1e-9) << margin;
    EXPECT_NEAR(t.points[1].angle_to_running_mean_deg, turn, 1e-6) << margin;
    EXPECT_EQ(t.turns, margin > 0) << "turned by " << turn << " deg against cones of " << cone;
    EXPECT_EQ(t.points[1].turned, margin > 0) << margin;
    EXPECT_FALSE(t.points[0].turned);
    if (margin > 0) {
      ASSERT_EQ(t.events.size(), 1u);
      EXPECT_EQ(t.events[0].kind, TrackEvent::Kind::turns);
      EXPECT_DOUBLE_EQ(t.events[0].chainage, 12.5);
      EXPECT_DOUBLE_EQ(t.events[0].previous_chainage, 10.0);
    } else {
      EXPECT_TRUE(t.events.empty());
    }
  }
}

TEST(DriveSets, ADescendingDriveWalksTheVisitsByFallingChainage) {
  DriveSetOptions o;
  o.drive = Drive::descending;
  std::vector<VisitSets> v = five_visits(-1);
  std::swap(v[0], v[4]);  // the order given does not matter
  const DriveSets d = track_sets_along_drive(v, o);
  ASSERT_EQ(d.tracks.size(), 4u);
  EXPECT_DOUBLE_EQ(d.visits.front().chainage, 0);
  EXPECT_DOUBLE_EQ(d.visits.back().chainage, -10);
  const SetTrack* b = track_near(d, 40, 300);
  ASSERT_TRUE(b && !b->events.empty());
  EXPECT_DOUBLE_EQ(b->events.front().chainage, -7.5);
}

TEST(DriveSets, AThousandVisitsKeepThreeSteadySets) {
  // The benchmark's input (tools/bench/tunnel_bench.cpp) at its size: three
  // sets seen in every visit, scattering within their cones: three tracks
  // of 1000 points and no event. Timing is the benchmark's business.
  std::vector<VisitSets> v;
  for (int i = 0; i < 1000; ++i) {
    VisitSets visit{i + 1, 3.0 * i, {}};
    visit.sets = {{"a", pole(70, 120, i), 80, 25},
                  {"b", pole(40, 300, i), 100, 30},
                  {"c", pole(20, 30, i), 60, 15}};
    v.push_back(visit);
  }
  const DriveSets d = track_sets_along_drive(v);
  ASSERT_EQ(d.tracks.size(), 3u);
  for (const auto& t : d.tracks) {
    EXPECT_EQ(t.points.size(), 1000u);
    EXPECT_TRUE(t.events.empty());
  }
}

TEST(DriveSets, BadInputIsRefusedByName) {
  std::vector<VisitSets> v = five_visits();
  v[1].visit_id = v[0].visit_id;
  EXPECT_THROW(track_sets_along_drive(v), InputError);
  v = five_visits();
  v[2].sets[1].normal = Eigen::Vector3d::Zero();
  try {
    track_sets_along_drive(v);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("visits[2].sets[1]"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(track_sets_along_drive({}).tracks.empty());
}

}  // namespace
}  // namespace rockface::tunnel

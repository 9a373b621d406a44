// Joining pieces of joint traces in the face frame (join_trace_pieces): the
// rule the replay, the tablet's analysis of a visit and `rockface measure`
// share.
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "core/photogrammetry/surface/trace_pieces.h"

namespace rp = rockface::photogrammetry;

namespace {

// A joint trace on a vertical face (the x-z plane), running down to the
// east at 17 deg: points every centimetre from `from` to `to` metres along
// it, shifted by `offset` (face frame, m).
const Eigen::Vector3d kRun = Eigen::Vector3d(1, 0, -0.3).normalized();
const Eigen::Vector3d kAcross =
    Eigen::Vector3d(0.3, 0, 1).normalized();  // in the face, normal to the run

rp::TracePiece piece(const std::string& label, const std::string& joint, int image, double from,
                     double to, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  rp::TracePiece p{label, joint, image, {}};
  for (double s = from; s <= to + 1e-9; s += 0.01) p.points.push_back(s * kRun + offset);
  return p;
}

}  // namespace

// Two overlapping pieces of J1, one per pair, differing by a 1 cm
// registration residual on their common part: one trace with both pieces,
// spanning both, its points ordered along the run.
TEST(JoinTracePieces, OverlappingPiecesOfOneJointFromTwoPairsAreOneTrace) {
  const auto traces = rp::join_trace_pieces(
      {piece("T1", "J1", 0, 0.0, 1.2), piece("T4", "J1", 1, 0.9, 2.0, 0.01 * kAcross)});
  ASSERT_EQ(traces.size(), 1u);
  const rp::FaceTrace& t = traces[0];
  EXPECT_EQ(t.label, "T1");
  EXPECT_EQ(t.joint, "J1");
  EXPECT_EQ(t.pieces, (std::vector<std::string>{"T1", "T4"}));
  EXPECT_EQ(t.images, (std::vector<int>{0, 1}));
  ASSERT_EQ(t.points.size(), 121u + 111u);
  // Ordered along the run (either way): the along-run coordinate is
  // monotonic and goes from one end of T1 to the far end of T4. 1e-9: the
  // 1 cm sampling is exact up to rounding; the 1 cm offset is across.
  const double first = t.points.front().dot(kRun), last = t.points.back().dot(kRun);
  const double sign = last > first ? 1 : -1;
  for (std::size_t k = 1; k < t.points.size(); ++k)
    EXPECT_GE(sign * (t.points[k].dot(kRun) - t.points[k - 1].dot(kRun)), -1e-9) << k;
  EXPECT_NEAR(std::min(first, last), 0.0, 1e-9);
  EXPECT_NEAR(std::max(first, last), 2.0, 1e-9);
}

// An unassigned piece continues a joint's piece from another pair: joined,
// the trace takes the joint.
TEST(JoinTracePieces, AnUnassignedPieceJoinsAndTheTraceTakesTheJoint) {
  const auto traces =
      rp::join_trace_pieces({piece("T1", "", 0, 0.0, 1.2), piece("T4", "J1", 1, 1.0, 2.0)});
  ASSERT_EQ(traces.size(), 1u);
  EXPECT_EQ(traces[0].joint, "J1");
}

// The same overlap within one pair: traces the geologist drew apart, kept
// apart.
TEST(JoinTracePieces, PiecesOfOnePairAreNotJoined) {
  const auto traces =
      rp::join_trace_pieces({piece("T1", "J1", 0, 0.0, 1.2), piece("T2", "J1", 0, 0.9, 2.0)});
  ASSERT_EQ(traces.size(), 2u);
  EXPECT_EQ(traces[0].pieces, std::vector<std::string>{"T1"});
  EXPECT_EQ(traces[1].pieces, std::vector<std::string>{"T2"});
  // Unjoined pieces keep their points as given.
  EXPECT_EQ(traces[0].points.size(), 121u);
  EXPECT_EQ(traces[0].points.front(), Eigen::Vector3d::Zero());
}

// Two traces of a joint set 20 cm apart (beyond the 5 cm join distance),
// parallel, on different pairs: two traces.
TEST(JoinTracePieces, ParallelTracesTwentyCentimetresApartAreNotJoined) {
  const auto traces = rp::join_trace_pieces(
      {piece("T1", "J1", 0, 0.0, 1.2), piece("T4", "J1", 1, 0.0, 1.2, 0.2 * kAcross)});
  EXPECT_EQ(traces.size(), 2u);
}

// Overlapping pieces named for different joints, and a piece of the same
// joint crossing at 30 deg (beyond the 10 deg limit): not joined.
TEST(JoinTracePieces, DifferentJointsOrDirectionsAreNotJoined) {
  EXPECT_EQ(rp::join_trace_pieces(
                {piece("T1", "J1", 0, 0.0, 1.2), piece("T4", "J2", 1, 0.9, 2.0, 0.01 * kAcross)})
                .size(),
            2u);
  rp::TracePiece crossing{"T5", "J1", 1, {}};
  const Eigen::Vector3d turned =
      Eigen::AngleAxisd(30.0 * M_PI / 180, Eigen::Vector3d::UnitY()) * kRun;
  for (double s = -0.5; s <= 0.5; s += 0.01) crossing.points.push_back(0.6 * kRun + s * turned);
  EXPECT_EQ(rp::join_trace_pieces({piece("T1", "J1", 0, 0.0, 1.2), crossing}).size(), 2u);
}

// A one-point piece has no direction: it stays on its own.
TEST(JoinTracePieces, AOnePointPieceStaysAlone) {
  rp::TracePiece dot{"T9", "J1", 1, {0.5 * kRun}};
  const auto traces = rp::join_trace_pieces({piece("T1", "J1", 0, 0.0, 1.2), dot});
  ASSERT_EQ(traces.size(), 2u);
  EXPECT_EQ(traces[1].points.size(), 1u);
}

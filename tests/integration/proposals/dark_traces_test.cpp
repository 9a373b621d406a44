// Trace proposals on planar faces whose joints are dark lines without
// relief (issue 38, "Joints proposed on the image"): the faces of
// dark_trace_faces.h, sparse, medium and dense networks of three sets
// crossing each other many times, rendered by the mock camera (the demo
// scene's 1500 x 1000 camera, sensor noise), reconstructed and proposed at
// the tablet's preset (standard). Precision and recall are against the
// renderer's true traces within 5 cm (the tolerance), as in
// trace_proposals_test.cpp; the registration's own error is taken out
// (build_proposal_face_from).
#include <cstdio>
#include <map>

#include <gtest/gtest.h>

#include "tests/support/dark_trace_faces.h"

namespace rm = rockface::measure;
namespace rt = rockface::testing;

namespace {

constexpr double kTolerance = 0.05;  // m: the "within 5 cm"

using FaceRun = rt::ProposedFace;

const FaceRun& run(rt::TraceNetwork network) {
  static std::map<rt::TraceNetwork, std::unique_ptr<FaceRun>> runs;
  auto& r = runs[network];
  if (!r) {
    r = rt::propose_on(rt::build_dark_trace_face(network, rockface::Preset::standard),
                       rockface::Preset::standard, kTolerance);
    const auto& s = r->score;
    std::printf(
        "%s: %zu proposals, %.2f m; precision %.3f, recall %.3f of %.2f m of true traces; "
        "%.2f m false (sigma_Z %.1f mm)\n",
        rt::network_name(network), s.proposals, s.proposed_m, s.precision, s.recall, s.truth_m,
        s.false_m, 1000 * r->face.rec.accuracy.sigma_z);
    for (const auto& note : r->result.notes) std::printf("  %s\n", note.c_str());
  }
  return *r;
}

// Where two true traces of different joints cross, a proposal that runs
// along one of them on both sides of the crossing (within the tolerance at
// `reach` before and after it) followed that trace through the junction.
struct Junctions {
  int seen = 0;      // crossings of traces the 3D image covers, counted per trace
  int followed = 0;  // ... that one proposal runs through
};

bool on_surface(const FaceRun& r, const Eigen::Vector3d& q) {
  const auto px = rm::project_to_view(r.face.left, {q})[0];
  if (!px.allFinite() || !rm::pixel_in_image(r.face.left, px)) return false;
  const auto hit = r.picker->pick(rm::ray_through_pixel(r.face.left, px, "truth"));
  return hit && (hit->point - q).norm() <= 3 * kTolerance;  // as score_proposals covers
}

double distance_to_proposal(const rm::TraceProposal& p, const Eigen::Vector3d& q) {
  double best = 1e9;
  const auto& x = p.trace.points;
  for (std::size_t k = 1; k < x.size(); ++k)
    best = std::min(best, rt::distance_to_segment(q, x[k - 1], x[k]));
  return best;
}

Junctions junctions_followed(const FaceRun& r, double reach) {
  Junctions j;
  const auto& truth = r.face.truth;
  for (std::size_t a = 0; a < truth.size(); ++a)
    for (std::size_t b = 0; b < truth.size(); ++b) {
      if (a == b || r.face.truth_joint[a] == r.face.truth_joint[b]) continue;
      // The crossing: the point of a's segment nearest b's line (both lie
      // on the face, so they meet there when they cross at all).
      const Eigen::Vector3d pa = truth[a][0], da = (truth[a][1] - pa).normalized();
      const Eigen::Vector3d pb = truth[b][0], db = (truth[b][1] - pb).normalized();
      const Eigen::Vector3d n = da.cross(db);
      if (n.norm() < 1e-3) continue;
      const double ta = (pb - pa).cross(db).dot(n) / n.squaredNorm();
      const double tb = (pb - pa).cross(da).dot(n) / n.squaredNorm();
      const double la = (truth[a][1] - pa).norm(), lb = (truth[b][1] - pb).norm();
      if (ta < reach || ta > la - reach || tb < 0 || tb > lb) continue;
      const Eigen::Vector3d before = pa + (ta - reach) * da, after = pa + (ta + reach) * da;
      if (!on_surface(r, before) || !on_surface(r, after)) continue;
      ++j.seen;
      for (const auto& p : r.result.proposals)
        if (distance_to_proposal(p, before) <= kTolerance &&
            distance_to_proposal(p, after) <= kTolerance) {
          ++j.followed;
          break;
        }
    }
  return j;
}

}  // namespace

TEST(DarkTraceProposals, PrecisionAndRecallOnCrossingNetworksAtTheTabletsPreset) {
  for (auto network : {rt::TraceNetwork::medium, rt::TraceNetwork::dense}) {
    const rt::ProposalScore& s = run(network).score;
    ASSERT_GT(s.truth_m, 20.0) << "the 3D image must cover the true traces";
    // The figures. A proposal on a trace lies within the standard
    // reconstruction's depth noise (sigma_Z ~8 mm) and a pixel (4.5 mm) of
    // the true line, far inside 5 cm: a false point is a line off every
    // joint. Recall is lost behind and beside the range pole, within a line
    // width of the 3D image's edge and where two traces cross at under 20
    // degrees (their dark lines merge for a few centimetres). Seen: 1.000
    // and 0.960 / 0.952 (medium, dense); 0.64 / 0.66 before the skeleton
    // was made 8-thin and lines were joined through their junctions.
    EXPECT_GE(s.precision, 0.8) << rt::network_name(network);
    EXPECT_GE(s.recall, 0.7) << rt::network_name(network);
  }
}

TEST(DarkTraceProposals, ALineIsFollowedThroughTheJunctionsItCrosses) {
  const FaceRun& r = run(rt::TraceNetwork::dense);
  // 15 cm either side of a crossing: beyond where the two dark lines'
  // skeletons merge (two widths of the 4 cm Hessian scale at under 30
  // degrees), so a proposal there runs on through the junction.
  const Junctions j = junctions_followed(r, 0.15);
  std::printf("dense: %d of %d crossings followed through\n", j.followed, j.seen);
  ASSERT_GT(j.seen, 40) << "15 joints of three sets cross many times";
  // Seen: 72 of 89. Those not followed are where three traces cross
  // within a few centimetres, where two cross at under 20 degrees (their
  // lines merge over 15-20 cm), and beside the range pole. A line cut at
  // every junction follows none.
  EXPECT_GE(j.followed, 0.7 * j.seen);
}

// The phases of propose_traces (proposals/trace_proposals_phases.h), each
// on its own: a fold chain cut where a dark line runs beside it, a chain's
// runs over the surface, a run split at a sharp turn unless both sides are
// one plane, the evidence along a piece, its cue and confidence, the facet
// whose edge it follows, and the weak ones dropped and the rest named.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/measure/proposals/trace_proposals_phases.h"

namespace {

using namespace rockface::measure;
namespace phases = rockface::measure::proposal_phases;
using Poly = std::vector<cv::Point2f>;

TEST(ProposalPhases, AFoldChainIsCutWhereADarkLineRunsBesideIt) {
  Poly chain;
  for (int x = 0; x < 20; ++x) chain.emplace_back(static_cast<float>(x), 3.0f);
  cv::Mat dark_near = cv::Mat::zeros(8, 24, CV_8U);
  dark_near.at<std::uint8_t>(3, 10) = 255;
  const auto runs = phases::fold_runs(chain, dark_near, 5);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].size(), 10u);  // x 0..9
  EXPECT_EQ(runs[1].size(), 9u);   // x 11..19
  EXPECT_EQ(runs[1].front().x, 11.0f);
  // Runs shorter than the fewest pixels worth following are dropped.
  EXPECT_EQ(phases::fold_runs(chain, dark_near, 10).size(), 1u);
}

TEST(ProposalPhases, AChainsRunsAreThoseOverTheSurface) {
  const Poly poly = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}};
  const auto runs =
      phases::surface_runs(poly, [](const cv::Point2f& p) { return p.x != 2.0f && p.x != 5.0f; });
  ASSERT_EQ(runs.size(), 3u);  // the last one empty: the chain ends off the surface
  EXPECT_EQ(runs[0].size(), 2u);
  EXPECT_EQ(runs[1].size(), 2u);
  EXPECT_TRUE(runs[2].empty());
}

TEST(ProposalPhases, ARunIsSplitAtASharpTurnUnlessBothSidesAreOnePlane) {
  const Poly run = {{0, 0}, {10, 0}, {20, 0}, {20, 10}, {20, 20}};
  const auto split = phases::split_at_turns(run, 35.0, [](const Poly&) { return false; });
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[0], (Poly{{0, 0}, {10, 0}, {20, 0}}));
  EXPECT_EQ(split[1], (Poly{{20, 0}, {20, 10}, {20, 20}}));
  const auto one = phases::split_at_turns(run, 35.0, [](const Poly&) { return true; });
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], run);
  // A gentle bend is no turn.
  EXPECT_EQ(phases::split_at_turns(run, 95.0, [](const Poly&) { return false; }).size(), 1u);
}

TEST(ProposalPhases, TheEvidenceAlongAPieceIsTheShareAndMeanOfEachCue) {
  phases::EvidenceMaps maps;
  maps.dark = cv::Mat::zeros(10, 20, CV_8U);
  maps.dark_sigmas = cv::Mat::zeros(10, 20, CV_32F);
  maps.dark_contrast = cv::Mat::zeros(10, 20, CV_32F);
  maps.fold = cv::Mat::zeros(10, 20, CV_8U);
  maps.fold_angle = cv::Mat::zeros(10, 20, CV_32F);
  maps.ridge = cv::Mat::zeros(10, 20, CV_8U);
  maps.valley = cv::Mat::zeros(10, 20, CV_8U);
  // A dark line along row 5 for x < 10 (8 sigmas, 12 grey levels), a ridge
  // fold of 20 degrees along it for x >= 15.
  for (int x = 0; x < 10; ++x) {
    maps.dark.at<std::uint8_t>(5, x) = 255;
    maps.dark_sigmas.at<float>(5, x) = 8.0f;
    maps.dark_contrast.at<float>(5, x) = 12.0f;
  }
  for (int x = 15; x < 20; ++x) {
    maps.fold.at<std::uint8_t>(5, x) = 255;
    maps.fold_angle.at<float>(5, x) = 20.0f;
    maps.ridge.at<std::uint8_t>(5, x) = 255;
  }
  const phases::Evidence e = phases::evidence_along(maps, {{0, 5}, {19, 5}});
  EXPECT_DOUBLE_EQ(e.dark_fraction, 0.5);
  EXPECT_DOUBLE_EQ(e.fold_fraction, 0.25);
  EXPECT_DOUBLE_EQ(e.sigmas, 8.0);
  EXPECT_DOUBLE_EQ(e.contrast, 12.0);
  EXPECT_DOUBLE_EQ(e.fold_deg, 20.0);
  EXPECT_TRUE(e.ridge);
  EXPECT_EQ(phases::proposal_cue(e), ProposalCue::dark_line);
}

TEST(ProposalPhases, TheCueIsBothWhenEachCoversHalfTheLength) {
  phases::Evidence e;
  e.dark_fraction = 0.5;
  e.fold_fraction = 0.5;
  EXPECT_EQ(phases::proposal_cue(e), ProposalCue::both);
  e.dark_fraction = 0.4;
  EXPECT_EQ(phases::proposal_cue(e), ProposalCue::fold);
  e.fold_fraction = 0.3;
  EXPECT_EQ(phases::proposal_cue(e), ProposalCue::dark_line);
}

TEST(ProposalPhases, ConfidenceSaturatesWithEachCueAndGrowsWithLength) {
  ProposalOptions options;
  phases::Evidence none;
  EXPECT_EQ(phases::proposal_confidence(none, 10.0, options), 0.0);
  phases::Evidence dark;
  dark.dark_fraction = 1;
  dark.sigmas = options.dark_seed_sigmas;  // at the seed level: 1 - 1/e
  const double long_line = phases::proposal_confidence(dark, 100.0, options);
  EXPECT_NEAR(long_line, 1 - std::exp(-1.0), 1e-12);
  EXPECT_LT(phases::proposal_confidence(dark, options.min_length_m, options), long_line);
  // Two cues are independent witnesses: more than either alone.
  phases::Evidence both = dark;
  both.fold_fraction = 1;
  both.fold_deg = options.min_fold_deg;
  const double two = phases::proposal_confidence(both, 100.0, options);
  EXPECT_NEAR(two, 1 - std::exp(-2.0), 1e-12);
  EXPECT_LE(two, 1.0);
}

TraceProposal proposal(double confidence, std::vector<Eigen::Vector3d> points) {
  TraceProposal p;
  p.confidence = confidence;
  p.trace.points = std::move(points);
  return p;
}

TEST(ProposalPhases, AProposalFollowsTheFacetMostOfItsPointsLieOnTheEdgeOf) {
  ProposalOptions options;  // 0.05 m, 60 %
  std::vector<TraceProposal> found = {
      proposal(0.5, {{0, 0.01, 0}, {1, 0.02, 0}, {2, 0.0, 0}, {3, 0.5, 0}}),  // 3 of 4 on y = 0
      proposal(0.5, {{0, 0.5, 0}, {1, 0.5, 0}})};
  const std::vector<ProposalFacet> facets = {{7, {{0, 0, 0}, {4, 0, 0}, {4, -2, 0}, {0, -2, 0}}},
                                             {8, {{0, 0.5, 0}, {4, 0.5, 0}, {4, 2, 0}, {0, 2, 0}}}};
  phases::link_facets(found, facets, options);
  ASSERT_TRUE(found[0].facet_id);
  EXPECT_EQ(*found[0].facet_id, 7);
  EXPECT_DOUBLE_EQ(found[0].facet_fraction, 0.75);
  ASSERT_TRUE(found[1].facet_id);
  EXPECT_EQ(*found[1].facet_id, 8);
}

TEST(ProposalPhases, WeakProposalsAreDroppedAndTheRestNamedByFallingConfidence) {
  ProposalOptions options;
  options.min_confidence = 0.15;
  std::vector<TraceProposal> found = {proposal(0.3, {}), proposal(0.1, {}), proposal(0.9, {}),
                                      proposal(0.3, {})};
  found[0].trace.length = 1;
  found[3].trace.length = 2;
  std::vector<std::string> notes;
  phases::rank_proposals(found, options, notes);
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].confidence, 0.9);
  EXPECT_EQ(found[1].trace.length, 1);  // equal confidence: the order found
  EXPECT_EQ(found[2].trace.length, 2);
  EXPECT_EQ(found[0].id, "P1");
  EXPECT_EQ(found[2].trace.id, "P3");
  EXPECT_EQ(notes, (std::vector<std::string>{"1 lines left out: confidence below 15 %"}));
}

}  // namespace

#pragma once
// The phases of propose_traces (trace_proposals.h), each a function of its
// own input, declared here so that each can be read and tested on its own:
//   1. check_proposal_input: the photograph, the mesh's lattice, the widths;
//   2. working_image: the photograph in grey at the scale the lines need;
//   3. find_dark_lines_on / the folds: the two cues (line_evidence.h);
//   4. evidence_maps: the cues spread so that the other cue's line counts;
//   5. candidate_chains: dark-line chains and the fold runs away from them;
//   6. surface_runs, split_at_turns: each chain's measurable pieces;
//   7. evidence_along, proposal_cue, proposal_confidence: a piece scored
//      (measure_chains runs 6 and 7 over every chain);
//   8. link_facets, rank_proposals: facets whose edges they follow, the
//      weak ones dropped, the rest named by falling confidence.
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/measure/proposals/line_chains.h"
#include "core/measure/proposals/line_evidence.h"
#include "core/measure/proposals/trace_proposals.h"

namespace rockface::measure::proposal_phases {

// Throws InputError naming `where` for an empty photograph, one whose size
// is not the view's camera's, a mesh without lattice pixels, or no widths.
void check_proposal_input(const photogrammetry::SurfaceMesh& mesh, const PhotoView& view,
                          const cv::Mat& photo, const ProposalOptions& options,
                          const std::string& where);

// Pixels of the photograph per metre on the surface: the median over a
// sample of lattice edges (1 without any).
double pixels_per_metre(const photogrammetry::SurfaceMesh& mesh);

// The photograph in grey (CV_32F), reduced (never enlarged) so that the
// narrowest line width spans options.pixels_per_line pixels.
struct WorkingImage {
  cv::Mat grey;
  double scale = 1;     // working image / photograph
  double px_per_m = 1;  // working pixels per metre on the surface
};
WorkingImage working_image(const photogrammetry::SurfaceMesh& mesh, const cv::Mat& photo,
                           const ProposalOptions& options);

// The dark lines of the working image, away from the surface's edge (a
// step to no surface, not a line) by the widest width.
proposals::DarkLines find_dark_lines_on(const WorkingImage& image,
                                        const proposals::SurfaceImage& surface,
                                        const ProposalOptions& options);

// The evidence maps a piece is scored on, each spread so that the other
// cue's nearby line counts (a fold as far as its smoothing width).
struct EvidenceMaps {
  cv::Mat dark, dark_sigmas, dark_contrast, fold, fold_angle, ridge, valley;
  cv::Mat dark_near_fold;  // the dark lines spread as far as a fold's
};
EvidenceMaps evidence_maps(const proposals::DarkLines& dark, const proposals::Folds& folds,
                           double smoothing_px);

// The runs of a fold chain away from dark lines (dark_near_fold non-zero),
// of at least min_pixels each: folds where a dark line already runs are
// that line's evidence, not a second proposal.
std::vector<proposals::Chain> fold_runs(const proposals::Chain& chain,
                                        const cv::Mat& dark_near_fold, int min_pixels);

// The dark-line chains joined across gaps of up to gap_px, then the fold
// runs joined alike.
std::vector<proposals::Chain> candidate_chains(const proposals::DarkLines& dark,
                                               const proposals::Folds& folds,
                                               const cv::Mat& dark_near_fold, double gap_px);

// The runs of vertices of a polyline with surface under them (on_surface).
std::vector<std::vector<cv::Point2f>> surface_runs(
    const std::vector<cv::Point2f>& poly,
    const std::function<bool(const cv::Point2f&)>& on_surface);

// A run split where it turns by more than split_turn_deg, unless both sides
// together are one plane (one_plane: a trace crossing a fold of the face).
// The turn at a vertex is read between the directions over window_px of
// the run on either side (a line's skeleton wiggles for a line width where
// another crosses it: no turn), at its neighbouring vertices when
// window_px is 0; of vertices over the threshold within a window of each
// other, the sharpest is the split.
std::vector<std::vector<cv::Point2f>> split_at_turns(
    const std::vector<cv::Point2f>& run, double split_turn_deg,
    const std::function<bool(const std::vector<cv::Point2f>&)>& one_plane, double window_px = 0);

// What the cues saw along a piece.
struct Evidence {
  double dark_fraction = 0, fold_fraction = 0;
  double sigmas = 0, contrast = 0, fold_deg = 0;  // means over the pixels of each cue
  bool ridge = false;
};
Evidence evidence_along(const EvidenceMaps& maps, const std::vector<cv::Point2f>& poly);

// Both cues when each covers half the length, else the one that covers more.
ProposalCue proposal_cue(const Evidence& e);

// Each cue's strength saturates (a line twice the seed level, a fold twice
// the seed angle, are near certain) and counts for the fraction of the
// length it covers; two cues combine as independent witnesses; a short line
// is weak whatever its cues. In [0, 1].
double proposal_confidence(const Evidence& e, double length_m, const ProposalOptions& options);

// Every chain long enough measured as traces: simplified, cut into its
// runs over the surface, split at sharp turns, each piece measured on the
// mesh and scored on the evidence; the chains and pieces left out counted.
// `which`: the chains to measure (indices, in that order), null for all.
struct MeasuredChains {
  std::vector<TraceProposal> found;
  std::vector<std::size_t> chain_of;  // the chain each of `found` came from
  int short_chains = 0;               // shorter than options.min_length_m
  int unmeasurable = 0;               // no surface of the 3D image under them
};
MeasuredChains measure_chains(const std::vector<proposals::Chain>& chains, const EvidenceMaps& maps,
                              const MeshPicker& picker, const PhotoView& view,
                              const WorkingImage& image, const ProposalOptions& options,
                              Progress& progress, const std::string& where,
                              const std::vector<std::size_t>* which = nullptr);
// What measure_chains left out, in words.
std::vector<std::string> left_out_notes(const MeasuredChains& measured,
                                        const ProposalOptions& options);

// Each proposal's facet: the one with the largest fraction (at least
// options.facet_fraction) of its points within options.facet_tolerance_m of
// the facet's outline.
void link_facets(std::vector<TraceProposal>& found, const std::vector<ProposalFacet>& facets,
                 const ProposalOptions& options);

// The proposals under options.min_confidence dropped (said in notes), the
// rest by falling confidence, named P1, P2, ...
void rank_proposals(std::vector<TraceProposal>& found, const ProposalOptions& options,
                    std::vector<std::string>& notes);

}  // namespace rockface::measure::proposal_phases

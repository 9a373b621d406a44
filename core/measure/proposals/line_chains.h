#pragma once
// From one-pixel-wide line images (line_evidence.h) to polylines: the
// 8-connected chains between ends and junctions (on the skeleton made
// 8-thin), then chains joined across junctions and gaps where they run on
// in the same direction (a trace is broken by a patch of light rock, a
// junction continues the straightest pair).
#include <vector>

#include <opencv2/core.hpp>

namespace rockface::measure::proposals {

using Chain = std::vector<cv::Point2f>;

// The chains of a CV_8U line image (non-zero: line), each from end to end;
// chains of fewer than `min_pixels` pixels are dropped.
std::vector<Chain> trace_chains(const cv::Mat& lines, int min_pixels);

// Joins chains that run on in one line across gaps and junctions (issue
// 38: a trace crossed by others is followed through the crossings rather
// than cut at each). Each chain is first cut where it turns by more than
// `max_turn_deg` (the skeleton of one line may run on into a crossing one);
// chains no longer than `max_gap_px` (where two lines crossing at a small
// angle merge) link to neither line. Two ends are joined when within
// `max_gap_px`, or up to three times that when the two sides run on in one
// straight line (within 10 degrees and a couple of pixels: across a
// junction whose lines merged), with their directions (read a few pixels
// back from the end) differing by at most `max_turn_deg` and each end
// within that turn of the other's line; straightest and closest first,
// each end joined once.
std::vector<Chain> join_chains(std::vector<Chain> chains, double max_gap_px, double max_turn_deg);

// Length in pixels along the chain.
double chain_length(const Chain& chain);

}  // namespace rockface::measure::proposals

#pragma once
// From one-pixel-wide line images (line_evidence.h) to polylines: the
// 8-connected chains between ends and junctions, then chains joined across
// junctions and gaps where they run on in the same direction (a trace is
// broken by a patch of light rock, a junction of three chains continues the
// straightest pair).
#include <vector>

#include <opencv2/core.hpp>

namespace rockface::measure::proposals {

using Chain = std::vector<cv::Point2f>;

// The chains of a CV_8U line image (non-zero: line), each from end to end;
// chains of fewer than `min_pixels` pixels are dropped.
std::vector<Chain> trace_chains(const cv::Mat& lines, int min_pixels);

// Joins chains whose ends face each other within `max_gap_px` (end to end)
// and whose directions at those ends, and across the gap, differ by at most
// `max_turn_deg`; closest and straightest first, each end joined once.
std::vector<Chain> join_chains(std::vector<Chain> chains, double max_gap_px, double max_turn_deg);

// Length in pixels along the chain.
double chain_length(const Chain& chain);

}  // namespace rockface::measure::proposals

#pragma once
// SIFT matches between two photographs whose coarse shift is known
// (image_overlap.h): each keypoint is compared only with the other
// photograph's keypoints within a window around where the shift puts it,
// instead of with all of them. On the merge's photographs (6,000-7,000
// keypoints each, a window of a tenth of the frame) that is ~30 times fewer
// descriptor distances than brute force, and the same tie points where the
// shift holds: Lowe's ratio test and the mutual check as in
// match_detected(), among the window's candidates. Both directions of the
// mutual check share one pass (a pair's distance is computed once).
#include <Eigen/Core>

#include "core/photogrammetry/matching/feature_matching.h"

namespace rockface::photogrammetry {

// shift_px: where a point of `left` lies in `right`, minus where it lies in
// `left` (full-resolution pixels); window_px: the half-size of the square
// searched around that place (the parallax of the face's relief and the
// error of the shift).
FeatureMatches match_guided(const ImageFeatures& left, const ImageFeatures& right,
                            const Eigen::Vector2d& shift_px, double window_px,
                            const ReconstructionPreset& preset);

}  // namespace rockface::photogrammetry

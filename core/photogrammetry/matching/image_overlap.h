#pragma once
// How much two photographs of one face overlap, from thumbnails: a cheap
// global test (phase correlation of 256-px grey thumbnails) that tells the
// merge of several 3D images which placed image to match a new one against
// first, instead of matching SIFT against every placed image. Stations moved
// along a face give photographs that differ mostly by a shift, which phase
// correlation finds with a clear peak; unrelated photographs give a low peak.
// Only an order: the tie points decide.
#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace rockface::photogrammetry {

struct Thumbnail {
  cv::Mat grey;      // CV_32F, zero mean
  double scale = 1;  // thumbnail pixels per photograph pixel
};

// `width`: the thumbnail's width in pixels (height by the aspect ratio).
Thumbnail make_thumbnail(const cv::Mat& photograph, int width = 256);

struct CoarseOverlap {
  Eigen::Vector2d shift_px = Eigen::Vector2d::Zero();  // of b against a, photograph pixels
  double fraction = 0;                                 // of a's area that b's shifted frame covers
  // Phase correlation peak, 0..1: the share of the frames' texture that
  // agrees at that shift. It falls with the overlap (on a rock texture,
  // 0.73 / 0.54 / 0.23 / 0.08 at 83 / 67 / 33 / 17 % in common) and stays
  // near 0.05 for unrelated rock, so it is the order to try pairs in.
  double response = 0;
  double score() const { return response; }
};

// Both thumbnails of photographs of the same size.
CoarseOverlap coarse_overlap(const Thumbnail& a, const Thumbnail& b);

}  // namespace rockface::photogrammetry

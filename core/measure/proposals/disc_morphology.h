#pragma once
// Dilation and erosion by a disc (OpenCV's MORPH_ELLIPSE element of 2r + 1
// pixels) of the cues' sparse images: the line images and their values
// are a few thousandths of the image, and the surface's mask is off the
// surface in a few large regions. The element is a stack of centred
// horizontal runs, so each run of set pixels of a row spreads into one
// span of each row of the element (and each value into its span):
// the work is the set pixels' (the unset runs', for an erosion), where
// cv::dilate / cv::erode read every pixel of the element for every pixel
// of the image (~1,400 reads a pixel at r = 21).
#include <opencv2/core.hpp>

namespace rockface::measure::proposals {

// Pixel for pixel what cv::dilate (cv::erode) gives with
// cv::getStructuringElement(cv::MORPH_ELLIPSE, {2r + 1, 2r + 1}), its
// default anchor and border (nothing beyond the image counts). `image`:
// one channel. Spread by runs: CV_8U whose set pixels share one value (a
// mask); CV_32F with no value below 0 (dilation). Any other image is
// handed to OpenCV.
cv::Mat dilate_disc(const cv::Mat& image, int radius);
cv::Mat erode_disc(const cv::Mat& image, int radius);

}  // namespace rockface::measure::proposals

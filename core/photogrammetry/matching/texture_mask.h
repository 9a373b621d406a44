#pragma once
// Where the left image has no texture for dense matching to follow (issue
// 38, "The 3D image beyond the rock"). Semi-global matching carries its
// smoothness along its paths into a featureless region: off a face's top
// edge into the dark background of a tunnel it spreads the rock's
// disparities as a sheet of surface that is not there. A pixel whose
// matching window holds no texture beyond the sensor's noise gives the
// matcher nothing to measure: its disparity is removed before the speckle
// filter, so specks the noise leaves behind go with it.
#include <cstddef>

#include <opencv2/core.hpp>

namespace rockface::photogrammetry {

struct TextureCheck {
  int window_px = 5;  // the matching window (the SGBM block), dense-scale pixels
  // A window is textured when its grey levels' variance, the noise's taken
  // out, exceeds the noise's by this ratio of texture to noise (amplitudes):
  // 1 = as much texture as noise. 0 = no check. The noise is measured where
  // the image is flattest (texture_mask.cpp).
  double min_texture_to_noise = 3.0;  // the presets' (reconstruction/preset.h)
};

// CV_8U, 255 where `image` (8-bit grey or BGR) has texture in the window
// about the pixel, 0 where it has only noise.
cv::Mat textured_pixels(const cv::Mat& image, const TextureCheck& check);

// Sets the disparities (SGBM's CV_16S) of untextured pixels to `invalid`;
// returns how many valid ones (above `invalid`) it removed.
std::size_t remove_untextured(cv::Mat& disparity, short invalid, const cv::Mat& textured);

}  // namespace rockface::photogrammetry

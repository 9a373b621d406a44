#pragma once
// The knobs of two-view reconstruction that trade accuracy for time, bundled
// into the named presets fast | standard | precise (DESIGN.md "Accuracy costs
// time"). tools/bench/reconstruct_bench.cpp measures each of them.
#include <string>

#include "core/common/preset.h"

namespace rockface::photogrammetry {

struct ReconstructionPreset {
  std::string name;

  // Features and relative orientation.
  // Images wider than this are reduced (INTER_AREA) before SIFT; a 24 Mpx
  // frame (6000 px) is thus matched at 2400 px. 0 = never reduce.
  int feature_max_width = 2400;
  int max_features = 8000;  // SIFT keypoints kept per image (strongest)
  double ratio_test = 0.8;  // Lowe's ratio: best / second-best distance
  double sift_contrast =
      0.02;  // SIFT contrast threshold (OpenCV default 0.04): rock in shade is dull
  double ransac_threshold_px = 1.0;  // MAGSAC++ inlier scale at full resolution
  int refine_iterations = 100;       // Levenberg-Marquardt iterations, relative orientation

  // Dense matching.
  // Dense matching works on images reduced to at most this width: the image
  // scale knob. It bounds time and memory (SGBM cost volume ~ width x disparities).
  int dense_max_width = 1600;
  int max_disparities = 256;       // upper bound of the search range (pixels at dense scale)
  double disparity_margin = 0.15;  // widening of the sparse disparity range, fraction of it
  int sgbm_block_size = 5;         // odd; matching window
  int sgbm_p1_per_channel = 8;     // P1 = this * channels * block^2 (OpenCV's advice)
  int sgbm_p2_per_channel = 32;    // P2 = this * channels * block^2
  int uniqueness_ratio = 10;       // percent
  int lr_max_difference_px = 1;    // left-right consistency, pixels at dense scale
  int speckle_window = 100;        // connected region below this many pixels is removed
  double speckle_range_px = 2.0;   // disparity jump that separates speckle regions
  // A pixel whose matching window has less texture than this ratio to the
  // sensor's noise is not matched (matching/texture_mask.h): 1 = the
  // texture's amplitude equals the noise's; 0 = no check. 3: on the
  // synthetic face against its dark background (tests/integration/
  // reconstruct/face_edge_test.cpp) a ratio of 1 left 1.9 % of the standard
  // preset's vertices up to 51 px beyond the rock, 2 left 0.16 % up to
  // 8 px, 3 leaves 0.04 % within 6 px (none at fast).
  double min_texture_to_noise = 3.0;
  bool sgbm_three_way = true;  // MODE_SGBM_3WAY (faster, same memory) vs MODE_SGBM
  // Holes left in the disparity map no longer than this (pixels at dense
  // scale, along a row or a column) whose rims agree within the slope are
  // filled from their rims (matching/disparity_holes.h); 0 = never.
  int disparity_hole_px = 8;
  double disparity_hole_slope_px = 1.0;  // disparity change per pixel across a hole

  // The terraces SGBM leaves on surfaces seen at a grazing angle, smoothed
  // back into their slope (matching/disparity_terraces.h): treads up to
  // this long (pixels at dense scale; 0 = never), risers up to this high.
  int terrace_max_tread_px = 16;
  double terrace_max_riser_px = 6.0;

  // A tunnel's lining seen along the drive (issue 38): the pair padded for
  // SGBM's edge columns and matched again where walls, invert or roof stand
  // at a grazing angle (matching/slanted_passes.h). No preset sets it: the
  // caller does where the visit's 3D image is measured against a tunnel
  // design (a replayed tunnel scene, a project with a tunnel), so a face's
  // reconstruction costs nothing more and is unchanged.
  bool lining_along_the_drive = false;

  // Expected disparity precision after sub-pixel interpolation (pixels at the
  // dense scale), used for the predicted depth precision sigma_Z.
  double disparity_sigma_px = 0.3;

  // Mesh: one lattice vertex every `lattice_step` dense-scale pixels.
  int lattice_step = 1;
};

// The scale (<= 1) at which an image `width` px wide is processed when at
// most `max_width` px are wanted (0 = full size).
double working_scale(int width, int max_width);

ReconstructionPreset preset_fast();
ReconstructionPreset preset_standard();
ReconstructionPreset preset_precise();

// The knobs of `preset` (its name decoded by rockface::parse_preset).
ReconstructionPreset reconstruction_preset(Preset preset);

}  // namespace rockface::photogrammetry

#pragma once
// Does the same rock look equally bright in the two photographs? Under
// daylight or fixed lamps it does, up to one exposure gain. A flash on the
// camera lights each photograph from its own station: the brightness of a
// point goes with cos(incidence) / distance^2 from that station, so the
// ratio of the two views' brightness changes across the face (by facet
// orientation and position), and strong vignetting does the same (the
// same rock sits at other pixels in each view). Semi-global matching's cost
// (cv::StereoSGBM: absolute differences of the grey levels and of their
// horizontal derivatives) is not gain-invariant, so where that ratio
// changes, the cheapest disparity drifts with it: measured on the
// synthetic face (tools/bench/tunnel_lighting_bench.cpp), the fast preset
// tilted its facets by 5-8 deg under a flash (18 deg where the flash
// clipped the near rock) while the relative orientation stayed within
// 0.01 deg. This measures that ratio at the tie points (the gain-only
// model's residual) and, when it varies, matching runs on images divided
// by their local mean brightness, which takes any slowly varying gain out
// of both views; the facets then come out within 0.1-0.3 deg (flash 0.5 to
// 2, same bench). Not always: on images lit alike, normalising costs at
// high ISO (it lifts the noise: 4 deg at ISO 25600 against 0.4).
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace rockface::photogrammetry {

struct ViewShadingOptions {
  // Local brightness: a Gaussian of this sigma (pixels of the images
  // compared) around each tie point; wide enough to average the rock's
  // texture, narrow against a facet.
  double window_sigma_px = 8;
  // Darker than this (grey levels, local mean) in either view: no measure
  // of the ratio (noise and the black level dominate).
  double min_level_grey = 16;
  // Above this (grey levels) in either view: clipped, no measure.
  double max_level_grey = 240;
  // The spread beyond which the views count as lit differently: the
  // gain-only model's residual, half the 10-90 % range of log(ratio).
  // Measured on the synthetic face (tools/bench/tunnel_lighting_bench.cpp,
  // fast preset): daylight, lamps, noise, JPEG, dust and shotcrete 0.004-
  // 0.012; the cos^4 vignetting 0.039 (costs no accuracy); a flash of 0.5 /
  // 1 / 2 0.053 / 0.149 / 0.151 (dips 5-18 deg off unnormalised); twice
  // and three times the vignetting 0.065 / 0.094 and a fully wet facet
  // 0.052-0.075 (normalised, these keep or gain accuracy).
  double max_spread = 0.045;
  // Fewer usable tie points than this: not measured.
  int min_samples = 30;
};

struct ViewShading {
  int samples = 0;     // tie points where both views gave a usable level
  double gain = 1;     // median right / left brightness of the same rock
  double spread = 0;   // gain-only residual: half the 10-90 % range of log(ratio)
  double lowest = 1;   // 10th and 90th percentile of the ratio, divided by the gain
  double highest = 1;  //
  bool measured() const { return samples > 0; }
};

// The ratio at each tie point (pixels of `left` and `right`, one pair per
// tie point), both images 8-bit grey or BGR.
ViewShading compare_view_shading(const cv::Mat& left, const cv::Mat& right,
                                 const std::vector<Eigen::Vector2d>& left_px,
                                 const std::vector<Eigen::Vector2d>& right_px,
                                 const ViewShadingOptions& options = {});

// Whether dense matching should run on brightness-normalised images.
inline bool shading_differs(const ViewShading& s, const ViewShadingOptions& options = {}) {
  return s.measured() && s.spread > options.max_spread;
}

// The image divided by its local mean brightness (Gaussian of sigma_px,
// each channel on its own), scaled so that the mean level is about 100;
// where the local mean is under `dark_grey` it is divided by `dark_grey`
// instead, so that noise in the dark is not lifted to full contrast.
cv::Mat normalise_local_brightness(const cv::Mat& image, double sigma_px, double dark_grey = 16);

// Sigma of normalise_local_brightness before dense matching, pixels of
// the matched (rectified) images: a few SGBM blocks, so that the gain is
// taken out over each block's neighbourhood. Measured on the synthetic
// face under flash 0.5 / 1 / 2 (bench above): sigma 4 left 0.10 / 0.07 /
// 0.34 deg of facet error, 10 left 0.08 / 0.06 / 1.05, 25 left 0.09 /
// 0.17 / 1.07.
constexpr double kShadingNormalisationSigmaPx = 4;

// The warning a reconstruction carries when the views were lit
// differently: what was measured, the likely causes, what was done and
// what to do next time.
std::string shading_warning(const ViewShading& s);

}  // namespace rockface::photogrammetry

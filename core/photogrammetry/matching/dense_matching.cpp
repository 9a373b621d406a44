#include "core/photogrammetry/matching/dense_matching.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/photogrammetry/camera/camera_cv.h"
#include "core/photogrammetry/matching/disparity_holes.h"
#include "core/photogrammetry/matching/disparity_terraces.h"
#include "core/photogrammetry/matching/slanted_passes.h"
#include "core/photogrammetry/matching/texture_mask.h"

namespace rockface::photogrammetry {

namespace {

cv::Mat sgbm_disparity(const cv::Mat& left, const cv::Mat& right, const DisparityRange& range,
                       const ReconstructionPreset& p) {
  const int channels = left.channels();
  const int block = p.sgbm_block_size | 1;
  auto sgbm = cv::StereoSGBM::create(
      range.min_disparity, range.num_disparities, block,
      p.sgbm_p1_per_channel * channels * block * block,
      p.sgbm_p2_per_channel * channels * block * block,
      /*disp12MaxDiff=*/-1, /*preFilterCap=*/63, p.uniqueness_ratio,
      /*speckleWindowSize=*/0, /*speckleRange=*/0,
      p.sgbm_three_way ? cv::StereoSGBM::MODE_SGBM_3WAY : cv::StereoSGBM::MODE_SGBM);
  cv::Mat disparity;  // CV_16S, 1/16 px
  sgbm->compute(left, right, disparity);
  return disparity;
}

// One pass: SGBM both ways, checked, cleaned, its terraces smoothed and its
// small holes filled.
DisparityMap match_pass(const cv::Mat& left, const cv::Mat& right, const DisparityRange& range,
                        const ReconstructionPreset& preset, Progress& progress,
                        const cv::Mat& texture_left) {
  progress.step("dense matching: left", 0.0);
  const cv::Mat disp_left = sgbm_disparity(left, right, range, preset);
  progress.step("dense matching: right", 0.45);
  // The right image's disparity: SGBM on the mirrored pair with the roles
  // swapped has the same disparity range (x'_r - d = x'_l in mirrored columns).
  cv::Mat left_flip, right_flip, disp_right;
  cv::flip(left, left_flip, 1);
  cv::flip(right, right_flip, 1);
  const cv::Mat disp_right_flip = sgbm_disparity(right_flip, left_flip, range, preset);
  left_flip.release();
  right_flip.release();
  cv::flip(disp_right_flip, disp_right, 1);
  progress.step("dense matching: consistency", 0.9);

  const short invalid = static_cast<short>((range.min_disparity - 1) * 16);
  const int max_diff16 = preset.lr_max_difference_px * 16;
  cv::Mat checked = disp_left.clone();
  std::size_t matched = 0, rejected = 0;
  for (int y = 0; y < checked.rows; ++y) {
    short* d = checked.ptr<short>(y);
    const short* dr = disp_right.ptr<short>(y);
    for (int x = 0; x < checked.cols; ++x) {
      if (d[x] <= invalid) continue;
      ++matched;
      const int xr = x - static_cast<int>(std::lround(d[x] / 16.0));
      if (xr < 0 || xr >= checked.cols || dr[xr] <= invalid ||
          std::abs(d[x] - dr[xr]) > max_diff16) {
        d[x] = invalid;
        ++rejected;
      }
    }
  }
  // No texture in the window, nothing measured (texture_mask.h): removed
  // before the speckle filter, which then takes the specks the noise left.
  const cv::Mat textured = textured_pixels(texture_left.empty() ? left : texture_left,
                                           {preset.sgbm_block_size, preset.min_texture_to_noise});
  const std::size_t untextured = remove_untextured(checked, invalid, textured);
  cv::filterSpeckles(checked, invalid, preset.speckle_window,
                     static_cast<int>(std::lround(preset.speckle_range_px * 16)));

  DisparityMap out;
  out.range = range;
  out.disparity.create(checked.size(), CV_32F);
  std::size_t valid = 0;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int y = 0; y < checked.rows; ++y) {
    const short* d = checked.ptr<short>(y);
    float* o = out.disparity.ptr<float>(y);
    for (int x = 0; x < checked.cols; ++x) {
      if (d[x] <= invalid) {
        o[x] = nan;
      } else {
        o[x] = d[x] / 16.0f;
        ++valid;
      }
    }
  }
  out.valid_fraction = static_cast<double>(valid) / static_cast<double>(checked.total());
  TerraceSmoothing terraces;
  terraces.max_tread_px = preset.terrace_max_tread_px;
  terraces.max_riser_px = preset.terrace_max_riser_px;
  const std::size_t smoothed = smooth_disparity_terraces(out.disparity, terraces);
  out.terraced_fraction = static_cast<double>(smoothed) / static_cast<double>(checked.total());
  const std::size_t filled = fill_disparity_holes(
      out.disparity, {preset.disparity_hole_px, preset.disparity_hole_slope_px});
  out.filled_fraction = static_cast<double>(filled) / static_cast<double>(checked.total());
  out.lr_rejected_fraction =
      matched ? static_cast<double>(rejected) / static_cast<double>(matched) : 0;
  out.untextured_fraction =
      matched ? static_cast<double>(untextured) / static_cast<double>(matched) : 0;
  return out;
}

// One pass over the pair padded with black columns, cropped after: SGBM
// leaves the first min + num columns of the left image unmatched (it cannot
// try every disparity there) and the last -min, yet a pixel whose true
// disparity is smaller than its column has its match in the right image
// (a tunnel's near wall at the frame's edge). The black border has no
// texture: nothing is measured on it (texture_mask.h).
DisparityMap match_padded(const cv::Mat& left, const cv::Mat& right, const DisparityRange& range,
                          const ReconstructionPreset& preset, Progress& progress,
                          const cv::Mat& texture_left) {
  const int before = std::max(0, range.min_disparity + range.num_disparities);
  const int after = std::max(0, -range.min_disparity);
  auto pad = [&](const cv::Mat& m) {
    if (m.empty()) return m;
    cv::Mat p;
    cv::copyMakeBorder(m, p, 0, 0, before, after, cv::BORDER_CONSTANT, cv::Scalar::all(0));
    return p;
  };
  DisparityMap out = match_pass(pad(left), pad(right), range, preset, progress, pad(texture_left));
  const double padded = static_cast<double>(out.disparity.total());
  out.disparity = out.disparity(cv::Rect(before, 0, left.cols, left.rows)).clone();
  // Of the image's pixels: what was measured lies inside it.
  const double ratio = padded / static_cast<double>(out.disparity.total());
  out.valid_fraction *= ratio;
  out.filled_fraction *= ratio;
  out.terraced_fraction *= ratio;
  return out;
}

}  // namespace

DisparityMap match_rectified(const cv::Mat& left, const cv::Mat& right, const DisparityRange& range,
                             const ReconstructionPreset& preset, Progress& progress,
                             const cv::Mat& texture_left) {
  if (left.size() != right.size() || left.type() != right.type())
    throw InputError("rectified pair", "left and right differ in size or type");
  if (range.num_disparities <= 0 || range.num_disparities % 16 != 0)
    throw InputError("disparity range",
                     "the number of disparities must be a positive multiple of 16");
  if (!preset.lining_along_the_drive)
    return match_pass(left, right, range, preset, progress, texture_left);
  // A tunnel's lining seen along the drive (issue 38; only where the 3D
  // image is measured against a tunnel design, so a face costs nothing
  // more): the pair padded for SGBM's edge columns, the near walls, and
  // slanted passes for the walls, invert and roof seen at a grazing angle
  // (slanted_passes.h), which fill the first pass's holes and move its
  // terraces onto their slope (3 px at most). The fractions stay the first
  // pass's: the accuracy prediction's input.
  DisparityMap out = match_padded(left, right, range, preset, progress, texture_left);
  NoProgress quiet;
  SlantedPassOptions slanted;
  slanted.max_disparities = preset.max_disparities;
  const SlantedResult s = match_slanted(
      right, out.disparity, slanted, [&](const cv::Mat& warped, const SlantedRange& r) {
        progress.step("dense matching: slanted surfaces", 0.95);
        return match_padded(left, warped, {r.min_disparity, r.num_disparities}, preset, quiet,
                            texture_left)
            .disparity;
      });
  out.disparity = s.disparity;
  progress.step("dense matching", 1.0);
  return out;
}

Rectification rectify(const CameraIntrinsics& left, const CameraIntrinsics& right,
                      const RelativeOrientation& ro, double scale) {
  Rectification r;
  r.scale = scale;
  const CameraIntrinsics l = scaled(left, scale), rt = scaled(right, scale);
  r.size = cv::Size(l.width, l.height);
  cv::Matx33d R;
  cv::Vec3d T;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) R(i, j) = ro.R(i, j);
    T[i] = ro.t(i);
  }
  cv::Mat R1, R2, P1, P2, Q;
  // alpha = 0: the rectified images show only valid pixels, so SGBM never
  // matches the black border of the warp.
  cv::stereoRectify(camera_matrix(l), distortion_vector(l), camera_matrix(rt),
                    distortion_vector(rt), r.size, R, T, R1, R2, P1, P2, Q, 0, 0.0, r.size);
  R1.copyTo(r.R1);
  R2.copyTo(r.R2);
  P1.copyTo(r.P1);
  P2.copyTo(r.P2);
  Q.copyTo(r.Q);
  if (std::abs(r.P2(1, 3)) > std::abs(r.P2(0, 3)))
    throw InputError("left/right images",
                     "the base between the two stations is mostly vertical; take the second "
                     "photograph beside the first, not above or below it");
  cv::initUndistortRectifyMap(camera_matrix(l), distortion_vector(l), R1, P1, r.size, CV_32FC1,
                              r.map1x, r.map1y);
  cv::initUndistortRectifyMap(camera_matrix(rt), distortion_vector(rt), R2, P2, r.size, CV_32FC1,
                              r.map2x, r.map2y);
  return r;
}

RectifiedTiePoints rectified_tie_points(const RelativeOrientation& ro, const Rectification& rect,
                                        const CameraIntrinsics& left,
                                        const CameraIntrinsics& right) {
  const CameraIntrinsics l = scaled(left, rect.scale), r = scaled(right, rect.scale);
  std::vector<cv::Point2d> pl, pr, ql, qr;
  const double s = rect.scale;
  for (std::size_t i = 0; i < ro.left.size(); ++i) {
    pl.emplace_back((ro.left[i].x() + 0.5) * s - 0.5, (ro.left[i].y() + 0.5) * s - 0.5);
    pr.emplace_back((ro.right[i].x() + 0.5) * s - 0.5, (ro.right[i].y() + 0.5) * s - 0.5);
  }
  RectifiedTiePoints out;
  if (pl.empty()) return out;
  cv::undistortPoints(pl, ql, camera_matrix(l), distortion_vector(l), rect.R1, rect.P1);
  cv::undistortPoints(pr, qr, camera_matrix(r), distortion_vector(r), rect.R2, rect.P2);
  for (std::size_t i = 0; i < ql.size(); ++i) {
    out.left.emplace_back(ql[i].x, ql[i].y);
    out.right.emplace_back(qr[i].x, qr[i].y);
  }
  return out;
}

DisparityRange disparity_range_from_inliers(const RelativeOrientation& ro,
                                            const Rectification& rect, const CameraIntrinsics& left,
                                            const CameraIntrinsics& right,
                                            const ReconstructionPreset& preset) {
  const RectifiedTiePoints q = rectified_tie_points(ro, rect, left, right);
  std::vector<double> d;
  for (std::size_t i = 0; i < q.left.size(); ++i) d.push_back(q.left[i].x() - q.right[i].x());
  if (d.empty())
    throw InputError("left/right images", "no tie points to bound the disparity search");
  std::sort(d.begin(), d.end());
  // 1st and 99th percentile: a stray inlier must not blow up the search.
  const double lo = d[d.size() / 100], hi = d[d.size() - 1 - d.size() / 100];
  const double pad = preset.disparity_margin * (hi - lo) + 8.0;
  int min_d = static_cast<int>(std::floor(lo - pad));
  int num = static_cast<int>(std::ceil(hi + pad)) - min_d;
  num = (num + 15) / 16 * 16;
  if (num > preset.max_disparities) {
    // Keep the window centred on the median tie point.
    const double med = d[d.size() / 2];
    num = preset.max_disparities / 16 * 16;
    min_d = static_cast<int>(std::lround(med)) - num / 2;
  }
  return {min_d, std::max(num, 16)};
}

}  // namespace rockface::photogrammetry

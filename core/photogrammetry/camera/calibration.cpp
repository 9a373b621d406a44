#include "core/photogrammetry/camera/calibration.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <utility>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/error.h"

namespace rockface::photogrammetry {

std::vector<cv::Point3f> CalibrationPattern::board_points() const {
  std::vector<cv::Point3f> points;
  points.reserve(static_cast<size_t>(cols) * rows);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      points.emplace_back(static_cast<float>(c * spacing_m), static_cast<float>(r * spacing_m),
                          0.f);
  return points;
}

namespace {

const char* const kPatternWhere = "--pattern";

int parse_count(std::string_view text, std::string_view what) {
  int value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < 2)
    throw InputError(kPatternWhere, std::string(what) + " \"" + std::string(text) +
                                        "\" is not a whole number of at least 2");
  return value;
}

}  // namespace

CalibrationPattern parse_calibration_pattern(std::string_view spec) {
  const std::string usage =
      "expected chessboard:COLSxROWS:SQUARE_M or circles:COLSxROWS:SPACING_M (e.g. "
      "chessboard:9x6:0.025), got \"" +
      std::string(spec) + "\"";
  const size_t c1 = spec.find(':');
  const size_t c2 = c1 == std::string_view::npos ? c1 : spec.find(':', c1 + 1);
  if (c2 == std::string_view::npos) throw InputError(kPatternWhere, usage);
  CalibrationPattern p;
  const std::string_view kind = spec.substr(0, c1);
  if (kind == "chessboard")
    p.kind = CalibrationPattern::Kind::chessboard;
  else if (kind == "circles")
    p.kind = CalibrationPattern::Kind::circles;
  else
    throw InputError(kPatternWhere, "unknown pattern \"" + std::string(kind) + "\"; " + usage);
  const std::string_view grid = spec.substr(c1 + 1, c2 - c1 - 1);
  const size_t x = grid.find('x');
  if (x == std::string_view::npos) throw InputError(kPatternWhere, usage);
  p.cols = parse_count(grid.substr(0, x), "column count");
  p.rows = parse_count(grid.substr(x + 1), "row count");
  const std::string spacing(spec.substr(c2 + 1));
  try {
    size_t used = 0;
    p.spacing_m = std::stod(spacing, &used);
    if (used != spacing.size()) throw std::invalid_argument("trailing text");
  } catch (const std::exception&) {
    throw InputError(kPatternWhere, "spacing \"" + spacing + "\" is not a number; " + usage);
  }
  if (!(p.spacing_m > 0) || p.spacing_m > 10)
    throw InputError(kPatternWhere,
                     "spacing " + spacing + " m must be positive and in metres (0.025 for 25 mm)");
  return p;
}

std::optional<std::vector<cv::Point2f>> detect_calibration_pattern(
    const cv::Mat& grey, const CalibrationPattern& pattern) {
  std::vector<cv::Point2f> points;
  if (pattern.kind == CalibrationPattern::Kind::chessboard) {
    const int flags = cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE;
    if (!cv::findChessboardCorners(grey, pattern.size(), points, flags)) return std::nullopt;
    // The refinement window must stay inside one square: half the smallest
    // distance between neighbouring corners, at most 11 px.
    double min_step = 1e9;
    for (int r = 0; r < pattern.rows; ++r)
      for (int c = 0; c + 1 < pattern.cols; ++c) {
        const cv::Point2f d = points[r * pattern.cols + c + 1] - points[r * pattern.cols + c];
        min_step = std::min(min_step, static_cast<double>(std::hypot(d.x, d.y)));
      }
    const int half = std::clamp(static_cast<int>(min_step / 2) - 1, 2, 11);
    cv::cornerSubPix(grey, points, cv::Size(half, half), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 1e-3));
  } else {
    if (!cv::findCirclesGrid(grey, pattern.size(), points, cv::CALIB_CB_SYMMETRIC_GRID))
      return std::nullopt;
  }
  return points;
}

int CalibrationResult::views_used() const {
  return static_cast<int>(
      std::count_if(views.begin(), views.end(), [](const auto& v) { return !v.outlier; }));
}

std::vector<std::string> CalibrationResult::outlier_names() const {
  std::vector<std::string> names;
  for (const auto& v : views)
    if (v.outlier) names.push_back(v.name);
  return names;
}

namespace {

struct Solution {
  cv::Mat K, dist;
  std::vector<cv::Mat> rvecs, tvecs;
  double rms = 0;
};

Solution solve(const std::vector<std::vector<cv::Point3f>>& object,
               const std::vector<std::vector<cv::Point2f>>& image, cv::Size size) {
  Solution s;
  s.K = cv::Mat::eye(3, 3, CV_64F);
  s.dist = cv::Mat::zeros(5, 1, CV_64F);
  s.rms = cv::calibrateCamera(
      object, image, size, s.K, s.dist, s.rvecs, s.tvecs, 0,
      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 100, 1e-12));
  return s;
}

double view_rms(const std::vector<cv::Point3f>& object, const std::vector<cv::Point2f>& image,
                const cv::Mat& rvec, const cv::Mat& tvec, const Solution& s) {
  std::vector<cv::Point2f> projected;
  cv::projectPoints(object, rvec, tvec, s.K, s.dist, projected);
  double sum = 0;
  for (size_t i = 0; i < image.size(); ++i) {
    const cv::Point2f d = projected[i] - image[i];
    sum += d.dot(d);
  }
  return std::sqrt(sum / static_cast<double>(image.size()));
}

CameraPose board_pose(const cv::Mat& rvec, const cv::Mat& tvec) {
  cv::Mat Rcv;
  cv::Rodrigues(rvec, Rcv);
  CameraPose pose;
  cv::cv2eigen(Rcv, pose.R);
  Eigen::Vector3d t;
  cv::cv2eigen(tvec, t);
  pose.centre = -pose.R.transpose() * t;
  return pose;
}

}  // namespace

CalibrationResult calibrate_camera(const std::vector<CalibrationView>& views,
                                   const CalibrationPattern& pattern, cv::Size size,
                                   const CalibrationOptions& options) {
  const auto board = pattern.board_points();
  if (static_cast<int>(views.size()) < options.min_views)
    throw InputError("calibration", "only " + std::to_string(views.size()) +
                                        " view(s) with the pattern; at least " +
                                        std::to_string(options.min_views) +
                                        " views from different angles are needed");
  for (const auto& v : views)
    if (v.image_points.size() != board.size())
      throw InputError(v.name, "has " + std::to_string(v.image_points.size()) +
                                   " pattern points, the pattern has " +
                                   std::to_string(board.size()));

  std::vector<std::vector<cv::Point3f>> object(views.size(), board);
  std::vector<std::vector<cv::Point2f>> image;
  for (const auto& v : views) image.push_back(v.image_points);
  Solution first = solve(object, image, size);

  // Per-view errors of the first solution decide the outliers.
  std::vector<double> first_rms(views.size());
  for (size_t i = 0; i < views.size(); ++i)
    first_rms[i] = view_rms(board, image[i], first.rvecs[i], first.tvecs[i], first);
  std::vector<double> sorted = first_rms;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double limit = std::max(options.outlier_factor * median, options.outlier_min_px);
  std::vector<bool> outlier(views.size());
  for (size_t i = 0; i < views.size(); ++i) outlier[i] = first_rms[i] > limit;

  CalibrationResult result;
  Solution final = first;
  std::vector<size_t> kept;
  for (size_t i = 0; i < views.size(); ++i)
    if (!outlier[i]) kept.push_back(i);
  if (static_cast<int>(kept.size()) < options.min_views)
    throw InputError("calibration",
                     std::to_string(views.size() - kept.size()) + " of " +
                         std::to_string(views.size()) + " views reproject badly (more than " +
                         std::to_string(limit) + " px); fewer than " +
                         std::to_string(options.min_views) +
                         " good views remain: retake sharp views of a flat, still board");
  if (kept.size() != views.size()) {
    std::vector<std::vector<cv::Point3f>> obj_kept(kept.size(), board);
    std::vector<std::vector<cv::Point2f>> img_kept;
    for (size_t i : kept) img_kept.push_back(image[i]);
    Solution second = solve(obj_kept, img_kept, size);
    // Outlier views keep their own pose, solved against the final intrinsics.
    final.K = second.K;
    final.dist = second.dist;
    final.rms = second.rms;
    for (size_t k = 0; k < kept.size(); ++k) {
      final.rvecs[kept[k]] = second.rvecs[k];
      final.tvecs[kept[k]] = second.tvecs[k];
    }
    for (size_t i = 0; i < views.size(); ++i)
      if (outlier[i])
        cv::solvePnP(board, image[i], final.K, final.dist, final.rvecs[i], final.tvecs[i]);
  }

  CameraIntrinsics& in = result.intrinsics;
  in.width = size.width;
  in.height = size.height;
  in.fx = final.K.at<double>(0, 0);
  in.fy = final.K.at<double>(1, 1);
  in.cx = final.K.at<double>(0, 2);
  in.cy = final.K.at<double>(1, 2);
  for (int k = 0; k < 5; ++k) in.distortion[k] = final.dist.at<double>(k);
  in.rms_px = final.rms;
  result.rms_px = final.rms;
  for (size_t i = 0; i < views.size(); ++i) {
    CalibrationViewResult v;
    v.name = views[i].name;
    v.outlier = outlier[i];
    v.rms_px = view_rms(board, image[i], final.rvecs[i], final.tvecs[i], final);
    v.board_pose = board_pose(final.rvecs[i], final.tvecs[i]);
    result.views.push_back(std::move(v));
  }
  return result;
}

CalibrationFromImages calibrate_from_images(const std::vector<std::string>& paths,
                                            const CalibrationPattern& pattern,
                                            const CalibrationOptions& options) {
  CalibrationFromImages out;
  std::vector<CalibrationView> views;
  cv::Size size;
  std::string size_from;
  for (const auto& path : paths) {
    if (!std::filesystem::is_regular_file(path)) throw InputError(path, "no such image file");
    const cv::Mat grey = cv::imread(path, cv::IMREAD_GRAYSCALE);
    if (grey.empty())
      throw InputError(path, "cannot be read as an image (corrupt or not a JPEG/PNG/TIFF)");
    if (size_from.empty()) {
      size = grey.size();
      size_from = path;
    } else if (grey.size() != size) {
      throw InputError(path, "is " + std::to_string(grey.cols) + "x" + std::to_string(grey.rows) +
                                 " but " + size_from + " is " + std::to_string(size.width) + "x" +
                                 std::to_string(size.height) +
                                 ": all views must come from one camera setting");
    }
    CalibrationImageReport report{path, false};
    if (auto points = detect_calibration_pattern(grey, pattern)) {
      report.pattern_found = true;
      views.push_back({std::filesystem::path(path).filename().string(), std::move(*points)});
    }
    out.images.push_back(report);
  }
  if (static_cast<int>(views.size()) < options.min_views) {
    std::string missing;
    for (const auto& r : out.images)
      if (!r.pattern_found) missing += (missing.empty() ? "" : ", ") + r.path;
    throw InputError("calibration",
                     "the pattern " + std::to_string(pattern.cols) + "x" +
                         std::to_string(pattern.rows) + " was found in " +
                         std::to_string(views.size()) + " of " + std::to_string(paths.size()) +
                         " image(s); at least " + std::to_string(options.min_views) +
                         " are needed" +
                         (missing.empty() ? std::string() : " (not found in: " + missing + ")"));
  }
  out.result = calibrate_camera(views, pattern, size, options);
  out.views = std::move(views);
  out.size = size;
  return out;
}

}  // namespace rockface::photogrammetry

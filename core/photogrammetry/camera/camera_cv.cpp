#include "core/photogrammetry/camera/camera_cv.h"

#include <opencv2/calib3d.hpp>

#include "core/common/error.h"

namespace rockface::photogrammetry {

cv::Matx33d camera_matrix(const CameraIntrinsics& c) {
  return cv::Matx33d(c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
}

cv::Mat distortion_vector(const CameraIntrinsics& c) {
  cv::Mat d(1, 5, CV_64F);
  for (int i = 0; i < 5; ++i) d.at<double>(0, i) = c.distortion[i];
  return d;
}

std::vector<Eigen::Vector2d> undistort_to_normalised(const std::vector<Eigen::Vector2d>& pixels,
                                                     const CameraIntrinsics& camera) {
  std::vector<Eigen::Vector2d> out(pixels.size());
  if (pixels.empty()) return out;
  std::vector<cv::Point2d> src(pixels.size()), dst;
  for (std::size_t i = 0; i < pixels.size(); ++i) src[i] = {pixels[i].x(), pixels[i].y()};
  // More iterations than OpenCV's default 5: strong wide-angle distortion
  // needs them to converge to well below a hundredth of a pixel.
  cv::undistortPoints(src, dst, camera_matrix(camera), distortion_vector(camera), cv::noArray(),
                      cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 40, 1e-12));
  for (std::size_t i = 0; i < dst.size(); ++i) out[i] = {dst[i].x, dst[i].y};
  return out;
}

std::vector<Eigen::Vector2d> project(const std::vector<Eigen::Vector3d>& points_camera,
                                     const CameraIntrinsics& camera) {
  std::vector<Eigen::Vector2d> out(points_camera.size());
  if (points_camera.empty()) return out;
  std::vector<cv::Point3d> src(points_camera.size());
  for (std::size_t i = 0; i < src.size(); ++i)
    src[i] = {points_camera[i].x(), points_camera[i].y(), points_camera[i].z()};
  std::vector<cv::Point2d> dst;
  cv::projectPoints(src, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), camera_matrix(camera),
                    distortion_vector(camera), dst);
  for (std::size_t i = 0; i < dst.size(); ++i) out[i] = {dst[i].x, dst[i].y};
  return out;
}

Eigen::Vector2d pixel_of_normalised(const Eigen::Vector2d& normalised,
                                    const CameraIntrinsics& camera) {
  return project({Eigen::Vector3d(normalised.x(), normalised.y(), 1.0)}, camera)[0];
}

CameraIntrinsics scaled(const CameraIntrinsics& camera, double s) {
  CameraIntrinsics c = camera;
  c.width = static_cast<int>(std::lround(camera.width * s));
  c.height = static_cast<int>(std::lround(camera.height * s));
  c.fx = camera.fx * s;
  c.fy = camera.fy * s;
  c.cx = (camera.cx + 0.5) * s - 0.5;
  c.cy = (camera.cy + 0.5) * s - 0.5;
  return c;
}

void check_camera_fits_image(const CameraIntrinsics& camera, const cv::Mat& image,
                             const std::string& where) {
  if (image.empty()) throw InputError(where, "the image is empty or could not be read");
  if (camera.fx <= 0 || camera.fy <= 0)
    throw InputError(where, "the camera has no focal length (fx, fy must be > 0)");
  if (camera.width > 0 && camera.height > 0 &&
      (camera.width != image.cols || camera.height != image.rows))
    throw InputError(
        where, "the image is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                   " px but the camera was calibrated at " + std::to_string(camera.width) + "x" +
                   std::to_string(camera.height) + " px");
}

}  // namespace rockface::photogrammetry

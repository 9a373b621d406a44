#pragma once
// The camera model in OpenCV's terms: camera matrix, distortion vector,
// undistortion of pixel positions and projection of points. The one place
// where CameraIntrinsics meets OpenCV.
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/photogrammetry/camera/camera_model.h"

namespace rockface::photogrammetry {

cv::Matx33d camera_matrix(const CameraIntrinsics& camera);
cv::Mat distortion_vector(const CameraIntrinsics& camera);  // 1x5 double

// Pixel positions (distorted) to normalised image coordinates (x/z, y/z).
std::vector<Eigen::Vector2d> undistort_to_normalised(const std::vector<Eigen::Vector2d>& pixels,
                                                     const CameraIntrinsics& camera);

// Projects points given in the camera frame to (distorted) pixels.
std::vector<Eigen::Vector2d> project(const std::vector<Eigen::Vector3d>& points_camera,
                                     const CameraIntrinsics& camera);
// The (distorted) pixel of one undistorted, normalised image point.
Eigen::Vector2d pixel_of_normalised(const Eigen::Vector2d& normalised,
                                    const CameraIntrinsics& camera);

// The same camera for an image resized by `scale` (pixel centres follow
// OpenCV's resize convention, (x + 0.5) * s - 0.5).
CameraIntrinsics scaled(const CameraIntrinsics& camera, double scale);

// Throws InputError(where, ...) when the calibration does not fit the image.
void check_camera_fits_image(const CameraIntrinsics& camera, const cv::Mat& image,
                             const std::string& where);

}  // namespace rockface::photogrammetry

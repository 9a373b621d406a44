#pragma once
// Why a pick found no surface of the 3D image, read from the photograph
// around it (issue 39): a geologist told only "no surface under this pick"
// on a face too dark to match does not know to light it. The photograph
// shows what dense matching saw there: too dark, burnt out, or without
// texture; otherwise the two photographs did not match that spot.
#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace rockface::measure {

// "that part of the left photograph is too dark to match (mean 9 of 255
// around the pick): ...". An empty photograph gives the general cause.
std::string no_surface_cause(const cv::Mat& photo, const std::string& photo_name,
                             const Eigen::Vector2d& pixel);

}  // namespace rockface::measure

#pragma once
// The pictures of the field report, drawn with OpenCV: the face photograph
// with the traces and the blocks' outlines on it, and the stereonet
// (core/measure's picture of the joints and their sets).
#include <optional>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "storage/field_report/field_report.h"

namespace rockface::storage {

// Pixel of a project point (datum-relative) in the report's photograph:
// through the first model's registration back to the left camera's frame and
// its calibration. Nothing when the point is behind the camera.
std::optional<Eigen::Vector2d> photograph_pixel(const FieldReport& report,
                                                const Eigen::Vector3d& point);

// Block outline colours (BGR): removable red, marginal orange, keyed green,
// infinite grey.
cv::Scalar block_colour(const analysis::ReportBlock& block);
inline const cv::Scalar kTraceColour{0, 230, 255};  // yellow

// BGR; empty when the visit has no photograph.
cv::Mat face_picture(const FieldReport& report);
// BGR, size_px square; empty when there are no joints.
cv::Mat stereonet_picture(const FieldReport& report, int size_px = 900);

}  // namespace rockface::storage

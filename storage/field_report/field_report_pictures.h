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
// The stereonet's friction circle: the lowest friction angle of the joints
// (degrees; the first to slide), none when no joint has one.
std::optional<double> stereonet_friction_deg(const FieldReport& report);
// The face plane the stereonet checks sliding on: the largest of those with
// a known dip direction that is steeper than the friction angle (no plane
// slides out of a face flatter than that: a floor or a shallow roof), or none.
const ReportedFacePlane* stereonet_face(const FieldReport& report);

// BGR, size_px square; empty when there are no joints. The poles and the
// great circles of the joints, each set's mean pole, its 95 % confidence
// cone and the cone of 95 % of its poles; the friction circle, and the
// faces' great circles with the daylight envelope and the sliding zone of
// the largest (Markland's test) where the visit has a face plane.
cv::Mat stereonet_picture(const FieldReport& report, int size_px = 900);

}  // namespace rockface::storage

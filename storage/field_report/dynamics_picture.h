#pragma once
// The picture of a block's motion after failure, as the seed's cavern
// example shows it: the block's outline at regular times, with the floor
// and time labels, in a side view (the vertical plane of its horizontal
// travel) or, when it mostly moves level, a plan view. Drawn with OpenCV;
// written beside the analysis report (`rockface analyse`) and shown in the
// field report.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/analysis/report.h"

namespace rockface::storage {

// vertices: the block's corners at rest (absolute, as in the report).
// BGR; empty when the motion has no samples.
cv::Mat dynamics_picture(const std::string& block_id, const std::vector<Eigen::Vector3d>& vertices,
                         const analysis::ReportDynamics& d, int width = 900, int height = 600);

// The block's corners (absolute) at one sample of its path.
std::vector<Eigen::Vector3d> posed_vertices(const std::vector<Eigen::Vector3d>& vertices,
                                            const analysis::ReportDynamics& d,
                                            const analysis::ReportMotionSample& s);

}  // namespace rockface::storage

#pragma once
// The wedges' pictures, drawn with OpenCV for `rockface wedges --png`, the
// field report and the tablet:
// - the section: the excavation's outline looking along the drive, each
//   perimeter wedge seen along the axis (its apex and its face on the
//   outline) filled and named, face wedges as their triangle on the face
//   (dashed), a metre scale;
// - a perspective of the largest wedges: each wedge's faces (joint faces
//   coloured by set, the excavation face grey) with the outline of the
//   section through it, seen from inside the tunnel behind and below.
#include <opencv2/core.hpp>

#include "core/tunnel/wedge_analysis.h"

namespace rockface::storage {

// BGR, width_px wide and as high as the section needs.
cv::Mat wedge_section_picture(const tunnel::WedgeAnalysis& analysis, int width_px = 800);
// BGR: up to `count` of the largest wedges side by side.
cv::Mat wedge_perspective_picture(const tunnel::WedgeAnalysis& analysis, int count = 3,
                                  int width_px = 900);
// Both, the section above the perspective.
cv::Mat wedges_picture(const tunnel::WedgeAnalysis& analysis, int width_px = 900);

}  // namespace rockface::storage

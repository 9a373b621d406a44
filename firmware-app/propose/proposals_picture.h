#pragma once
// The picture of the proposals: the left photograph with each facet
// filled in its set's colour (grey: in no set), outlined and labelled, and
// a legend of the sets (dip / dip direction, Fisher K, spacing, facets).
#include <opencv2/core.hpp>

#include "firmware-app/propose/propose_workflow.h"

namespace rockface::app {

// BGR, at most `max_width` px wide. Without a stored photograph the facets
// are drawn on grey at the photograph's size.
cv::Mat proposals_picture(const ProposeResult& result, int max_width = 2000);

}  // namespace rockface::app

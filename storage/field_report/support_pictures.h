#pragma once
// The Q-system support chart with the visit's point on it (issue 44),
// drawn with cairo for the field report's "Support of this round" and
// `rockface support --png`: Q (0.001-1000) across, the equivalent dimension
// De (1-100) up, both logarithmic; the category boundaries of
// core/rockmass/q_support_chart.h with the categories numbered in their
// regions; the visit's point (and a ring when it is marginal) with its
// category.
#include <optional>

#include <opencv2/core.hpp>

#include "core/rockmass/q_support_chart.h"

namespace rockface::storage {

// BGR, width_px wide (two thirds as high). point: none draws the chart alone.
cv::Mat q_chart_picture(const std::optional<rockmass::QChartPoint>& point, int width_px = 800);

}  // namespace rockface::storage

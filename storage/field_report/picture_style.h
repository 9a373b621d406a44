#pragma once
// The field report's pictures share one ink, one paper and one font, and
// write their labels the same way (the tunnel and wedge pictures each had
// their own copy of these).
#include <opencv2/imgproc.hpp>
#include <string>

namespace rockface::storage {

inline const cv::Scalar kInk{30, 30, 30};
inline const cv::Scalar kPaper{255, 255, 255};
inline constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

// A label at `at` (its baseline's left end), anti-aliased.
inline void draw_label(cv::Mat& img, const std::string& s, cv::Point at, double scale = 0.5,
                       const cv::Scalar& colour = kInk, int thickness = 1) {
  cv::putText(img, s, at, kFont, scale, colour, thickness, cv::LINE_AA);
}

}  // namespace rockface::storage

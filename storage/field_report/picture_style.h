#pragma once
// The field report's pictures share one ink, one paper and one font, and
// write their labels the same way (the tunnel and wedge pictures each had
// their own copy of these).
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace rockface::storage {

inline const cv::Scalar kInk{30, 30, 30};
inline const cv::Scalar kPaper{255, 255, 255};
inline constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

// A label at `at` (its baseline's left end), anti-aliased.
inline void draw_label(cv::Mat& img, const std::string& s, cv::Point at, double scale = 0.5,
                       const cv::Scalar& colour = kInk, int thickness = 1) {
  cv::putText(img, s, at, kFont, scale, colour, thickness, cv::LINE_AA);
}

// `s` broken at spaces into lines no wider than `max_width_px` at `scale`
// (a word wider than that stands alone on its line): a message on a picture
// must not run past its right edge (issue 38).
inline std::vector<std::string> wrap_label(const std::string& s, int max_width_px,
                                           double scale = 0.5, int thickness = 1) {
  std::vector<std::string> lines;
  std::string line, word;
  const auto width = [&](const std::string& t) {
    int base = 0;
    return cv::getTextSize(t, kFont, scale, thickness, &base).width;
  };
  std::istringstream words(s);
  while (words >> word) {
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && width(longer) > max_width_px) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace rockface::storage

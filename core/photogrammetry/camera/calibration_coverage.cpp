#include "core/photogrammetry/camera/calibration_coverage.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/common/number_format.h"

namespace rockface::photogrammetry {

namespace {

constexpr int kGrid = 3;
const std::array<std::string, kGrid* kGrid> kCellNames = {"top left",    "top",    "top right",
                                                          "left",        "centre", "right",
                                                          "bottom left", "bottom", "bottom right"};

}  // namespace

std::string CalibrationCoverage::warning() const {
  std::string w = "the views' pattern reaches " + format_fixed(100 * radius_fraction, 0, " %") +
                  " of the way from the image centre to its corners";
  if (!unseen_cells.empty()) {
    w += " and never shows in the image's ";
    for (std::size_t i = 0; i < unseen_cells.size(); ++i)
      w += (i == 0 ? "" : i + 1 == unseen_cells.size() ? " and " : ", ") + unseen_cells[i];
  }
  w += ": the lens distortion there is extrapolated, not measured; add views with the pattern "
       "near the image's edges and corners";
  return w;
}

CalibrationCoverage calibration_coverage(const std::vector<CalibrationView>& views,
                                         const CalibrationResult& result, cv::Size size) {
  CalibrationCoverage c;
  const cv::Point2d centre(size.width / 2.0, size.height / 2.0);
  const double half_diagonal = std::hypot(centre.x, centre.y);
  std::array<bool, kGrid * kGrid> seen{};
  for (std::size_t v = 0; v < views.size(); ++v) {
    if (v < result.views.size() && result.views[v].outlier) continue;
    for (const cv::Point2f& p : views[v].image_points) {
      c.radius_fraction =
          std::max(c.radius_fraction, std::hypot(p.x - centre.x, p.y - centre.y) / half_diagonal);
      const int col = std::clamp(static_cast<int>(p.x * kGrid / size.width), 0, kGrid - 1);
      const int row = std::clamp(static_cast<int>(p.y * kGrid / size.height), 0, kGrid - 1);
      seen[static_cast<std::size_t>(row * kGrid + col)] = true;
    }
  }
  for (std::size_t i = 0; i < seen.size(); ++i) {
    if (seen[i])
      ++c.cells_seen;
    else
      c.unseen_cells.push_back(kCellNames[i]);
  }
  return c;
}

}  // namespace rockface::photogrammetry

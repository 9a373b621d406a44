#include "storage/exchange/intensity_grey.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/error.h"

namespace rockface::storage {

void grey_from_intensity(ImportedSurface& s, const std::string& source) {
  std::vector<float> intensities = std::move(s.intensities);
  s.intensities = {};
  if (intensities.empty() || !s.mesh.colours.empty()) return;
  if (intensities.size() != s.mesh.vertices.size())
    throw InputError(source, std::to_string(intensities.size()) + " intensities for " +
                                 std::to_string(s.mesh.vertices.size()) + " points");
  double lo = intensities.front(), hi = lo;
  for (std::size_t k = 0; k < intensities.size(); ++k) {
    if (!std::isfinite(intensities[k]))
      throw InputError(source, "point " + std::to_string(k) +
                                   ": its intensity is not a finite "
                                   "number");
    lo = std::min(lo, static_cast<double>(intensities[k]));
    hi = std::max(hi, static_cast<double>(intensities[k]));
  }
  const double span = hi - lo;
  s.mesh.colours.reserve(intensities.size());
  for (const float i : intensities) {
    // One intensity everywhere says nothing: mid grey.
    const double grey = span > 0 ? 255.0 * (i - lo) / span : 128.0;
    const auto g = static_cast<std::uint8_t>(std::clamp(std::lround(grey), 0L, 255L));
    s.mesh.colours.push_back({g, g, g});
  }
  s.intensity_as_grey = std::array<double, 2>{lo, hi};
}

}  // namespace rockface::storage

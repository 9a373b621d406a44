#pragma once
// How the report JSON rounds its numbers (report_json.cpp,
// report_dynamics_json.cpp). An unknown (NaN, infinity) is kept as it is:
// nlohmann::json writes it as null, never as a number.
#include <algorithm>
#include <cmath>

namespace rockface::storage {

// 9 significant digits: every digit a field measurement could justify,
// without the binary noise of the computation.
inline double tidy_relative(double v) {
  if (!std::isfinite(v) || v == 0) return v;
  const double scale = std::pow(10.0, 9 - std::ceil(std::log10(std::abs(v))));
  return std::round(v * scale) / scale;
}

// An absolute coordinate in metres (a vertex, a centroid, a point of the
// motion): 9 significant digits, but never coarser than 1e-5 m, so that
// survey coordinates (E/N up to 1e7 m) keep their 0.1 mm (issue 40).
// Within 1e4 m of zero this is tidy_relative.
inline double tidy_coordinate(double v) {
  if (!std::isfinite(v) || v == 0) return v;
  const int decimals = std::max(9 - static_cast<int>(std::ceil(std::log10(std::abs(v)))), 5);
  const double scale = std::pow(10.0, decimals);
  return std::round(v * scale) / scale;
}

}  // namespace rockface::storage

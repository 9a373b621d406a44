#include "core/photogrammetry/targets/reference_line.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/common/error.h"

namespace rockface::photogrammetry {

std::array<Eigen::Vector2d, 2> parse_reference_line(const std::string& text,
                                                    const std::string& where) {
  constexpr double kMinLengthPx = 10;  // shorter: its bearing in the image is too uncertain
  std::stringstream ss(text);
  std::string field;
  std::vector<double> v;
  while (std::getline(ss, field, ',')) {
    try {
      std::size_t used = 0;
      v.push_back(std::stod(field, &used));
      if (used != field.size() || !std::isfinite(v.back())) throw std::invalid_argument(field);
    } catch (const std::exception&) {
      throw InputError(where, "'" + field + "' is not a number (expected U1,V1,U2,V2)");
    }
  }
  if (v.size() != 4)
    throw InputError(where, "expected four numbers U1,V1,U2,V2 (pixels of the left image)");
  const std::array<Eigen::Vector2d, 2> line{Eigen::Vector2d(v[0], v[1]),
                                            Eigen::Vector2d(v[2], v[3])};
  if ((line[1] - line[0]).norm() < kMinLengthPx)
    throw InputError(where, "the two points are less than 10 px apart");
  return line;
}

}  // namespace rockface::photogrammetry

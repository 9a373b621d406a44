#include "storage/exchange/imported_surface.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/common/error.h"

namespace rockface::storage {

void take_datum(ImportedSurface& s) {
  auto& vertices = s.mesh.vertices;
  if (vertices.empty()) return;
  double largest = 0;
  for (const auto& p : vertices) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  if (largest <= kSurveySizedCoordinate) return;
  // Rounded to metres: a datum a surveyor can read and type again.
  const Eigen::Vector3d datum = vertices.front().array().round().matrix();
  for (auto& p : vertices) p -= datum;
  for (auto& p : s.scanner_positions) p -= datum;
  s.datum += datum;
}

void require_finite_point(const Eigen::Vector3d& p, const std::string& source,
                          const std::string& where) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(p[k]))
      throw InputError(source, where + ": " + "xyz"[k] + std::string(" is not a finite number"));
}

std::string read_whole_file(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open the file");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw InputError(file, "cannot read the file");
  return std::move(s).str();
}

}  // namespace rockface::storage

#include "core/tunnel/surface_reach.h"

#include <algorithm>

namespace rockface::tunnel {

std::vector<AlignmentPlace> rock_places(const Alignment& alignment, const SurfaceInput& surface) {
  const std::size_t step = std::max<std::size_t>(1, surface.vertices.size() / 20000);
  std::vector<AlignmentPlace> places;
  for (std::size_t i = 0; i < surface.vertices.size(); i += step)
    if (surface.not_rock_vertex.empty() || !surface.not_rock_vertex[i])
      places.push_back(alignment.place(surface.vertices[i]));
  return places;
}

std::optional<SurfaceReach> surface_reach(const Alignment& alignment,
                                          const std::vector<AlignmentPlace>& places) {
  if (places.empty()) return std::nullopt;
  const double sense = alignment.drive() == Drive::ascending ? 1.0 : -1.0;
  std::vector<double> ahead;
  for (const auto& p : places) ahead.push_back(sense * p.chainage);
  std::sort(ahead.begin(), ahead.end());
  const auto at = [&](double f) {
    return sense * ahead[static_cast<std::size_t>(f * (ahead.size() - 1))];
  };
  return SurfaceReach{at(0.02), at(0.99), at(0.0)};
}

}  // namespace rockface::tunnel

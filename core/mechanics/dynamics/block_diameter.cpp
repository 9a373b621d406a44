#include "core/mechanics/dynamics/block_diameter.h"

#include <algorithm>

namespace rockface::mechanics {

double block_diameter(const blocks::Polyhedron& block) {
  // Every pair: a block has tens of corners, and a pair's distance is the
  // same in every frame (the farthest pair need not lie on any axis).
  const auto& v = block.vertices();
  double farthest = 0;
  for (size_t i = 0; i < v.size(); ++i)
    for (size_t j = i + 1; j < v.size(); ++j) farthest = std::max(farthest, (v[i] - v[j]).norm());
  return farthest;
}

}  // namespace rockface::mechanics

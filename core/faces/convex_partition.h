#pragma once
// A non-convex surface patch (a face with a notch, an L-shaped bench) split
// into convex polygons without new corners: ear clipping, then Hertel and
// Mehlhorn's merge of neighbouring triangles while the union stays convex
// (at most four times the fewest convex pieces).
#include <vector>

#include <Eigen/Core>

namespace rockface::faces {

// `polygon`: a simple polygon, counter-clockwise. Returns the pieces as
// corner indices, each counter-clockwise; a corner whose turn is within
// `straight_sine` of straight counts as convex. Empty if the outline
// crosses itself (no ear can be cut).
std::vector<std::vector<int>> convex_partition(const std::vector<Eigen::Vector2d>& polygon,
                                               double straight_sine);

}  // namespace rockface::faces

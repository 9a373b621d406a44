#pragma once
// A convex block's closed surface from its corners alone: the report keeps a
// block's vertices, not its faces, and a convex block is the convex hull of
// its corners (CGAL's convex_hull_3). Triangles counter-clockwise seen from
// outside, indices into the corners given.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace rockface::app {

// Empty when the corners span no volume (fewer than four, or all in a
// plane). Corners that lie inside the hull or on a face's interior (none for
// a block's corners) are simply not used.
std::optional<std::vector<std::array<int, 3>>> convex_hull_triangles(
    const std::vector<Eigen::Vector3d>& corners);

}  // namespace rockface::app

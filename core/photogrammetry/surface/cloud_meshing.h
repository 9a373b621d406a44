#pragma once
// A point cloud (a laser scan, a drone's dense cloud) made a surface the
// geologist can map on: a 2.5D Delaunay triangulation (CGAL) of the points
// projected on their best plane, the plane of a face or a slope. Holes stay
// holes: a triangle with an edge much longer than the point spacing where
// it lies bridges what the scanner did not see (a shadow behind a block, the
// gap between two scan positions, the outer hull's slivers) and is dropped,
// never kept as rock that was not measured.
//
// The spacing "where it lies" is each point's distance to its nearest
// neighbour (always a Delaunay neighbour, so the triangulation gives it);
// a triangle is kept when its longest edge is at most
// `max_edge_to_spacing` times the largest nearest-neighbour distance of its
// three corners, that taken at most 3 times the middle corner's (a lone
// point amid another surface, e.g. rock seen past a target plate standing
// in front of it, has its nearest neighbour as far as that surface). Points (almost) on top of one
// another in the plane keep one vertex; the others stay in the cloud, in no triangle.
//
// A large cloud is triangulated in overlapping strips (CloudMeshingOptions),
// each triangle kept by the one strip whose core holds its centroid.
//
// A surface that folds over its best plane (a whole round's walls, an
// overhang seen from below) is not a 2.5D surface: the 3D edge test drops the
// triangles it would fold into, so the fold comes out as a hole.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace rockface::photogrammetry {

struct CloudMeshingOptions {
  // 4: on a regular grid the longest Delaunay edge is a diagonal (1.41
  // spacings) and on a scanner's irregular sampling rarely beyond 3
  // nearest-neighbour distances; a gap of 4 spacings is a hole.
  double max_edge_to_spacing = 4.0;
  // Triangulated in strips along the plane's longer axis of this many
  // points each (CGAL's triangulation takes some 160 bytes a point: a strip
  // of a million is 160 MB whatever the cloud's size)...
  std::size_t strip_points = 1'000'000;
  // ...overlapping their neighbours by this many point spacings, so that the
  // triangles near a strip's edge are those of one triangulation of the
  // whole (a kept triangle's edges are a few spacings).
  double strip_overlap_spacings = 20.0;
};

struct CloudMesh {
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from +normal
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // of the best plane (unit)
  double median_spacing = 0;                          // of the nearest-neighbour distances
  std::size_t dropped_triangles = 0;                  // bridging a hole or the hull
  std::size_t unused_points = 0;                      // in no kept triangle
};

struct BestPlane {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, the least spread
  Eigen::Vector3d u = Eigen::Vector3d::UnitX();       // unit, the most spread
};

// The plane of least squares through the points (a sample of a large
// cloud). InputError when they lie on a line.
BestPlane best_plane(std::span<const Eigen::Vector3d> points);

// Throws InputError when the points do not span a surface (fewer than three,
// or all on one line). A span: part of a cloud (a round's face, after its
// walls) is meshed where it lies, without a copy (issue 43's peak).
CloudMesh mesh_point_cloud(std::span<const Eigen::Vector3d> points,
                           const CloudMeshingOptions& options = {});
inline CloudMesh mesh_point_cloud(const std::vector<Eigen::Vector3d>& points,
                                  const CloudMeshingOptions& options = {}) {
  return mesh_point_cloud(std::span<const Eigen::Vector3d>(points), options);
}

// The same over coordinates the caller gives each point on a surface the
// cloud does not fold over (a round's developed view: chainage and arc length
// of the design outline), in metres, so that the strips and the spacing are
// those of the surface. Triangles are counter-clockwise in (u, v); centroid
// and normal are left as they are (no plane).
CloudMesh mesh_point_cloud_on(std::span<const Eigen::Vector3d> points,
                              const std::vector<Eigen::Vector2d>& uv,
                              const CloudMeshingOptions& options = {});

// The same where some points lie twice on the surface (a developed view's
// seam: the outline's start meshed again past its end): uv[k] is point k's
// place for k < points.size(), and uv[points.size() + j] a second place of
// point repeated[j]. The triangles index uv (a second place's index is
// points.size() + j), unused_points counts the points in no triangle at
// either place. No copy of a repeated point is made.
CloudMesh mesh_point_cloud_on(std::span<const Eigen::Vector3d> points,
                              const std::vector<Eigen::Vector2d>& uv,
                              const std::vector<int>& repeated,
                              const CloudMeshingOptions& options = {});

}  // namespace rockface::photogrammetry

#pragma once
// The "3D image": a triangulated surface on the lattice of the rectified left
// image. Every vertex knows its pixel in the original left photograph, so the
// photograph is the texture (texture coordinates) and picking on the image is
// picking on the surface.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace rockface::photogrammetry {

struct SurfaceMesh {
  std::vector<Eigen::Vector3d> vertices;             // model or world frame
  std::vector<std::array<std::uint8_t, 3>> colours;  // RGB, from the left image
  std::vector<Eigen::Vector2f> pixels;               // position in the original left image (px)
  std::vector<Eigen::Vector2f> texcoords;            // (u, v) in [0, 1], v up (OBJ/PLY convention)
  std::vector<std::array<int, 3>> triangles;
  int texture_width = 0, texture_height = 0;  // size of the left image the texcoords refer to

  std::size_t size() const { return vertices.size(); }
  bool empty() const { return vertices.empty(); }

  // Applies x -> scale * R x + t to every vertex.
  void transform(double scale, const Eigen::Matrix3d& R, const Eigen::Vector3d& t);

  // The surface point seen at a pixel of the original left image: the vertex
  // nearest to it within `max_distance_px`, or nothing (no surface there).
  std::optional<Eigen::Vector3d> point_at_pixel(const Eigen::Vector2d& pixel,
                                                double max_distance_px) const;

  // Every vertex's pixel in the left photograph (`texture_width` x
  // `texture_height`) from its texture coordinates, and that size kept:
  // what a stored mesh, which keeps only the texture coordinates, needs to
  // be a lattice again. Nothing when the texture coordinates are not one
  // per vertex or the size is unknown.
  void pixels_from_texcoords(int texture_width, int texture_height);

  // Median length of the lattice edges (the point spacing), model units.
  double median_edge_length() const;
};

}  // namespace rockface::photogrammetry

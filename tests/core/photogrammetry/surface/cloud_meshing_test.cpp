// Meshing an imported point cloud (core/photogrammetry/surface/cloud_meshing.h):
// a scanned face becomes triangles, a hole stays a hole, a line is no surface.
#include "core/photogrammetry/surface/cloud_meshing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <vector>

#include <Eigen/Geometry>

#include "core/common/error.h"

namespace {

using rockface::photogrammetry::mesh_point_cloud;

// A vertical face (normal north) on a jittered 1 cm grid, 2 x 1 m, with a
// round hole of radius `hole` at its centre (a block's shadow).
std::vector<Eigen::Vector3d> face_cloud(double hole, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.003, 0.003);
  std::normal_distribution<double> noise(0, 0.001);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < 200; ++i)
    for (int k = 0; k < 100; ++k) {
      const double x = 0.01 * i + jitter(rng), z = 0.01 * k + jitter(rng);
      if (std::hypot(x - 1.0, z - 0.5) < hole) continue;
      out.emplace_back(500000 + x, 5000000 + noise(rng), 1000 + z);
    }
  return out;
}

TEST(CloudMeshing, AHoleStaysAHole) {
  std::mt19937 rng(43);
  const auto points = face_cloud(0.15, rng);
  const auto mesh = mesh_point_cloud(points);
  // The plane is the face's: its normal is north (or south), within the
  // 1 mm noise over 2 m: 1e-3 of a radian is generous.
  EXPECT_GT(std::abs(mesh.normal.y()), 1 - 1e-3);
  // 1 cm grid jittered by 3 mm: nearest neighbours 0.4 to 1 cm.
  EXPECT_GT(mesh.median_spacing, 0.004);
  EXPECT_LT(mesh.median_spacing, 0.011);
  // No triangle crosses the hole: none has its centroid inside it (a
  // bridge's centroid lies inside the hole's 15 cm).
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d c =
        (points[static_cast<std::size_t>(t[0])] + points[static_cast<std::size_t>(t[1])] +
         points[static_cast<std::size_t>(t[2])]) /
        3;
    EXPECT_GE(std::hypot(c.x() - 500001.0, c.z() - 1000.5), 0.15 - 0.01);
  }
  // The rest is covered: about two triangles a point (Euler), less the
  // hull's and the hole's slivers dropped.
  EXPECT_GT(mesh.triangles.size(), 1.9 * static_cast<double>(points.size()));
  EXPECT_GT(mesh.dropped_triangles, 0u);
  EXPECT_EQ(mesh.unused_points, 0u);
}

TEST(CloudMeshing, TrianglesTurnCounterClockwiseSeenFromTheNormal) {
  std::mt19937 rng(7);
  const auto points = face_cloud(0, rng);
  const auto mesh = mesh_point_cloud(points);
  for (std::size_t i = 0; i < mesh.triangles.size(); i += 97) {
    const auto& t = mesh.triangles[i];
    const Eigen::Vector3d a = points[static_cast<std::size_t>(t[0])],
                          b = points[static_cast<std::size_t>(t[1])],
                          c = points[static_cast<std::size_t>(t[2])];
    EXPECT_GT((b - a).cross(c - a).dot(mesh.normal), 0);
  }
}

// Strips of 1000 points (a large cloud's way, made small) give the
// triangles of one triangulation of the whole: none lost at a seam, none
// twice.
TEST(CloudMeshing, StripsGiveTheTrianglesOfTheWhole) {
  std::mt19937 rng(11);
  const auto points = face_cloud(0.15, rng);
  rockface::photogrammetry::CloudMeshingOptions whole;
  whole.strip_points = points.size();
  rockface::photogrammetry::CloudMeshingOptions strips;
  strips.strip_points = 1000;
  auto canonical = [](std::vector<std::array<int, 3>> t) {
    for (auto& x : t) std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
    std::sort(t.begin(), t.end());
    return t;
  };
  const auto one = canonical(mesh_point_cloud(points, whole).triangles);
  const auto many = canonical(mesh_point_cloud(points, strips).triangles);
  EXPECT_EQ(one.size(), many.size());
  EXPECT_TRUE(one == many);
}

TEST(CloudMeshing, PointsOnALineAreNoSurface) {
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 100; ++i) line.emplace_back(i, 2.0 * i, 0);
  EXPECT_THROW(mesh_point_cloud(line), rockface::InputError);
  EXPECT_THROW(mesh_point_cloud({{0, 0, 0}, {1, 0, 0}}), rockface::InputError);
}

}  // namespace

// A developed view's seam (issue 43's round scans): points meshed at a
// second place of the surface given as repeated points give the triangles
// that copies of them appended to the cloud give (the way before, which
// held a copy of every repeated point), indexed alike; the points after the
// meshed span (a round's face, after its walls) are not touched.
TEST(CloudMeshing, RepeatedPointsMeshAsTheirCopiesWould) {
  std::mt19937 rng(17);
  std::vector<Eigen::Vector3d> points = face_cloud(0.1, rng);
  std::vector<Eigen::Vector2d> uv;
  for (const auto& p : points) uv.emplace_back(p.x() - 500000, p.z() - 1000);
  // The first 20 cm of u again past the end (2 m), as a seam band.
  std::vector<int> repeated;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (uv[k].x() < 0.2) repeated.push_back(static_cast<int>(k));
  std::vector<Eigen::Vector2d> uv_all = uv;
  std::vector<Eigen::Vector3d> copies = points;
  for (int k : repeated) {
    uv_all.emplace_back(uv[static_cast<std::size_t>(k)].x() + 2.0,
                        uv[static_cast<std::size_t>(k)].y());
    copies.push_back(points[static_cast<std::size_t>(k)]);
  }
  rockface::photogrammetry::CloudMeshingOptions strips;
  strips.strip_points = 5000;  // a seam across strips too
  auto canonical = [](std::vector<std::array<int, 3>> t) {
    for (auto& x : t) std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
    std::sort(t.begin(), t.end());
    return t;
  };
  const auto copied = rockface::photogrammetry::mesh_point_cloud_on(copies, uv_all, strips);
  // The cloud with points after the meshed ones (a face), which the span
  // leaves out.
  std::vector<Eigen::Vector3d> with_face = points;
  with_face.emplace_back(0, 0, 0);
  const auto placed = rockface::photogrammetry::mesh_point_cloud_on(
      std::span<const Eigen::Vector3d>(with_face).first(points.size()), uv_all, repeated, strips);
  EXPECT_GT(copied.triangles.size(), 1.9 * static_cast<double>(points.size()));
  EXPECT_TRUE(canonical(copied.triangles) == canonical(placed.triangles));
  EXPECT_EQ(copied.median_spacing, placed.median_spacing);
  EXPECT_EQ(placed.unused_points, 0u);
  std::vector<int> outside = repeated;
  outside.front() = -1;  // no such point
  EXPECT_THROW(rockface::photogrammetry::mesh_point_cloud_on(points, uv_all, outside, strips),
               rockface::InputError);
}

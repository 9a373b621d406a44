// Meshing an imported point cloud (core/photogrammetry/surface/cloud_meshing.h):
// a scanned face becomes triangles, a hole stays a hole, a line is no surface.
#include "core/photogrammetry/surface/cloud_meshing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

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

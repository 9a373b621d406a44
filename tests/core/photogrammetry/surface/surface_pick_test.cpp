// A pick's surface point read from the plane around it (surface_pick.h):
// a lattice of vertices on a known plane, seen by a pinhole camera at the
// origin, with the errors issue 38 met beside the range pole.
#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "core/photogrammetry/surface/surface_pick.h"

namespace rockface::photogrammetry {
namespace {

CameraIntrinsics pinhole() {
  CameraIntrinsics k;
  k.width = 1200;
  k.height = 800;
  k.fx = k.fy = 800;
  k.cx = 599.5;
  k.cy = 399.5;
  return k;
}

// The plane n.x = c (a face 8 m away, turned 20 deg about the vertical):
// where the ray through pixel (u, v) meets it. The truth, computed here
// from the plane's equation, not by the code under test.
Eigen::Vector3d on_plane(const CameraIntrinsics& k, double u, double v) {
  const Eigen::Vector3d n(std::sin(0.35), 0, std::cos(0.35));
  const double c = 8.0 * std::cos(0.35);
  const Eigen::Vector3d ray((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
  return ray * (c / n.dot(ray));
}

// One vertex per pixel within 30 px of (700, 400), each 2 mm rms off the
// plane along its ray (sensor noise), then spoilt as `spoil` says.
SurfaceMesh lattice(const CameraIntrinsics& k, const std::function<double(int, int)>& spoil) {
  SurfaceMesh mesh;
  cv::RNG rng(38);
  for (int v = 370; v <= 430; ++v)
    for (int u = 670; u <= 730; ++u) {
      const Eigen::Vector3d p = on_plane(k, u, v);
      const double depth_error = rng.gaussian(0.002) + spoil(u - 700, v - 400);
      mesh.vertices.push_back(p * (1 + depth_error / p.norm()));
      mesh.pixels.emplace_back(static_cast<float>(u), static_cast<float>(v));
    }
  return mesh;
}

// The vertex at the pick is 59 mm too deep (as the sample heading's
// compass line's end was) and a strip of the range pole, 1.2 m nearer,
// crosses the disc: the plane of the rest gives the pick's point. 2 mm of
// noise over ~1000 inliers leaves well under a millimetre on the plane;
// 2 mm is the bound (the noise of one vertex).
TEST(SurfacePick, AnOutlierAtThePickAndAPoleBesideItDoNotMoveThePoint) {
  const CameraIntrinsics k = pinhole();
  const SurfaceMesh mesh = lattice(k, [](int du, int dv) {
    if (du == 0 && dv == 0) return 0.059;
    if (du >= 10 && du <= 16) return -1.2;  // the pole's own vertices
    return 0.0;
  });
  const Eigen::Vector2d pick(700, 400);
  const auto p = surface_point_at_pick(mesh, pick, k);
  ASSERT_TRUE(p);
  EXPECT_LT((*p - on_plane(k, 700, 400)).norm(), 0.002);
  // The nearest vertex, as the compass line was read before, is the outlier.
  const auto nearest = mesh.point_at_pixel(pick, 2.0);
  ASSERT_TRUE(nearest);
  EXPECT_GT((*nearest - on_plane(k, 700, 400)).norm(), 0.05);
}

TEST(SurfacePick, NothingWhereTheImageHasNoSurface) {
  const CameraIntrinsics k = pinhole();
  const SurfaceMesh mesh = lattice(k, [](int, int) { return 0.0; });
  EXPECT_FALSE(surface_point_at_pick(mesh, {200, 200}, k));
}

}  // namespace
}  // namespace rockface::photogrammetry

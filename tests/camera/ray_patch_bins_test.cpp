#include "camera/ray_patch_bins.h"

#include <random>

#include <gtest/gtest.h>

namespace rockface::camera {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// Does the ray from the camera centre through normalised image point (x, y)
// cross the (convex) triangle? Brute force, in camera coordinates.
bool ray_hits_triangle(const photogrammetry::CameraPose& pose, const std::vector<Vector3d>& tri,
                       double x, double y) {
  const Vector3d d(x, y, 1.0);
  const Vector3d a = pose.to_camera(tri[0]), b = pose.to_camera(tri[1]), c = pose.to_camera(tri[2]);
  const Vector3d n = (b - a).cross(c - a);
  const double denom = n.dot(d);
  if (std::abs(denom) < 1e-15) return false;
  const double t = n.dot(a) / denom;
  if (t <= 0) return false;
  const Vector3d p = t * d;
  return n.dot((b - a).cross(p - a)) >= 0 && n.dot((c - b).cross(p - b)) >= 0 &&
         n.dot((a - c).cross(p - c)) >= 0;
}

TEST(RayPatchBins, EveryHitPatchIsACandidateInPatchOrder) {
  // The camera at the origin looking north (+y): camera x = East, y = down.
  photogrammetry::CameraPose pose;
  pose.R << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-6, 6), ahead(-2, 10);
  std::vector<std::vector<Vector3d>> tris;
  for (int k = 0; k < 400; ++k) {
    // Some triangles reach behind the camera (y < 0): those are kept in
    // every cell; some lie wholly behind and can never be hit.
    const Vector3d c(u(rng), ahead(rng), u(rng));
    tris.push_back({c, c + Vector3d(u(rng), u(rng), u(rng)) * 0.3,
                    c + Vector3d(u(rng), u(rng), u(rng)) * 0.3});
  }
  const RayPatchBins bins(tris, pose, Vector2d(-1, -1), Vector2d(1, 1), 16);
  std::uniform_real_distribution<double> ray(-1, 1);
  int hits = 0;
  for (int r = 0; r < 3000; ++r) {
    const double x = ray(rng), y = ray(rng);
    const std::vector<int>* cand = bins.candidates(x, y);
    ASSERT_NE(cand, nullptr);
    EXPECT_TRUE(std::is_sorted(cand->begin(), cand->end()));
    for (std::size_t k = 0; k < tris.size(); ++k)
      if (ray_hits_triangle(pose, tris[k], x, y)) {
        ++hits;
        EXPECT_TRUE(std::binary_search(cand->begin(), cand->end(), static_cast<int>(k)))
            << "ray (" << x << ", " << y << ") hits patch " << k << " but it is not a candidate";
      }
  }
  EXPECT_GT(hits, 1000);  // the test exercised many hits, not an empty scene
  // Outside the window every patch must be tested.
  EXPECT_EQ(bins.candidates(1.5, 0), nullptr);
}

TEST(RayPatchBins, PatchBehindTheCameraIsNeverACandidate) {
  photogrammetry::CameraPose pose;
  pose.R << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  const std::vector<std::vector<Vector3d>> tris{{{-1, -2, -1}, {1, -2, -1}, {0, -2, 1}}};
  const RayPatchBins bins(tris, pose, Vector2d(-1, -1), Vector2d(1, 1), 8);
  for (double x : {-0.9, 0.0, 0.9})
    for (double y : {-0.9, 0.0, 0.9}) EXPECT_TRUE(bins.candidates(x, y)->empty());
}

}  // namespace
}  // namespace rockface::camera

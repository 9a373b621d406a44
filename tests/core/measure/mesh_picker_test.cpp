// Picking: the BVH answers what a loop over every triangle answers, and the
// pose of the left photograph is recovered from the lattice alone.
#include <random>

#include <gtest/gtest.h>

#include "core/measure/mesh_picker.h"
#include "tests/support/folded_face.h"

namespace rm = rockface::measure;

namespace {

std::optional<double> brute_force(const rockface::photogrammetry::SurfaceMesh& mesh,
                                  const rm::Ray& ray) {
  std::optional<double> best;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]], e1 = mesh.vertices[t[1]] - a,
                          e2 = mesh.vertices[t[2]] - a;
    Eigen::Matrix3d M;
    M << -ray.direction, e1, e2;
    const Eigen::Vector3d s = M.colPivHouseholderQr().solve(ray.origin - a);
    if (s(1) >= 0 && s(2) >= 0 && s(1) + s(2) <= 1 && s(0) > 0 && (!best || s(0) < *best))
      best = s(0);
  }
  return best;
}

}  // namespace

TEST(MeshPicker, AgreesWithALoopOverAllTriangles) {
  const auto face = rockface::test::folded_face(200, 150, 0.01, 2);
  const rm::MeshPicker picker(face.mesh);
  EXPECT_GT(picker.node_count(), face.mesh.triangles.size() / 8);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 200; ++i) {
    rm::Ray ray;
    ray.origin = Eigen::Vector3d(2 * u(rng), 2 * u(rng), 0.5 + u(rng));
    ray.direction = Eigen::Vector3d(0.3 * u(rng), 1.0, 0.3 * u(rng)).normalized();
    const auto expected = brute_force(face.mesh, ray);
    const auto got = picker.pick(ray);
    ASSERT_EQ(expected.has_value(), got.has_value()) << "ray " << i;
    if (!got) continue;
    ++hits;
    // Both solve the same 3x3 system: they agree to rounding.
    EXPECT_NEAR(got->distance, *expected, 1e-9);
    EXPECT_LT((got->point - (ray.origin + *expected * ray.direction)).norm(), 1e-9);
    EXPECT_LT(got->normal.dot(ray.direction), 0);  // turned toward the viewer
  }
  EXPECT_GT(hits, 100);
}

TEST(MeshPicker, PickThroughALatticePixelLandsOnItsVertex) {
  const auto face = rockface::test::folded_face(400, 300, 0.0, 2);
  const rm::MeshPicker picker(face.mesh);
  for (std::size_t i = 0; i < face.mesh.size(); i += 997) {
    const auto hit = picker.pick(face.view, face.mesh.pixels[i].cast<double>(), "pixel");
    ASSERT_TRUE(hit);
    // The vertex lies on its pixel's ray: the hit is the vertex, to the
    // rounding of the float pixel (1e-5 px at 10 m ~ 1e-7 m).
    EXPECT_LT((hit->point - face.mesh.vertices[i]).norm(), 1e-5);
  }
}

TEST(MeshPicker, VerticesNearABall) {
  const auto face = rockface::test::folded_face(200, 150, 0.0, 2);
  const rm::MeshPicker picker(face.mesh);
  const Eigen::Vector3d c = face.mesh.vertices[face.mesh.size() / 2];
  const auto near = picker.vertices_near(c, 0.5);
  std::size_t expected = 0;
  for (const auto& v : face.mesh.vertices) expected += (v - c).norm() <= 0.5;
  EXPECT_EQ(near.size(), expected);
}

TEST(PhotoView, LeftPoseRecoveredFromTheLattice) {
  const auto face = rockface::test::folded_face(400, 300, 0.0, 2);
  const rm::PhotoView v = rm::left_view_from_lattice(face.mesh, face.view.camera);
  // Exact 2D-3D pairs (float pixels): the pose is recovered to ~1e-6.
  EXPECT_LT((v.pose.centre - face.view.pose.centre).norm(), 1e-3);
  EXPECT_LT((v.pose.R - face.view.pose.R).norm(), 1e-4);
}

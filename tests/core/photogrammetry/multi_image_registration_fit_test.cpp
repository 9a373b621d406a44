// The pieces of one image's registration in the merge
// (multi_image_registration_fit.h): the overlap index finds exactly the
// nearest point within its radius (brute force says which), the robust
// similarity recovers a known transform through outliers and stops sampling
// as soon as the inlier ratio allows, and a sample moved by a rigid motion
// is the sample taken through that motion.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "core/photogrammetry/estimators/multi_image_registration_fit.h"

namespace {

namespace rp = rockface::photogrammetry;

std::vector<Eigen::Vector3d> random_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> p;
  for (std::size_t i = 0; i < n; ++i) p.emplace_back(3 * u(rng), 2 * u(rng), 0.2 * u(rng));
  return p;
}

TEST(MultiImageFit, TheOverlapIndexFindsExactlyTheNearestPointWithinItsRadius) {
  const auto points = random_points(5000, 3);
  const double radius = 0.05;
  const rp::NearestWithin near(points, radius);
  const auto queries = random_points(2000, 4);
  int found = 0;
  for (const auto& q : queries) {
    int best = -1;
    double best_d = radius;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double d = (points[i] - q).norm();
      if (d < best_d) {
        best_d = d;
        best = static_cast<int>(i);
      }
    }
    const auto [index, distance] = near.nearest(q);
    ASSERT_EQ(index, best);
    if (best >= 0) {
      ++found;
      EXPECT_DOUBLE_EQ(distance, best_d);
    }
  }
  // The radius is a few point spacings: most queries have a point, some not,
  // so both answers are exercised.
  EXPECT_GT(found, 200);
  EXPECT_LT(found, 2000);
  // A query far outside the points' box finds none.
  EXPECT_EQ(near.nearest(Eigen::Vector3d(100, 100, 100)).first, -1);
}

TEST(MultiImageFit, TheSimilarityIsRecoveredThroughOutliersWithFewSamples) {
  rp::Similarity truth;
  truth.scale = 2.5;
  truth.R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 1, 0.3).normalized()).toRotationMatrix();
  truth.t = Eigen::Vector3d(1, -2, 0.5);
  const auto slave = random_points(1000, 7);
  std::mt19937_64 rng(8);
  std::normal_distribution<double> noise(0.0, 0.002);
  std::uniform_real_distribution<double> wild(-5.0, 5.0);
  rp::TiePoints tie;
  for (std::size_t i = 0; i < slave.size(); ++i) {
    tie.slave.push_back(slave[i]);
    // A fifth are wrong matches: anywhere on the face.
    if (i % 5 == 0)
      tie.reference.emplace_back(wild(rng), wild(rng), wild(rng));
    else
      tie.reference.push_back(truth.apply(slave[i]) +
                              Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  }
  const double inlier_m = 0.02;  // 10 noise sigmas: every true match is in
  const rp::TieFit fit = rp::fit_tie_points(tie, inlier_m, 400, 1);
  EXPECT_EQ(fit.inliers.size(), 800u);
  // At 80 % inliers an all-inlier sample of three is missed 1e-4 of the
  // time after log(1e-4) / log(1 - 0.8^3) = 14 samples: far fewer than 400.
  EXPECT_LE(fit.samples, 30);
  // 800 points with 2 mm noise over a 6 m x 4 m patch fix the scale to a
  // few 1e-5 and the rotation to a few 1e-5 rad; 1e-4 leaves room.
  EXPECT_NEAR(fit.slave_to_face.scale, truth.scale, 1e-4 * truth.scale);
  EXPECT_LT((fit.slave_to_face.R - truth.R).norm(), 1e-4);
  // The same data and seed give the same fit, sample for sample.
  const rp::TieFit again = rp::fit_tie_points(tie, inlier_m, 400, 1);
  EXPECT_EQ(again.samples, fit.samples);
  EXPECT_EQ(again.inliers, fit.inliers);
}

TEST(MultiImageFit, AMovedSampleIsTheSampleTakenThroughTheMotion) {
  rp::SurfaceMesh mesh;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 30; ++x)
      mesh.vertices.emplace_back(0.1 * x, 0.1 * y, 0.01 * std::sin(x + 2.0 * y));
  for (int y = 0; y + 1 < 20; ++y)
    for (int x = 0; x + 1 < 30; ++x) {
      const int a = y * 30 + x;
      mesh.triangles.push_back({a, a + 1, a + 30});
      mesh.triangles.push_back({a + 1, a + 31, a + 30});
    }
  const auto normals = rp::vertex_normals(mesh);
  rp::Similarity first;
  first.scale = 1.7;
  first.t = Eigen::Vector3d(0.3, 0, 1);
  rp::Similarity rigid;
  rigid.R = Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  rigid.t = Eigen::Vector3d(0.002, -0.001, 0.003);
  const auto before = rp::sample_surface(mesh, normals, first, 100);
  const auto direct = rp::sample_surface(mesh, normals, first.then(rigid), 100);
  const auto moved = rp::moved(before, rigid);
  ASSERT_EQ(moved.points.size(), direct.points.size());
  ASSERT_GT(direct.points.size(), 50u);
  for (std::size_t i = 0; i < direct.points.size(); ++i) {
    // Two orders of the same double arithmetic: rounding only.
    EXPECT_LT((moved.points[i] - direct.points[i]).norm(), 1e-12);
    EXPECT_LT((moved.normals[i] - direct.normals[i]).norm(), 1e-12);
  }
}

}  // namespace

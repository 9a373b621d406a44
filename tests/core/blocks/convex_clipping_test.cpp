#include "core/blocks/convex_clipping.h"

#include <set>
#include <utility>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace rockface::blocks {
namespace {

const Eigen::Vector3d kLo(0, 0, 0), kHi(1, 1, 1);

// V - E + F of a closed surface, and every directed edge met once each way.
int euler(const ClippedSolid& s) {
  std::set<std::pair<int, int>> directed;
  for (const auto& f : s.faces)
    for (size_t k = 0; k < f.loop.size(); ++k)
      EXPECT_TRUE(directed.insert({f.loop[k], f.loop[(k + 1) % f.loop.size()]}).second);
  for (const auto& [a, b] : directed) EXPECT_TRUE(directed.count({b, a})) << a << " " << b;
  return static_cast<int>(s.vertices.size()) - static_cast<int>(directed.size() / 2) +
         static_cast<int>(s.faces.size());
}

TEST(ConvexClipping, UncutBoxIsTheBox) {
  const auto s = clip_box(kLo, kHi, {}, {}, 1e-9, 1e-9);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->vertices.size(), 8u);
  EXPECT_EQ(s->faces.size(), 6u);
  EXPECT_EQ(euler(*s), 2);
  for (const auto& f : s->faces) {
    // Counter-clockwise seen from outside: the loop's area vector points out.
    const auto& v = s->vertices;
    const Eigen::Vector3d a2 = (v[f.loop[1]] - v[f.loop[0]]).cross(v[f.loop[2]] - v[f.loop[0]]);
    const Eigen::Vector3d centre = 0.5 * (kLo + kHi);
    EXPECT_GT(a2.dot(v[f.loop[0]] - centre), 0);
  }
}

TEST(ConvexClipping, CornerCutOffMakesATriangle) {
  // x + y + z <= 0.5 keeps the corner tetrahedron at the origin: the three
  // box faces through it, cut to triangles, and the cut.
  const Eigen::Vector3d n = -Eigen::Vector3d(1, 1, 1).normalized();
  const auto s = clip_box(kLo, kHi, {n}, {n.dot(Eigen::Vector3d(0.5, 0, 0))}, 1e-9, 1e-9);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->vertices.size(), 4u);
  EXPECT_EQ(s->faces.size(), 4u);
  EXPECT_EQ(s->faces.back().plane, 0);
  EXPECT_EQ(s->faces.back().loop.size(), 3u);
  EXPECT_EQ(euler(*s), 2);
}

TEST(ConvexClipping, CutThroughCornersWithinTheToleranceMakesNoNewCorner) {
  // The plane through three corners of the box (x + y + z >= 1), moved by
  // less than the tolerance: those corners are on it, nothing new.
  const Eigen::Vector3d n = Eigen::Vector3d(1, 1, 1).normalized();
  for (double shift : {-4e-10, 0.0, 4e-10}) {
    const auto s = clip_box(kLo, kHi, {n}, {n.dot(Eigen::Vector3d(1, 0, 0)) + shift}, 1e-9, 1e-9);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->vertices.size(), 7u) << shift;  // the origin goes, no corner comes
    EXPECT_EQ(s->faces.size(), 7u) << shift;
    EXPECT_EQ(euler(*s), 2);
  }
}

TEST(ConvexClipping, PlaneTouchingAnEdgeCutsNothing) {
  // x + y <= 2 touches the box along its edge x = y = 1.
  const Eigen::Vector3d n = -Eigen::Vector3d(1, 1, 0).normalized();
  const auto s = clip_box(kLo, kHi, {n}, {n.dot(Eigen::Vector3d(1, 1, 0))}, 1e-9, 1e-9);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->vertices.size(), 8u);
  EXPECT_EQ(s->faces.size(), 6u);
  for (const auto& f : s->faces) EXPECT_LT(f.plane, 0);
}

TEST(ConvexClipping, NothingLeftIsNoFaces) {
  const auto s = clip_box(kLo, kHi, {Eigen::Vector3d::UnitX()}, {2.0}, 1e-9, 1e-9);
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->faces.empty());
}

TEST(ConvexClipping, CornersCloserThanTheMergeDistanceAreOne) {
  // Two cuts near the corner (1, 1, 1), 1e-7 apart along their normals:
  // the small face between them has corners 1e-7 apart. With a merge
  // distance of 1e-6 they are one corner; the surface stays closed.
  const Eigen::Vector3d a = -Eigen::Vector3d(1, 1, 2).normalized();
  const Eigen::Vector3d b = -Eigen::Vector3d(2, 1, 1).normalized();
  const Eigen::Vector3d p(1, 1, 0.5);
  const std::vector<Eigen::Vector3d> n{a, b};
  const std::vector<double> off{a.dot(p), b.dot(p) + 1e-7};
  const auto split = clip_box(kLo, kHi, n, off, 1e-12, 1e-12);
  const auto merged = clip_box(kLo, kHi, n, off, 1e-12, 1e-6);
  ASSERT_TRUE(split && merged);
  EXPECT_EQ(euler(*split), 2);
  EXPECT_EQ(euler(*merged), 2);
  EXPECT_LT(merged->vertices.size(), split->vertices.size());
}

}  // namespace
}  // namespace rockface::blocks

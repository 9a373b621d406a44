#include "core/blocks/polyhedron.h"

#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "core/blocks/construction.h"
#include "core/blocks/convexity.h"
#include "core/common/error.h"
#include "tests/core/blocks/block_shapes.h"

namespace rockface::blocks {
namespace {

using test::build;
using test::prism;

// Message of the InputError thrown by f ("" if none was thrown).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Polyhedron, CubeTopologyLinksFacesEdgesAndCorners) {
  const Polyhedron cube = build(prism(test::rectangle(1, 1), 0, 1));
  EXPECT_EQ(cube.vertices().size(), 8u);
  EXPECT_EQ(cube.edges().size(), 12u);
  EXPECT_EQ(cube.faces().size(), 6u);
  EXPECT_EQ(cube.half_edges().size(), 24u);
  for (int v = 0; v < 8; ++v) {
    EXPECT_EQ(cube.faces_around_vertex(v).size(), 3u);
    EXPECT_EQ(cube.planes_at_vertex(v).size(), 3u);
    // Counter-clockwise seen from outside: consecutive outgoing edges turn
    // positively about the outward direction of the corner.
    const auto out = cube.outgoing_half_edges(v);
    const Eigen::Vector3d corner_out = cube.vertices()[v] - Eigen::Vector3d(0.5, 0.5, 0.5);
    for (size_t k = 0; k < out.size(); ++k) {
      const Eigen::Vector3d d0 = cube.vertices()[cube.target(out[k])] - cube.vertices()[v];
      const Eigen::Vector3d d1 =
          cube.vertices()[cube.target(out[(k + 1) % out.size()])] - cube.vertices()[v];
      EXPECT_GT(d0.cross(d1).dot(corner_out), 0) << "vertex " << v;
      // The k-th face holds the k-th outgoing half-edge.
      EXPECT_EQ(cube.half_edges()[out[k]].face, cube.faces_around_vertex(v)[k]);
    }
  }
  // Half-edge links are mutual.
  for (int h = 0; h < 24; ++h) {
    const HalfEdge& he = cube.half_edges()[h];
    EXPECT_EQ(cube.half_edges()[he.twin].twin, h);
    EXPECT_EQ(cube.half_edges()[he.next].prev, h);
    EXPECT_EQ(cube.half_edges()[he.twin].origin, cube.target(h));
  }
  // Every face of a cube has 4 neighbours, none of them itself.
  for (int f = 0; f < 6; ++f) {
    const auto adj = cube.adjacent_faces(f);
    EXPECT_EQ(std::set<int>(adj.begin(), adj.end()).size(), 4u);
    EXPECT_EQ(std::count(adj.begin(), adj.end(), f), 0);
    EXPECT_EQ(cube.face_edges(f).size(), 4u);
  }
  EXPECT_GE(cube.half_edge_between(0, 1), 0);
  EXPECT_EQ(cube.half_edge_between(0, 6), -1);  // a space diagonal is no edge
  for (int e = 0; e < 12; ++e) EXPECT_FALSE(cube.edge_is_reflex(e));
  EXPECT_TRUE(is_convex(cube));
}

TEST(Polyhedron, LShapedPrismHasReflexEdgeAndIsNotConvex) {
  const Polyhedron l = build(prism(test::l_shape(1), 0, 1));
  EXPECT_FALSE(is_convex(l));
  int reflex = 0;
  for (int e = 0; e < static_cast<int>(l.edges().size()); ++e)
    if (l.edge_is_reflex(e)) {
      ++reflex;
      // The reflex edge is the vertical edge at the inner corner (1, 1).
      const Eigen::Vector3d a = l.vertices()[l.edges()[e].v0];
      EXPECT_NEAR(a.x(), 1, 0);
      EXPECT_NEAR(a.y(), 1, 0);
    }
  EXPECT_EQ(reflex, 1);
  EXPECT_FALSE(face_is_convex(l, 0));  // bottom L
  EXPECT_TRUE(face_is_convex(l, 2));   // a side rectangle
}

TEST(Polyhedron, ReportsVertexIndexOutOfRange) {
  auto s = prism(test::rectangle(1, 1), 0, 1);
  s.faces[3].loop[2] = 8;
  const std::string msg = input_error([&] { build(s, "B7"); });
  EXPECT_NE(msg.find("block B7"), std::string::npos) << msg;
  EXPECT_NE(msg.find("face 3 (side1)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("vertex 8 is out of range"), std::string::npos) << msg;
}

TEST(Polyhedron, ReportsOpenSurface) {
  auto s = prism(test::rectangle(1, 1), 0, 1);
  s.faces.erase(s.faces.begin() + 1);  // no top
  const std::string msg = input_error([&] { build(s, "B1"); });
  EXPECT_NE(msg.find("not closed"), std::string::npos) << msg;
  EXPECT_NE(msg.find("block B1"), std::string::npos) << msg;
}

TEST(Polyhedron, ReportsInconsistentOrientation) {
  auto s = prism(test::rectangle(1, 1), 0, 1);
  std::reverse(s.faces[4].loop.begin(), s.faces[4].loop.end());
  const std::string msg = input_error([&] { build(s); });
  EXPECT_NE(msg.find("inconsistent orientation"), std::string::npos) << msg;
}

TEST(Polyhedron, ReportsInsideOutBlock) {
  auto s = prism(test::rectangle(1, 1), 0, 1);
  for (auto& f : s.faces) std::reverse(f.loop.begin(), f.loop.end());
  const std::string msg = input_error([&] { build(s); });
  EXPECT_NE(msg.find("clockwise"), std::string::npos) << msg;
}

TEST(Polyhedron, ReportsNonPlanarFace) {
  auto s = prism(test::rectangle(1, 1), 0, 1);
  s.vertices[6].z() += 0.01;  // lifts one top corner by 1 % of the size
  const std::string msg = input_error([&] { build(s, "B3"); });
  EXPECT_NE(msg.find("not planar"), std::string::npos) << msg;
  EXPECT_NE(msg.find("face 1 (top)"), std::string::npos) << msg;
}

TEST(Polyhedron, ReportsHoleThroughTheBlock) {
  // Two faces glued along a whole loop leave the surface closed but give
  // V - E + F != 2 only with a handle; a pair of disjoint cubes has 2 + 2.
  auto a = prism(test::rectangle(1, 1), 0, 1);
  auto b = prism(test::rectangle(1, 1), 2, 1);
  for (auto& f : b.faces) {
    for (int& v : f.loop) v += 8;
    f.index += 10;
    f.name += "b";
  }
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  a.faces.insert(a.faces.end(), b.faces.begin(), b.faces.end());
  const std::string msg = input_error([&] { build(a); });
  EXPECT_NE(msg.find("Euler"), std::string::npos) << msg;
}

TEST(Polyhedron, ReportsUnusedVertex) {
  auto s = prism(test::rectangle(1, 1), 0, 1);
  s.vertices.emplace_back(5, 5, 5);
  const std::string msg = input_error([&] { build(s); });
  EXPECT_NE(msg.find("vertex 8 belongs to no face"), std::string::npos) << msg;
}

TEST(Polyhedron, FacesOnOneNamedPlaneShareIt) {
  // A U-shaped prism whose top consists of two faces on the same plane.
  const std::vector<Eigen::Vector2d> u{{0, 0}, {3, 0}, {3, 2}, {2, 2},
                                       {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  auto s = prism(u, 0, 1);
  // Split the bottom along the diagonal 0-5 into two faces on one plane.
  s.faces[0].loop = {7, 6, 5, 0};  // left part of the bottom, clockwise from above
  s.faces.push_back(FaceInput{0, "bottom", PlaneKind::Joint, std::nullopt, {5, 4, 3, 2, 1, 0}});
  const Polyhedron p = build(s);
  EXPECT_EQ(p.faces_on_plane(p.faces()[0].plane).size(), 2u);
}

}  // namespace
}  // namespace rockface::blocks

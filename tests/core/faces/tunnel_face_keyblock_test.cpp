// A tunnel face with floor and side walls, and three joints that meet 0.8 m
// behind the face: the traces cut out one triangle on the face whose block is
// the tetrahedron-like keyblock with its apex at the joints' common point; the
// other closed loops are infinite (their joint cones widen into the rock).
// Every joint is traced once per patch it crosses, as a geologist marks it
// patch by patch: the pieces of one joint must give one plane, not several
// copies of it.
#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "core/common/units.h"
#include "core/faces/surface_loops.h"
#include "core/faces/trace_blocks.h"
#include "core/faces/trace_network.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "tests/core/faces/benched_slope.h"
#include "tests/core/faces/trace_map_run.h"

namespace rockface::faces {
namespace {

using V = Eigen::Vector3d;
using testing::joint;

constexpr double kSnap = 0.05;

// The face (two patches with a slight re-entrant angle at x = 0), the floor
// and both walls of a 6 m wide, 5 m high heading driven north.
std::vector<PatchInput> heading() {
  return {
      {"FACE_W", {V(-3, 10, 0), V(0, 10.3, 0), V(0, 10.5, 5), V(-3, 10.2, 5)}},
      {"FACE_E", {V(0, 10.3, 0), V(3, 10.1, 0), V(3, 10.3, 5), V(0, 10.5, 5)}},
      {"FLOOR", {V(-3, 0, 0), V(3, 0, 0), V(3, 10.1, 0), V(0, 10.3, 0), V(-3, 10, 0)}},
      {"WALL_W", {V(-3, 0, 0), V(-3, 10, 0), V(-3, 10.2, 5), V(-3, 0, 5)}},
      {"WALL_E", {V(3, 0, 0), V(3, 0, 5), V(3, 10.3, 5), V(3, 10.1, 0)}},
  };
}

const V kApex(-1.5, 11.1, 1.6);  // the joints' common point, behind the face

std::vector<TraceJoint> joints() {
  return {joint("J1", 60, 200, 0), joint("J2", 75, 110, 1), joint("J3", 20, 350, 2)};
}

geometry::Plane plane_of(const TraceJoint& j) {
  return geometry::Plane::from_orientation(j.orientation, kApex);
}

// The joint's trace on each convex patch it crosses: the chord between the
// two crossings of the plane with the polygon's edges.
std::vector<TraceInput> traces_patch_by_patch() {
  std::vector<TraceInput> out;
  for (const TraceJoint& j : joints()) {
    const geometry::Plane pl = plane_of(j);
    for (const PatchInput& p : heading()) {
      std::vector<V> x;
      for (size_t i = 0; i < p.polygon.size(); ++i) {
        const V& a = p.polygon[i];
        const V& b = p.polygon[(i + 1) % p.polygon.size()];
        const double da = pl.signed_distance(a), db = pl.signed_distance(b);
        if ((da < 0) == (db < 0)) continue;  // half-open: a corner on the plane counts once
        x.push_back(a + (b - a) * (da / (da - db)));
      }
      if (x.size() == 2) out.push_back({j.id + "-" + p.id, j, {x[0], x[1]}});
    }
  }
  return out;
}

testing::TraceMapRun analyse(const std::vector<TraceInput>& traces) {
  return testing::run_trace_map(heading(), traces, kSnap, deg_to_rad(1.0), deg_to_rad(1.0));
}

// Where the face patch's plane meets two joints.
V face_corner(const geometry::Plane& face, const geometry::Plane& a, const geometry::Plane& b) {
  Eigen::Matrix3d M;
  M << face.normal.transpose(), a.normal.transpose(), b.normal.transpose();
  return M.colPivHouseholderQr().solve(V(face.offset, a.offset, b.offset));
}

geometry::Plane patch_plane(const PatchInput& p) {
  const V n = (p.polygon[1] - p.polygon[0]).cross(p.polygon[2] - p.polygon[0]).normalized();
  return {n.z() < 0 ? V(-n) : n, (n.z() < 0 ? V(-n) : n).dot(p.polygon[0])};
}

TEST(TunnelFaceKeyblock, OneFiniteBlockWithItsApexWhereTheJointsMeet) {
  const auto traces = traces_patch_by_patch();
  ASSERT_GE(traces.size(), 9u);  // each joint crosses at least three patches
  const auto r = analyse(traces);
  std::vector<const TraceBlock*> finite;
  for (const auto& b : r.blocks) {
    // The pieces of one joint are one plane: three joint digits at most.
    int joint_planes = 0;
    for (const auto& p : b.planes) joint_planes += p.kind == blocks::PlaneKind::Joint ? 1 : 0;
    EXPECT_LE(joint_planes, 3);
    for (const auto& n : b.notes) EXPECT_EQ(n.find("not assembled"), std::string::npos) << n;
    if (b.finite) finite.push_back(&b);
  }
  ASSERT_EQ(finite.size(), 1u);
  const TraceBlock& key = *finite.front();
  ASSERT_TRUE(key.polyhedron && key.analysis);
  EXPECT_FALSE(key.finiteness.finite.marginal);
  EXPECT_TRUE(key.finiteness.removable.value);

  // Its loop on the face: the three corners where two joints meet on a face
  // patch (the two patches meet at x = 0; the apex lies west of it, so the
  // corners are found on the patch each lies on).
  const auto patches = heading();
  const geometry::Plane west = patch_plane(patches[0]), east = patch_plane(patches[1]);
  const auto js = joints();
  const geometry::Plane j1 = plane_of(js[0]), j2 = plane_of(js[1]), j3 = plane_of(js[2]);
  int corners_found = 0;
  for (const auto& [a, b] : {std::pair{j1, j2}, std::pair{j2, j3}, std::pair{j1, j3}}) {
    V c = face_corner(west, a, b);
    if (c.x() > 0) c = face_corner(east, a, b);
    for (const V& x : key.surface_polygon)
      // Trace ends are exact crossings; the network snaps nothing here, so
      // the corners agree to rounding of the line intersections (~1e-12 m).
      if ((x - c).norm() < 1e-9) ++corners_found;
  }
  EXPECT_EQ(corners_found, 3);

  // Volume of the cone from the apex over the loop: one third of area times
  // the apex's distance from each face patch, the loop split at x = 0.
  double volume = 0;
  for (bool west_side : {true, false}) {
    std::vector<V> part;
    for (const V& x : key.surface_polygon)
      if (west_side ? x.x() <= 1e-9 : x.x() >= -1e-9) part.push_back(x);
    V area2 = V::Zero();
    for (size_t i = 0; i < part.size(); ++i) area2 += part[i].cross(part[(i + 1) % part.size()]);
    const geometry::Plane& face = west_side ? west : east;
    volume += area2.norm() / 2 * std::abs(face.signed_distance(kApex)) / 3;
  }
  // Both sides are the same polyhedron from exact planes: rounding only.
  EXPECT_NEAR(key.analysis->mass.volume, volume, 1e-9 * volume);
  EXPECT_GT(volume, 0.5);  // the loop is a real block (~0.77 m^3), not a sliver

  // Purely frictional sliding on J1 and J2: the factor of safety does not
  // depend on the block's size, so it is that of the joint pyramid.
  ASSERT_TRUE(key.analysis->mode);
  EXPECT_EQ(key.analysis->mode->type, kinematics::ModeType::Sliding);
  std::vector<int> sliding = key.analysis->mode->planes;
  std::sort(sliding.begin(), sliding.end());
  EXPECT_EQ(sliding, (std::vector<int>{0, 1}));
  std::vector<kinematics::ContactPlane> contacts;
  for (int k = 0; k < 3; ++k) {
    const geometry::Plane pl = plane_of(js[k]);
    const double side = pl.signed_distance(key.analysis->mass.centroid) > 0 ? 1 : -1;
    contacts.push_back({k, side * pl.normal, js[k].friction, 0});
  }
  const auto pyramid = kinematics::sliding_mode(V(0, 0, -1), contacts, deg_to_rad(1.0));
  ASSERT_TRUE(pyramid.fos && key.analysis->fos);
  // Same formula on the same normals; the block's resultant is its weight.
  EXPECT_NEAR(*key.analysis->fos, *pyramid.fos, 1e-9);
}

TEST(TunnelFaceKeyblock, OneTracePerJointAcrossThePatchesGivesTheSameBlocks) {
  // The same joints marked as one polyline each, running over the patch
  // edges, instead of one trace per patch.
  const auto pieces = traces_patch_by_patch();
  const auto ref = analyse(pieces);
  std::vector<TraceInput> joined;
  for (const TraceJoint& j : joints()) {
    TraceInput t{j.id, j, {}};
    std::vector<const TraceInput*> mine;
    for (const auto& p : pieces)
      if (p.joint->id == j.id) mine.push_back(&p);
    // Chain the chords end to start; each joint's pieces form one open path.
    t.points = mine.front()->points;
    std::vector<bool> used(mine.size(), false);
    used[0] = true;
    for (bool grew = true; grew;) {
      grew = false;
      for (size_t k = 0; k < mine.size(); ++k) {
        if (used[k]) continue;
        const auto& q = mine[k]->points;
        if ((q[0] - t.points.back()).norm() < 1e-9) {
          t.points.push_back(q[1]);
        } else if ((q[1] - t.points.back()).norm() < 1e-9) {
          t.points.push_back(q[0]);
        } else if ((q[1] - t.points.front()).norm() < 1e-9) {
          t.points.insert(t.points.begin(), q[0]);
        } else if ((q[0] - t.points.front()).norm() < 1e-9) {
          t.points.insert(t.points.begin(), q[1]);
        } else {
          continue;
        }
        used[k] = grew = true;
      }
    }
    joined.push_back(t);
  }
  const auto got = analyse(joined);
  ASSERT_EQ(got.blocks.size(), ref.blocks.size());
  for (size_t k = 0; k < ref.blocks.size(); ++k) {
    EXPECT_EQ(got.blocks[k].finite, ref.blocks[k].finite);
    if (ref.blocks[k].analysis && got.blocks[k].analysis) {
      // Same planes and loop: rounding of the corner solves only.
      EXPECT_NEAR(got.blocks[k].analysis->mass.volume, ref.blocks[k].analysis->mass.volume, 1e-9);
    } else {
      EXPECT_EQ(bool(got.blocks[k].analysis), bool(ref.blocks[k].analysis));
    }
  }
}

TEST(TunnelFaceKeyblock, PiecesOfAJointMergeOnlyWhereTheyMeet) {
  // On the benched slope's lower face, three traces of the vertical set Jy
  // whose planes lie within 3 cm (inside the 5 cm tolerance): "a" and "c"
  // meet end to end (one joint marked in two pieces), "b" runs parallel
  // further up and meets neither - another joint of the set.
  using testing::on_lower_face;
  const std::vector<TraceInput> t = {
      {"a", joint("Jy", 90, 0, 0), {on_lower_face(4, 0.5), on_lower_face(4, 2)}},
      {"c", joint("Jy", 90, 0, 0), {on_lower_face(4.03, 2), on_lower_face(4.03, 2.8)}},
      {"b", joint("Jy", 90, 0, 0), {on_lower_face(4.02, 3.5), on_lower_face(4.02, 4.5)}},
  };
  const FreeSurface surface = FreeSurface::build(testing::benched_slope_patches(), kSnap);
  const TraceNetwork net = TraceNetwork::build(surface, t, {kSnap, 0.0});
  ASSERT_EQ(net.groups().size(), 2u);
  EXPECT_EQ(net.groups()[0].traces, (std::vector<int>{0, 1}));
  EXPECT_EQ(net.groups()[1].traces, (std::vector<int>{2}));
}

}  // namespace
}  // namespace rockface::faces

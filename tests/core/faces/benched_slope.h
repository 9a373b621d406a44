#pragma once
// A benched slope of five patches (floor, lower face, bench, upper face, top)
// striking north-south, facing west, 20 m long, with joint traces whose
// blocks are known by construction:
//   A: on the lower face, between vertical joints y = 4 and y = 8, above a
//      joint dipping 30 out of the face and left of one dipping 80 out of it:
//      a finite triangular prism.
//   B: across the crest of the lower face, between vertical joints y = 12 and
//      y = 16, above a joint dipping 20 out of the face, behind a vertical
//      joint x = 5 on the bench: a finite block on a convex edge.
//   C: on the top, between four joints dipping 80 away from each other: an
//      infinite block (it widens with depth).
// Trace points lie exactly on the joint planes; the tests perturb them.
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/common/units.h"
#include "core/faces/free_surface.h"
#include "core/faces/trace_plane.h"
#include "core/geometry/orientation.h"

namespace rockface::faces::testing {

inline std::vector<PatchInput> benched_slope_patches() {
  using V = Eigen::Vector3d;
  return {
      {"S1", {V(-10, 0, 0), V(0, 0, 0), V(0, 20, 0), V(-10, 20, 0)}},
      {"S2", {V(0, 0, 0), V(3, 0, 6), V(3, 20, 6), V(0, 20, 0)}},
      {"S3", {V(3, 0, 6), V(8, 0, 6), V(8, 20, 6), V(3, 20, 6)}},
      {"S4", {V(8, 0, 6), V(11, 0, 12), V(11, 20, 12), V(8, 20, 6)}},
      {"S5", {V(11, 0, 12), V(21, 0, 12), V(21, 20, 12), V(11, 20, 12)}},
  };
}

inline TraceJoint joint(const std::string& id, double dip, double dipdir, int index) {
  TraceJoint j;
  j.index = index;
  j.id = id;
  j.orientation = {deg_to_rad(dip), deg_to_rad(dipdir)};
  j.friction = deg_to_rad(35);
  return j;
}

// A point of the lower face at height z and northing y.
inline Eigen::Vector3d on_lower_face(double y, double z) {
  return {z / 2, y, z};
}

struct ExpectedLoop {
  std::string name;
  std::vector<Eigen::Vector3d> corners;  // the surface polygon
  bool finite = true;
};

inline std::vector<TraceInput> benched_slope_traces() {
  using V = Eigen::Vector3d;
  std::vector<TraceInput> t;
  // Block A. Vertical joints along the dip of the face, past both horizontal traces.
  t.push_back({"A-y4", joint("Jy", 90, 0, 0), {on_lower_face(4, 0.5), on_lower_face(4, 4.5)}});
  t.push_back({"A-y8", joint("Jy", 90, 0, 0), {on_lower_face(8, 0.5), on_lower_face(8, 4.5)}});
  // Dipping 30 and 80 towards 270 (out of the face): horizontal lines on it.
  t.push_back({"A-low",
               joint("J30", 30, 270, 1),
               {on_lower_face(3, 1), on_lower_face(6, 1), on_lower_face(9, 1)}});
  t.push_back({"A-high", joint("J80", 80, 270, 2), {on_lower_face(3, 4), on_lower_face(9, 4)}});
  // Block B: vertical joints marked from the face over the crest onto the bench.
  t.push_back(
      {"B-y12", joint("Jy", 90, 0, 0), {on_lower_face(12, 2), on_lower_face(12, 6), V(6, 12, 6)}});
  t.push_back(
      {"B-y16", joint("Jy", 90, 0, 0), {on_lower_face(16, 2), on_lower_face(16, 6), V(6, 16, 6)}});
  t.push_back({"B-low", joint("J20", 20, 270, 3), {on_lower_face(11, 3), on_lower_face(17, 3)}});
  t.push_back({"B-back", joint("Jx", 90, 90, 4), {V(5, 11, 6), V(5, 17, 6)}});
  // Block C on the top: four joints dipping 80 away from the block.
  t.push_back({"C-w", joint("Jw", 80, 270, 5), {V(14, 2, 12), V(14, 10, 12)}});
  t.push_back({"C-e", joint("Je", 80, 90, 6), {V(18, 2, 12), V(18, 10, 12)}});
  t.push_back({"C-s", joint("Js", 80, 180, 7), {V(13, 3, 12), V(19, 3, 12)}});
  t.push_back({"C-n", joint("Jn", 80, 0, 8), {V(13, 9, 12), V(19, 9, 12)}});
  return t;
}

inline std::vector<ExpectedLoop> benched_slope_loops() {
  using V = Eigen::Vector3d;
  return {
      {"A",
       {on_lower_face(4, 1), on_lower_face(8, 1), on_lower_face(8, 4), on_lower_face(4, 4)},
       true},
      {"B",
       {on_lower_face(12, 3), on_lower_face(16, 3), V(3, 16, 6), V(5, 16, 6), V(5, 12, 6),
        V(3, 12, 6)},
       true},
      {"C", {V(14, 3, 12), V(18, 3, 12), V(18, 9, 12), V(14, 9, 12)}, false},
  };
}

}  // namespace rockface::faces::testing

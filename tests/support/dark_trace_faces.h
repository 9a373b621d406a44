#pragma once
// Faces whose joints show only as dark lines (issue 38, "Joints proposed on
// the image"): two planar patches with no relief along any joint, cut by
// joints of three sets that cross each other many times, so that a trace
// is followed through its junctions or lost in pieces. Three networks:
// sparse (2 joints per set), medium (3) and dense (5 per set, 15 joints).
// The true traces are the renderer's (each joint plane cut with the true
// surface, camera::true_trace_segments), scored with score_proposals of
// proposal_faces.h.
//
// The two patches meet in a bend of 9 degrees, like the demo scene's face,
// under the fold cue's 12: a single plane would do for the proposals, but
// the relative orientation of a stereo pair of one plane is ambiguous (seen
// here: "the rays intersect at only 0.7 deg" on three texture seeds of
// five, a matter for core/photogrammetry).
//
// The sets are the demo scene's (60/200, 75/110, 20/350): on the nearly
// vertical face A's traces rise at about 30 degrees, B's are steep and C's
// nearly level, so A and C cross at under 30 degrees, where a line that
// runs on at every junction along the straightest pair takes the wrong
// branch. Joints of one set are 1.2-1.8 m apart.
#include <string>

#include "tests/support/proposal_faces.h"

namespace rockface::testing {

enum class TraceNetwork { sparse, medium, dense };

inline const char* network_name(TraceNetwork n) {
  switch (n) {
    case TraceNetwork::sparse:
      return "sparse (3 x 2 joints)";
    case TraceNetwork::medium:
      return "medium (3 x 3 joints)";
    case TraceNetwork::dense:
      return "dense (3 x 5 joints)";
  }
  return "";
}

inline int joints_per_set(TraceNetwork n) {
  return n == TraceNetwork::sparse ? 2 : n == TraceNetwork::medium ? 3 : 5;
}

// The face's north coordinate at (x, z): two planes, nearly vertical
// (2.3 degrees off), that meet along x = 0 in a gentle bend (9 degrees; the
// fold cue's seed is 12) like the demo scene's face.
inline double bent_face_y(double x, double z) {
  return 10.3 + (x < 0 ? 0.1 * x : -0.07 * x) + 0.04 * (z - 0.5);
}

inline camera::SyntheticScene dark_trace_face_scene(TraceNetwork network) {
  camera::SyntheticScene s = proposal_face_scene(JointDensity::none);
  // The demo scene's camera (tools/samples/tunnel-face-demo.scene.json):
  // 1500 x 1000 px, a 2 cm trace 4.5 px wide at 10 m.
  s.camera.width = 1500;
  s.camera.height = 1000;
  s.camera.fx = s.camera.fy = 2232.5;
  s.camera.cx = 749.5;
  s.camera.cy = 499.5;
  s.range_pole = camera::SyntheticRangePole{{0.6, 7.0, -0.6}, 2.0, 0.25};
  s.patches.clear();
  const double xs[] = {-4.2, 0.0, 4.2};
  for (int k = 0; k < 2; ++k) {
    camera::SyntheticPatch p;
    p.id = "F" + std::to_string(k + 1);
    for (auto [x, z] : {std::pair{xs[k], -2.5}, {xs[k + 1], -2.5}, {xs[k + 1], 3.5}, {xs[k], 3.5}})
      p.polygon.emplace_back(x, bent_face_y(x, z), z);
    s.patches.push_back(p);
  }
  s.reference_line = {{Eigen::Vector3d(-1.0, bent_face_y(-1.0, 1.8), 1.8),
                       Eigen::Vector3d(1.0, bent_face_y(1.0, 2.2), 2.2)}};
  auto joint = [&](const std::string& id, double dip, double dipdir, double x, double z) {
    s.joints.push_back({id, geometry::plane_normal_deg(dip, dipdir), {x, bent_face_y(x, z), z}});
  };
  // Where each joint passes through the face's middle line (z = 0.5 for
  // the steep sets, x = 0 for the flat one), spread over the face; the
  // first ones of each list are the sparse network's.
  const double a_x[] = {-1.8, 1.2, 0.0, -3.0, 2.4};
  const double b_x[] = {-1.4, 1.0, -0.2, 2.2, -2.6};
  const double c_z[] = {-0.3, 1.5, 0.6, -1.2, 2.4};
  for (int i = 0; i < joints_per_set(network); ++i) {
    joint("A" + std::to_string(i + 1), 60, 200, a_x[i], 0.5);
    joint("B" + std::to_string(i + 1), 75, 110, b_x[i], 0.5);
    joint("C" + std::to_string(i + 1), 20, 350, 0.0, c_z[i]);
  }
  return s;
}

inline ProposalFace build_dark_trace_face(TraceNetwork network, Preset preset) {
  return build_proposal_face_from(JointDensity::none, dark_trace_face_scene(network), preset);
}

}  // namespace rockface::testing

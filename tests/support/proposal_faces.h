#pragma once
// Rendered faces with known joints for trace proposals (issue 25), shared by
// the tests and tools/bench/trace_proposals_bench.cpp.
//
// The face: three planar facets that meet along two folds (continuous, no
// steps), leaning back 17 degrees, 10 m in front of the stations of the
// reconstruction tests (tests/support/synthetic_face.h:
// same cameras, range pole and compass line). The face broke along joints:
// the two folds lie on two vertical joints (planes x = -1.4 and x = 1.4),
// so each fold is a true trace that both cues see; the other joints are
// three sets (60/200, 80/100, 25/350), one, two or four of each (sparse,
// medium, dense). The flat face is one plane with the rock texture and no
// joint at all. True traces are the renderer's: each joint plane cut with
// the true surface (camera::true_trace_segments).
//
// Scores: a proposal point is true when within `tolerance` (5 cm) of a
// true trace; a true-trace sample is found when within `tolerance` of a
// proposal. Only the true traces the 3D image covers count (the reconstructed
// surface under them, not hidden behind the pole).
#include <algorithm>
#include <cmath>
#include <memory>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <string>
#include <vector>

#include "camera/synthetic_renderer.h"
#include "core/common/preset.h"
#include "core/geometry/orientation.h"
#include "core/measure/proposals/trace_proposals.h"
#include "core/photogrammetry/camera/camera_cv.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "tests/support/synthetic_face.h"
#include "tests/support/synthetic_truth.h"

namespace rockface::testing {

enum class JointDensity { none, sparse, medium, dense };

inline const char* density_name(JointDensity d) {
  switch (d) {
    case JointDensity::none:
      return "flat, no joints";
    case JointDensity::sparse:
      return "sparse (3 + 2 joints)";
    case JointDensity::medium:
      return "medium (6 + 2 joints)";
    case JointDensity::dense:
      return "dense (12 + 2 joints)";
  }
  return "";
}

// The face's north coordinate at (x, z): y = 10 + g(x) + 0.3 (z - 0.5).
inline double folded_face_y(double x, double z, bool flat) {
  double g = -0.1 * x;
  if (!flat && x < -1.4) g = 0.14 + 0.35 * (x + 1.4);
  if (!flat && x > 1.4) g = -0.14 + 0.3 * (x - 1.4);
  return 10.0 + g + 0.3 * (z - 0.5);
}

inline camera::SyntheticScene proposal_face_scene(JointDensity density) {
  const bool flat = density == JointDensity::none;
  // noise 2 grey levels and 0.6 px blur: a good DSLR at base ISO.
  camera::SyntheticScene s = synthetic_face(1200, 800, false, 2.0);
  s.patches.clear();
  const double xs[] = {-4.2, -1.4, 1.4, 4.2};
  for (int k = 0; k < 3; ++k) {
    camera::SyntheticPatch p;
    p.id = "F" + std::to_string(k + 1);
    for (auto [x, z] : {std::pair{xs[k], -2.5}, {xs[k + 1], -2.5}, {xs[k + 1], 3.5}, {xs[k], 3.5}})
      p.polygon.emplace_back(x, folded_face_y(x, z, flat), z);
    s.patches.push_back(p);
  }
  s.reference_line = {{Eigen::Vector3d(-1.0, folded_face_y(-1.0, 1.8, flat), 1.8),
                       Eigen::Vector3d(1.0, folded_face_y(1.0, 2.2, flat), 2.2)}};
  if (flat) return s;
  auto joint = [&](const std::string& id, double dip, double dipdir, double x, double z) {
    s.joints.push_back(
        {id, geometry::plane_normal_deg(dip, dipdir), {x, folded_face_y(x, z, flat), z}});
  };
  joint("K1", 90, 90, -1.4, 0.0);  // the folds
  joint("K2", 90, 90, 1.4, 0.0);
  const int per_set = density == JointDensity::sparse ? 1 : density == JointDensity::medium ? 2 : 4;
  const double a_x[] = {-2.9, 0.4, -0.9, 2.6}, b_x[] = {-3.4, 2.1, -0.5, 3.5},
               c_z[] = {1.6, -1.2, 2.8, 0.2};
  for (int i = 0; i < per_set; ++i) {
    joint("A" + std::to_string(i + 1), 60, 200, a_x[i], 0.5);
    joint("B" + std::to_string(i + 1), 80, 100, b_x[i], 0.5);
    joint("C" + std::to_string(i + 1), 25, 350, 0.0, c_z[i]);
  }
  return s;
}

struct ProposalFace {
  JointDensity density = JointDensity::none;
  camera::SyntheticScene scene;
  camera::SyntheticRender render;
  photogrammetry::ReconstructionResult rec;
  measure::PhotoView left;
  Eigen::Matrix4d scene_to_mesh = Eigen::Matrix4d::Identity();
  // True trace segments in the 3D image's frame.
  std::vector<std::array<Eigen::Vector3d, 2>> truth;
  std::vector<std::string> truth_joint;  // the joint of each segment
  // Facets' outlines in the 3D image's frame (the scene's patches).
  std::vector<measure::ProposalFacet> facets;
};

// `scene`: proposal_face_scene(density), perhaps with another camera (the
// benchmark's 24 Mpx frame).
inline ProposalFace build_proposal_face_from(JointDensity density, camera::SyntheticScene scene,
                                             Preset preset) {
  ProposalFace f;
  f.density = density;
  f.scene = std::move(scene);
  NoProgress progress;
  f.render = camera::render_scene(f.scene, progress);
  f.rec = photogrammetry::reconstruct(f.render.images[0], f.render.images[1], f.render.intrinsics,
                                      f.render.intrinsics,
                                      photogrammetry::reconstruction_preset(preset),
                                      pole_and_compass(f.scene, f.render, 0.0), progress);
  f.left = measure::left_view(f.rec.model_to_world, f.render.intrinsics);
  // The scene frame onto the 3D image's: the similarity between the true
  // surface point (the renderer's depth) and the mesh vertex at the same
  // pixels. The registration's own error (a few cm) is the reconstruction
  // tests' subject; here the proposals are judged on the 3D image they
  // were found on.
  const auto& pose = f.render.poses[0];
  std::vector<Eigen::Vector3d> truth_pts, mesh_pts;
  for (std::size_t k = 0; k < f.rec.mesh.size(); k += 13) {
    const Eigen::Vector2f px = f.rec.mesh.pixels[k];
    const int x = static_cast<int>(std::lround(px.x())), y = static_cast<int>(std::lround(px.y()));
    if (x < 0 || y < 0 || x >= f.render.depth_left.cols || y >= f.render.depth_left.rows) continue;
    const double depth = f.render.depth_left.at<float>(y, x);
    if (!(depth > 0)) continue;
    const Eigen::Vector2d ray =
        photogrammetry::undistort_to_normalised({px.cast<double>()}, f.render.intrinsics)[0];
    truth_pts.push_back(pose.R.transpose() * (depth * Eigen::Vector3d(ray.x(), ray.y(), 1.0)) +
                        pose.centre);
    mesh_pts.push_back(f.rec.mesh.vertices[k]);
  }
  Eigen::Matrix3Xd A(3, truth_pts.size()), B(3, mesh_pts.size());
  for (std::size_t i = 0; i < truth_pts.size(); ++i) {
    A.col(static_cast<Eigen::Index>(i)) = truth_pts[i];
    B.col(static_cast<Eigen::Index>(i)) = mesh_pts[i];
  }
  const Eigen::Matrix4d T = Eigen::umeyama(A, B, true);
  const auto to_mesh = [&T](const Eigen::Vector3d& p) {
    return Eigen::Vector3d((T * p.homogeneous()).head<3>());
  };
  f.scene_to_mesh = T;
  for (const auto& t : camera::true_trace_segments(f.scene))
    if (t.joint != "K1" && t.joint != "K2")  // the folds: added whole below
    {
      f.truth.push_back({to_mesh(t.world[0]), to_mesh(t.world[1])});
      f.truth_joint.push_back(t.joint);
    }
  // The fold joints' planes hold the facets' shared edges: their traces are
  // those edges (a degenerate cut for the renderer's clipping).
  if (density != JointDensity::none)
    for (double x : {-1.4, 1.4}) {
      f.truth.push_back({to_mesh(Eigen::Vector3d(x, folded_face_y(x, -2.5, false), -2.5)),
                         to_mesh(Eigen::Vector3d(x, folded_face_y(x, 3.5, false), 3.5))});
      f.truth_joint.push_back(x < 0 ? "K1" : "K2");
    }
  for (std::size_t k = 0; k < f.scene.patches.size(); ++k) {
    measure::ProposalFacet facet;
    facet.id = static_cast<int>(k) + 1;
    for (const auto& p : f.scene.patches[k].polygon) facet.outline.push_back(to_mesh(p));
    f.facets.push_back(facet);
  }
  return f;
}

inline ProposalFace build_proposal_face(JointDensity density, Preset preset) {
  return build_proposal_face_from(density, proposal_face_scene(density), preset);
}

inline double distance_to_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                  const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-24), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

struct ProposalScore {
  double precision = 1, recall = 0;
  double proposed_m = 0, false_m = 0;  // proposal length, and its part off every true trace
  double truth_m = 0;                  // true trace length the 3D image covers
  std::size_t proposals = 0;
  double mapped_area_m2 = 0;  // the face the 3D image covers
};

inline ProposalScore score_proposals(const ProposalFace& f,
                                     const std::vector<measure::TraceProposal>& proposals,
                                     const measure::MeshPicker& picker, double tolerance) {
  ProposalScore s;
  s.proposals = proposals.size();
  std::size_t true_points = 0, points = 0;
  for (const auto& p : proposals) {
    const auto& x = p.trace.points;
    for (std::size_t i = 0; i < x.size(); ++i) {
      // Each point stands for the length to its neighbours.
      const double len = 0.5 * ((i > 0 ? (x[i] - x[i - 1]).norm() : 0) +
                                (i + 1 < x.size() ? (x[i + 1] - x[i]).norm() : 0));
      double best = 1e9;
      for (const auto& t : f.truth) best = std::min(best, distance_to_segment(x[i], t[0], t[1]));
      ++points;
      s.proposed_m += len;
      if (best <= tolerance) {
        ++true_points;
      } else {
        s.false_m += len;
      }
    }
  }
  if (points > 0) s.precision = static_cast<double>(true_points) / static_cast<double>(points);
  // Recall: 1 cm samples of the true traces that the 3D image covers.
  std::size_t covered = 0, found = 0;
  for (const auto& t : f.truth) {
    const double len = (t[1] - t[0]).norm();
    const int n = std::max(1, static_cast<int>(len / 0.01));
    for (int i = 0; i <= n; ++i) {
      const Eigen::Vector3d q = t[0] + (t[1] - t[0]) * (static_cast<double>(i) / n);
      const auto px = measure::project_to_view(f.left, {q})[0];
      if (!px.allFinite() || !measure::pixel_in_image(f.left, px)) continue;
      const auto hit = picker.pick(measure::ray_through_pixel(f.left, px, "truth"));
      // Covered: the reconstructed surface is there, within 3x the
      // tolerance of the true point (not the pole in front of it, nor a hole).
      if (!hit || (hit->point - q).norm() > 3 * tolerance) continue;
      ++covered;
      bool near = false;
      for (const auto& p : proposals) {
        const auto& x = p.trace.points;
        for (std::size_t k = 1; k < x.size() && !near; ++k)
          near = distance_to_segment(q, x[k - 1], x[k]) <= tolerance;
        if (near) break;
      }
      found += near;
    }
  }
  s.truth_m = 0.01 * static_cast<double>(covered);
  if (covered > 0) s.recall = static_cast<double>(found) / static_cast<double>(covered);
  // Mapped area: the triangles of the 3D image (the pole's are a few cm^2).
  const auto& m = f.rec.mesh;
  for (const auto& t : m.triangles)
    s.mapped_area_m2 +=
        0.5 *
        (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
  return s;
}

// A face with its proposals at `preset` and their score against the truth
// within `tolerance` (m): what the proposal suites keep per face.
struct ProposedFace {
  ProposalFace face;
  std::unique_ptr<measure::MeshPicker> picker;
  measure::ProposalResult result;
  ProposalScore score;
};

inline std::unique_ptr<ProposedFace> propose_on(ProposalFace face, Preset preset,
                                                double tolerance) {
  auto r = std::make_unique<ProposedFace>();
  r->face = std::move(face);
  r->picker = std::make_unique<measure::MeshPicker>(r->face.rec.mesh);
  auto options = measure::proposal_options(preset);
  options.measure.point_sigma = r->face.rec.accuracy.sigma_z;
  NoProgress progress;
  r->result =
      measure::propose_traces(r->face.rec.mesh, *r->picker, r->face.left, r->face.render.images[0],
                              r->face.facets, options, progress, "proposals");
  r->score = score_proposals(r->face, r->result.proposals, *r->picker, tolerance);
  return r;
}

}  // namespace rockface::testing

#pragma once
// The synthetic face (synthetic_face.h) photographed as several stereo pairs
// from stations moved along it, each pair seeing ~5.4 m of the 8.4 m face:
// the scene of one pair, its photographs and reconstruction (the master by
// range pole and compass, the others unregistered), and the distance of a
// point to the true face. Shared by the multi-image test and the merge
// benchmark (tools/bench/face_merge_bench.cpp).
#include <optional>
#include <string>

#include "core/photogrammetry/reconstruction/multi_image_registration.h"
#include "tests/support/synthetic_truth.h"

namespace rockface::testing {

// The face with two joints: J1 nearly horizontal at ~1.6 m, across the
// photographs of pairs up to 2 m either side and above the pole; J2 steep at
// x ~ -2. `x_offset` moves both stations (and where they look) East.
inline camera::SyntheticScene multi_image_face(double x_offset) {
  camera::SyntheticScene s = synthetic_face(1200, 800);
  // A longer focal length: each pair sees only part of the face.
  s.camera.fx = s.camera.fy = 2200;
  // A shorter pole, so both targets are in the narrower view, below J1.
  s.range_pole = camera::SyntheticRangePole{{0.6, 7.0, -0.3}, 1.0, 0.25};
  const auto& mid = synthetic_facets()[1];
  s.reference_line = {{Eigen::Vector3d(-1.2, facet_y(mid, -1.2, -0.1), -0.1),
                       Eigen::Vector3d(0.3, facet_y(mid, 0.3, 0.1), 0.1)}};
  for (auto& st : s.stations) {
    st.position.x() += x_offset;
    st.look_at.x() += x_offset;
  }
  const auto normal = [](double dip, double dipdir) {
    return geometry::plane_normal_deg(dip, dipdir);
  };
  s.joints.push_back({"J1", normal(8, 180), {0.0, 10.0, 1.6}});
  s.joints.push_back({"J2", normal(80, 100), {-2.0, 10.0, 0.0}});
  return s;
}

struct FacePair {
  camera::SyntheticScene scene;
  camera::SyntheticRender render;
  rp::ReconstructionResult result;
};

// Renders and reconstructs one pair at the standard preset; the master is
// registered by range pole and compass, the others are left unregistered.
inline FacePair photograph_and_reconstruct(const camera::SyntheticScene& scene, bool master) {
  NoProgress progress;
  FacePair p{scene, camera::render_scene(scene, progress), {}};
  const rp::RegistrationSources sources =
      master ? pole_and_compass(scene, p.render, 0.0) : rp::RegistrationSources{};
  p.result = rp::reconstruct(p.render.images[0], p.render.images[1], p.render.intrinsics,
                             p.render.intrinsics, rp::preset_standard(), sources, progress);
  return p;
}

inline rp::FaceImage face_image(const FacePair& p, const std::string& name) {
  return {name, p.render.images[0], p.result.mesh, p.result.accuracy.sigma_z};
}

// Face frame -> scene frame: the master's registration is a pure shift from
// the scene frame when it is right (pole vertical, compass north), so the
// shift is the lower target's true centre minus its registered one.
inline Eigen::Vector3d face_origin(const FacePair& master) {
  return master.render.targets[0].centre -
         master.result.model_to_world.apply(master.result.targets->model[0]);
}

// Distance of a scene-frame point to the true face: the facet whose East
// extent holds it (points within 0.1 m of a facet edge are left out: there
// the nearest facet is ambiguous).
inline std::optional<double> distance_to_face(const Eigen::Vector3d& w) {
  for (const auto& f : synthetic_facets()) {
    if (w.x() < f.x_from + 0.1 || w.x() > f.x_to - 0.1) continue;
    const Eigen::Vector3d n = facet_normal(f);
    const Eigen::Vector3d on(w.x(), facet_y(f, w.x(), w.z()), w.z());
    return std::abs(n.dot(w - on));
  }
  return std::nullopt;
}

}  // namespace rockface::testing

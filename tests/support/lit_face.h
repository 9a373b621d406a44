#pragma once
// The synthetic face (tests/support/synthetic_face.h) under
// the tunnel's lighting effects, reconstructed with the fast preset and
// registered by the range pole and the compass line: what came out against
// the truth, or the message that refused it. Shared by the tests and the
// benchmark (tools/bench/tunnel_lighting_bench.cpp).
#include <optional>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "tests/support/synthetic_truth.h"

namespace rockface::testing {

struct LitFaceOutcome {
  std::optional<TruthComparison> truth;  // reconstructed and registered
  std::string refusal;                   // else what refused it ("where: reason")
  camera::SyntheticRender render;
  photogrammetry::ViewShading shading;  // how the views' shading differed (view_shading.h)
  bool shading_normalised = false;      // dense matching ran on normalised images for it
  std::vector<std::string> warnings;    // the reconstruction's
};

// The face with each facet dipping as synthetic_facets() says, 1200 x 800.
inline camera::SyntheticScene lit_face(const camera::SyntheticEffects& effects) {
  camera::SyntheticScene s = synthetic_face(1200, 800);
  s.effects = effects;
  return s;
}

inline LitFaceOutcome reconstruct_lit_face(const camera::SyntheticScene& scene) {
  NoProgress progress;
  LitFaceOutcome out;
  out.render = camera::render_scene(scene, progress);
  try {
    const auto result = photogrammetry::reconstruct(
        out.render.images[0], out.render.images[1], out.render.intrinsics, out.render.intrinsics,
        photogrammetry::preset_fast(), pole_and_compass(scene, out.render, 0.0), progress);
    out.shading = result.view_shading;
    out.shading_normalised = result.shading_normalised;
    out.warnings = result.accuracy.warnings;
    out.truth = compare_with_truth(scene, out.render, result);
  } catch (const InputError& e) {
    out.refusal = e.what();
  }
  return out;
}

}  // namespace rockface::testing

// End to end on the synthetic mock camera: render a faceted rock face with a
// range pole, reconstruct it with the standard preset, register it by the
// pole (scale, vertical) and the compass bearing of a reference line (north),
// and compare the surface with the truth.
#include <gtest/gtest.h>

#include "tests/support/synthetic_truth.h"

namespace rp = rockface::photogrammetry;
using rockface::testing::TruthComparison;

namespace {

struct Outcome {
  TruthComparison truth;
  rp::ReconstructionResult result;
};

Outcome reconstruct_and_compare(const rockface::camera::SyntheticScene& scene, double declination) {
  rockface::NoProgress progress;
  const auto render = rockface::camera::render_scene(scene, progress);
  Outcome out;
  out.result =
      rp::reconstruct(render.images[0], render.images[1], render.intrinsics, render.intrinsics,
                      rp::preset_standard(),
                      rockface::testing::pole_and_compass(scene, render, declination), progress);
  out.truth = rockface::testing::compare_with_truth(scene, render, out.result);
  return out;
}

void expect_registered(const Outcome& out) {
  const TruthComparison& o = out.truth;
  // Each facet is measured on thousands of points (it covers ~1/6 of the frame).
  EXPECT_GT(o.facet_points_min, 2000u);
  // The accuracy bar for the standard preset: facet orientations
  // within 1 deg, scale within 0.5 %, north within 1 deg. Expected errors are
  // far smaller: sigma_Z ~ 2 cm per point at 10 m is averaged over thousands
  // of points per facet (normal error ~0.1 deg); the pole's target centres
  // are good to ~0.05 px, i.e. ~0.03 % of its 2 m length.
  EXPECT_LT(o.worst_facet_deg, 1.0);
  EXPECT_LT(std::abs(o.scale_error), 0.005);
  EXPECT_LT(std::abs(o.north_error_deg), 1.0);
  // The pole defines the vertical; its tilt error is the targets' depth
  // error (~3 mm at 7 m) over its 2 m length: ~0.1 deg.
  EXPECT_LT(o.vertical_error_deg, 0.5);
  // After area matching the tie points are good to < 0.1 px; with ~2000 of
  // them the rotation is determined to ~0.005 deg (the refinement's own
  // sigma). 0.05 deg allows for the texture's residual matching bias.
  EXPECT_LT(o.rotation_error_deg, 0.05);
  EXPECT_LT(o.direction_error_deg, 0.2);
  // Targets ~38 px across, edges located along ~200 rays: the corrected
  // centre is good to ~0.02 px (noise and blur included).
  EXPECT_LT(o.worst_target_px, 0.05);
  // registration.h: the lower target is the frame's origin, compass or not.
  // The pole registration puts it there exactly and north turns about the
  // vertical through it: only rounding is left (~1e-15 m at metres).
  EXPECT_LT(o.lower_target_offset_m, 1e-9);
  EXPECT_TRUE(out.result.scaled);
  EXPECT_EQ(out.result.north_source, "compass");
}

}  // namespace

TEST(SyntheticReconstruction, CleanImagesStandardPreset) {
  const Outcome o = reconstruct_and_compare(rockface::testing::synthetic_face(), 4.0);
  expect_registered(o);
  // Base/distance 1.6/10 is inside 1/8 .. 1/5 and the pole targets are
  // ~38 px across: no warning at all.
  for (const auto& w : o.result.accuracy.warnings) ADD_FAILURE() << "unexpected warning: " << w;
}

TEST(SyntheticReconstruction, DistortionNoiseAndBlur) {
  const Outcome o =
      reconstruct_and_compare(rockface::testing::synthetic_face(1200, 800, true, 2.0), -2.5);
  expect_registered(o);
}

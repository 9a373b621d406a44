// Facets on rendered and reconstructed faces (the mock camera's synthetic
// renderer, the fast preset at 900 x 600 to keep CI short): a stepped face
// whose steps are the exposed faces of two joint sets of known orientation
// and spacing, and a flat wall with no joint. The stations, range pole and
// camera are those of the reconstruction tests' face (synthetic_face.h),
// so the registration by pole and compass is the one those tests bound.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/common/units.h"
#include "core/measure/facets/facet_sets.h"
#include "core/measure/facets/facets.h"
#include "tests/integration_reconstruct/synthetic_truth.h"

namespace rm = rockface::measure;
namespace rp = rockface::photogrammetry;
namespace rg = rockface::geometry;
using rockface::deg_to_rad;
using rockface::rad_to_deg;

namespace {

// Set A (60/220) and set B (60/140) in strips 1.2 m wide: their ridges are
// the sets' intersection lines (constant East), so each strip is a quad.
constexpr double kDip = 60, kDipDir = 220, kStrip = 1.2;

Eigen::Vector3d normal_a() {
  return rg::plane_normal_deg(kDip, kDipDir);
}
Eigen::Vector3d normal_b() {
  return rg::plane_normal_deg(kDip, 360 - kDipDir);
}
Eigen::Vector3d n_wall() {
  return rg::plane_normal_deg(80, 185);
}

struct Rendered {
  rockface::camera::SyntheticScene scene;
  rp::ReconstructionResult rec;
};

Rendered render_and_reconstruct(rockface::camera::SyntheticScene scene) {
  rockface::NoProgress progress;
  Rendered r;
  const auto render = rockface::camera::render_scene(scene, progress);
  r.rec = rp::reconstruct(render.images[0], render.images[1], render.intrinsics, render.intrinsics,
                          rp::preset_fast(),
                          rockface::testing::pole_and_compass(scene, render, 0.0), progress);
  r.scene = std::move(scene);
  return r;
}

// A strip of plane n through (x, y, 0) from x to x + width, z in [-2.5, 3.5].
rockface::camera::SyntheticPatch strip(const Eigen::Vector3d& n, double x, double y, double width) {
  auto y_at = [&](double px, double pz) { return y - (n.x() * (px - x) + n.z() * pz) / n.y(); };
  rockface::camera::SyntheticPatch p;
  p.id = "strip";
  for (auto [px, pz] : {std::pair{x, -2.5}, {x + width, -2.5}, {x + width, 3.5}, {x, 3.5}})
    p.polygon.emplace_back(px, y_at(px, pz), pz);
  return p;
}

const Rendered& stepped() {
  static const Rendered r = [] {
    auto scene = rockface::testing::synthetic_face(900, 600);
    scene.patches.clear();
    double x = -4.2, y = 10.0;
    for (int i = 0; i < 7; ++i, x += kStrip) {
      const Eigen::Vector3d n = i % 2 == 0 ? normal_a() : normal_b();
      scene.patches.push_back(strip(n, x, y, kStrip));
      y -= n.x() * kStrip / n.y();
    }
    // The compass line across the middle (B) strip, at z 1.8 and 2.0.
    const auto& mid = scene.patches[3].polygon;  // x from -0.6 to 0.6
    auto on_mid = [&](double px, double pz) {
      const Eigen::Vector3d n = normal_b();
      return Eigen::Vector3d(
          px, mid[0].y() - (n.x() * (px - mid[0].x()) + n.z() * (pz + 2.5)) / n.y(), pz);
    };
    scene.reference_line = {{on_mid(-0.5, 1.8), on_mid(0.5, 2.0)}};
    return render_and_reconstruct(std::move(scene));
  }();
  return r;
}

rm::MeasureSettings settings_of(const rp::ReconstructionResult& rec) {
  rm::MeasureSettings s;
  s.point_sigma = rec.accuracy.sigma_z;
  s.correlation_length = rec.point_spacing * rp::preset_fast().sgbm_block_size;
  return s;
}

rm::FacetSearch facets_of(const rp::ReconstructionResult& rec) {
  rockface::NoProgress progress;
  return rm::find_facets(rec.mesh, settings_of(rec), rm::facet_options(rockface::Preset::fast),
                         progress);
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

// The error a facet's orientation may have: 3 of its own sigmas (the fit
// of its points under the reconstruction's sigma_Z, one independent point
// per matching window), plus the frame: registration by range pole and
// compass on this camera and pole is good to 0.5 deg of tilt and 1 deg
// about the vertical (integration_reconstruct asserts both); a turn about
// the vertical moves a normal by that angle times sin(dip).
double allowed_deg(const rm::Facet& f) {
  return 3 * rad_to_deg(f.plane.sigma) + 0.5 + 1.0 * std::sin(f.plane.orientation.dip);
}

}  // namespace

TEST(FacetsOnReconstruction, SteppedFaceFacetsHaveTheirSetsOrientation) {
  const Rendered& r = stepped();
  const rm::FacetSearch found = facets_of(r.rec);
  // The seven strips, each 1.2 m x 6 m; the outer ones are cut by the image
  // (the left photograph sees x from about -4.6 to 4.6 m at 10 m) but stay
  // metres square. Steps of the dense matching at the ridges may split a
  // strip: at least the seven, at most twice as many.
  std::printf("sigma_Z %.4f m, %zu facets, %.1f of %.1f m2\n", r.rec.accuracy.sigma_z,
              found.facets.size(), found.facet_area, found.mapped_area);
  ASSERT_GE(found.facets.size(), 7u);
  EXPECT_LE(found.facets.size(), 14u);
  int big = 0;
  for (const rm::Facet& f : found.facets) {
    const double to_a = angle_deg(f.plane.fit.normal, normal_a());
    const double to_b = angle_deg(f.plane.fit.normal, normal_b());
    std::printf("F%d %.1f/%.1f sigma %.3f deg area %.2f m2: %.2f deg off its set (allowed %.2f)\n",
                f.id, rad_to_deg(f.plane.orientation.dip), rad_to_deg(f.plane.orientation.dipdir),
                rad_to_deg(f.plane.sigma), f.area, std::min(to_a, to_b), allowed_deg(f));
    EXPECT_LT(std::min(to_a, to_b), allowed_deg(f)) << "F" << f.id;
    big += f.area > 3.0;
  }
  EXPECT_GE(big, 7);  // every strip is found as a facet of metres square
}

TEST(FacetsOnReconstruction, SteppedFaceGivesTheTwoSetsWithTheirSpacing) {
  const Rendered& r = stepped();
  const rm::FacetSearch found = facets_of(r.rec);
  const rm::FacetSets sets = rm::facet_sets(found);
  ASSERT_EQ(sets.sets.size(), 2u);
  for (const rm::FacetSet& s : sets.sets) {
    const Eigen::Vector3d mean = s.summary.fisher.mean;
    const bool is_a = angle_deg(mean, normal_a()) < angle_deg(mean, normal_b());
    const double error = angle_deg(mean, is_a ? normal_a() : normal_b());
    std::printf("%s %s: %zu facets, %d planes, K %.0f, error %.2f deg, spacing %.3f m\n",
                s.summary.label.c_str(), is_a ? "A" : "B", s.facet_ids.size(), s.planes,
                s.summary.fisher.kappa, error, s.summary.spacing.value_or(-1));
    // The mean's own alpha95 plus the frame's 0.5 + 0.87 deg (allowed_deg).
    EXPECT_LT(error, rad_to_deg(s.summary.fisher.alpha95) + 0.5 + std::sin(deg_to_rad(kDip)));
    // A has four strips, B three: each on that many distinct planes.
    EXPECT_EQ(s.planes, is_a ? 4 : 3);
    ASSERT_TRUE(s.summary.spacing);
    // The true spacing, 2 x strip x |n_x| = 1.84 m. The measured one is the
    // spread of the facets' centroids along the mean normal over the gaps:
    // each centroid lies on its strip within sigma_Z / sqrt(n) (sub-mm),
    // but a tilt of the mean normal by e (rad) moves centroids up to the
    // face's half-width (4 m) apart by 4 e: 1.9 deg of error (the bound
    // above) gives 0.13 m over 3 to 2 gaps, 0.07 m per gap.
    const double truth = 2 * kStrip * std::abs(normal_a().x());
    EXPECT_NEAR(*s.summary.spacing, truth, 0.07 + truth * 0.02);
  }
}

TEST(FacetsOnReconstruction, FlatWallWithoutJointsGivesNoSet) {
  // A flat wall (80/185, as a face dressed by sprayed concrete): rendered
  // with the rock texture the stereo needs (real shotcrete shows its spray
  // texture; a surface with none gives no 3D image at all).
  static const Rendered r = [] {
    auto scene = rockface::testing::synthetic_face(900, 600);
    scene.patches.clear();
    const Eigen::Vector3d n = n_wall();
    rockface::camera::SyntheticPatch wall;
    wall.id = "wall";
    for (auto [x, z] : {std::pair{-6.0, -2.5}, {6.0, -2.5}, {6.0, 3.5}, {-6.0, 3.5}})
      wall.polygon.emplace_back(x, 10.0 - (n.x() * x + n.z() * (z - 0.5)) / n.y(), z);
    scene.patches.push_back(wall);
    auto on_wall = [&](double x, double z) {
      return Eigen::Vector3d(x, 10.0 - (n.x() * x + n.z() * (z - 0.5)) / n.y(), z);
    };
    scene.reference_line = {{on_wall(-1.0, 1.8), on_wall(1.0, 2.2)}};
    return render_and_reconstruct(std::move(scene));
  }();
  const rm::FacetSearch found = facets_of(r.rec);
  ASSERT_FALSE(found.facets.empty());
  // The wall is found (so "no set" is a verdict, not a failure to see it):
  // its largest facet covers most of the mapped surface at the wall's
  // orientation, within allowed_deg.
  EXPECT_GT(found.facets[0].area, 0.5 * found.mapped_area);
  EXPECT_LT(angle_deg(found.facets[0].plane.fit.normal, n_wall()), allowed_deg(found.facets[0]));
  const rm::FacetSets sets = rm::facet_sets(found);
  EXPECT_TRUE(sets.sets.empty());
  ASSERT_FALSE(sets.not_sets.empty());
  std::printf("%zu facets; %s\n", found.facets.size(), sets.not_sets[0].reason.c_str());
}

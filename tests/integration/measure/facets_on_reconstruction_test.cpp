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
#include "tests/support/synthetic_truth.h"

namespace rm = rockface::measure;
namespace rp = rockface::photogrammetry;
namespace rg = rockface::geometry;
using rockface::deg_to_rad;
using rockface::rad_to_deg;

namespace {

// Set A (60/200) and set B (60/160) in strips 1.2 m wide: their ridges are
// the sets' intersection lines (constant East), so each strip is a quad.
// The strips run from z = -4.5 to 5.5 m, beyond the photographs: a face
// that fills the frame (where a surface ends against the background, dense
// matching smears it into a ledge that would be a facet of its own).
constexpr double kDip = 60, kDipDir = 200, kStrip = 1.2;

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
  // The registered frame's origin in the scene: the range pole's lower
  // target (synthetic_truth.h).
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

Rendered render_and_reconstruct(rockface::camera::SyntheticScene scene) {
  rockface::NoProgress progress;
  Rendered r;
  const auto render = rockface::camera::render_scene(scene, progress);
  r.origin = render.targets[0].centre;
  r.rec = rp::reconstruct(render.images[0], render.images[1], render.intrinsics, render.intrinsics,
                          rp::preset_fast(),
                          rockface::testing::pole_and_compass(scene, render, 0.0), progress);
  r.scene = std::move(scene);
  return r;
}

// A strip of plane n through (x, y, 0) from x to x + width, z in [-4.5, 5.5].
rockface::camera::SyntheticPatch strip(const Eigen::Vector3d& n, double x, double y, double width) {
  auto y_at = [&](double px, double pz) { return y - (n.x() * (px - x) + n.z() * pz) / n.y(); };
  rockface::camera::SyntheticPatch p;
  p.id = "strip";
  for (auto [px, pz] : {std::pair{x, -4.5}, {x + width, -4.5}, {x + width, 5.5}, {x, 5.5}})
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
          px, mid[0].y() - (n.x() * (px - mid[0].x()) + n.z() * (pz + 4.5)) / n.y(), pz);
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
// about the vertical (integration/reconstruct asserts both); a turn about
// the vertical moves a normal by that angle times sin(dip).
double allowed_deg(const rm::Facet& f) {
  return 3 * rad_to_deg(f.plane.sigma) + 0.5 + 1.0 * std::sin(f.plane.orientation.dip);
}

}  // namespace

TEST(FacetsOnReconstruction, SteppedFaceFacetsHaveTheirSetsOrientation) {
  const Rendered& r = stepped();
  const rm::FacetSearch found = facets_of(r.rec);
  // The seven strips, each 1.2 m wide and higher than the photographs. The
  // dense matching's steps and holes may split a strip: at least the seven
  // facets, at most three per strip.
  std::printf("sigma_Z %.4f m, %zu facets, %.1f of %.1f m2\n", r.rec.accuracy.sigma_z,
              found.facets.size(), found.facet_area, found.mapped_area);
  ASSERT_GE(found.facets.size(), 7u);
  EXPECT_LE(found.facets.size(), 21u);
  for (const rm::Facet& f : found.facets) {
    const double to_a = angle_deg(f.plane.fit.normal, normal_a());
    const double to_b = angle_deg(f.plane.fit.normal, normal_b());
    const Eigen::Vector3d c = f.centroid + r.origin;
    std::printf(
        "F%d at (%.1f %.1f %.1f) %.1f/%.1f sigma %.3f deg area %.2f m2: %.2f deg off its set "
        "(allowed %.2f)\n",
        f.id, c.x(), c.y(), c.z(), rad_to_deg(f.plane.orientation.dip),
        rad_to_deg(f.plane.orientation.dipdir), rad_to_deg(f.plane.sigma), f.area,
        std::min(to_a, to_b), allowed_deg(f));
    EXPECT_LT(std::min(to_a, to_b), allowed_deg(f)) << "F" << f.id;
  }
  // Every strip the 3D image maps well is found: a facet of its set with
  // its centroid on it. Well: 6 m2 or more of it. The six inner strips map
  // 7.3 to 9.8 m2; the outermost (x 3.0 to 4.2, set A, at the edge of the
  // right photograph) maps 5.1 m2 in pieces cut by the matching's holes
  // and gets no facet: a known limit, said in docs/accuracy-cost.md. (Until stop 34 this check read
  // the mesh in a frame shifted by the compass's pivot, which hid it.)
  for (const auto& p : r.scene.patches) {
    const Eigen::Vector3d n =
        (p.polygon[1] - p.polygon[0]).cross(p.polygon[2] - p.polygon[0]).normalized();
    double mapped = 0;
    const auto& mesh = r.rec.mesh;
    for (const auto& t : mesh.triangles) {
      const Eigen::Vector3d a = mesh.vertices[t[0]], b = mesh.vertices[t[1]],
                            c = mesh.vertices[t[2]];
      const double x = (a + b + c).x() / 3 + r.origin.x();
      if (x > p.polygon[0].x() && x < p.polygon[1].x()) mapped += 0.5 * (b - a).cross(c - a).norm();
    }
    std::printf("strip from x = %.1f: %.2f m2 mapped\n", p.polygon[0].x(), mapped);
    if (mapped < 6.0) continue;
    const bool seen =
        std::any_of(found.facets.begin(), found.facets.end(), [&](const rm::Facet& f) {
          const Eigen::Vector3d c = f.centroid + r.origin;
          return c.x() > p.polygon[0].x() && c.x() < p.polygon[1].x() &&
                 angle_deg(f.plane.fit.normal, n) < allowed_deg(f);
        });
    EXPECT_TRUE(seen) << "the strip from x = " << p.polygon[0].x() << ", " << mapped
                      << " m2 mapped";
  }
}

TEST(FacetsOnReconstruction, SteppedFaceGivesTheTwoSetsWithTheirSpacing) {
  const Rendered& r = stepped();
  const rm::FacetSearch found = facets_of(r.rec);
  const rm::FacetSets sets = rm::facet_sets(found);
  for (const auto& c : sets.not_sets)
    std::printf("not a set (%zu facets, %.2f m2): %s\n", c.facet_ids.size(), c.area,
                c.reason.c_str());
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
    // A has four strips, B three (the outermost A strip is mostly outside
    // the right photograph): each strip found is a plane of its own.
    EXPECT_GE(s.planes, 3);
    EXPECT_LE(s.planes, is_a ? 4 : 3);
    ASSERT_TRUE(s.summary.spacing);
    // The true spacing, 2 x strip x |n_x| = 0.71 m. The measured one is the
    // spread of the facets' centroids along the mean normal over the gaps:
    // each centroid lies on its strip within sigma_Z / sqrt(n) (sub-mm),
    // but a tilt of the mean normal by e (rad) moves centroids up to the
    // face's half-width (4 m) apart by 4 e: 1.9 deg of error (the bound
    // above) gives 0.13 m over 2 or 3 gaps, under 0.07 m per gap.
    const double truth = 2 * kStrip * std::abs(normal_a().x());
    EXPECT_NEAR(*s.summary.spacing, truth, 0.07);
  }
}

// A flat wall (80/185, as a face dressed by sprayed concrete) standing on
// a flat floor (a scene of one plane is degenerate for relative
// orientation). Rendered with the rock texture the stereo needs (real
// shotcrete shows its spray texture; a surface with none gives no 3D
// image at all). No joints: two surfaces of one plane each, no set.
namespace {

const Rendered& flat_wall() {
  static const Rendered r = [] {
    auto scene = rockface::testing::synthetic_face(900, 600);
    scene.patches.clear();
    const Eigen::Vector3d n = n_wall();
    auto on_wall = [&](double x, double z) {
      return Eigen::Vector3d(x, 10.0 - (n.x() * x + n.z() * (z - 0.5)) / n.y(), z);
    };
    rockface::camera::SyntheticPatch wall;
    wall.id = "wall";
    for (auto [x, z] : {std::pair{-6.0, -2.5}, {6.0, -2.5}, {6.0, 5.5}, {-6.0, 5.5}})
      wall.polygon.push_back(on_wall(x, z));
    scene.patches.push_back(wall);
    rockface::camera::SyntheticPatch floor;
    floor.id = "floor";
    floor.polygon = {{-6.0, 4.0, -2.5}, on_wall(-6.0, -2.5), on_wall(6.0, -2.5), {6.0, 4.0, -2.5}};
    scene.patches.push_back(floor);
    // The cameras look down 12 deg so that the floor fills the lower third
    // of the photographs; the compass line is on the wall at eye height.
    for (auto& station : scene.stations) station.look_at.z() = -1.5;
    scene.reference_line = {{on_wall(-1.0, 0.0), on_wall(1.0, 0.2)}};
    return render_and_reconstruct(std::move(scene));
  }();
  return r;
}

}  // namespace

TEST(FacetsOnReconstruction, FlatWallWithoutJointsGivesNoSet) {
  const Rendered& r = flat_wall();
  const rm::FacetSearch found = facets_of(r.rec);
  // The wall is found (so "no set" is a verdict, not a failure to see it):
  // a facet at its orientation (within allowed_deg) of at least 10 m2, a
  // sixth of the wall the photographs see.
  const auto wall = std::find_if(found.facets.begin(), found.facets.end(), [&](const rm::Facet& f) {
    return angle_deg(f.plane.fit.normal, n_wall()) < allowed_deg(f);
  });
  ASSERT_NE(wall, found.facets.end());
  EXPECT_GT(wall->area, 10.0);
  const rm::FacetSets sets = rm::facet_sets(found);
  for (const rm::Facet& f : found.facets) {
    const Eigen::Vector3d c = f.centroid + r.origin;
    std::printf("F%d at (%.1f %.1f %.1f) %.1f/%.1f sigma %.3f deg area %.2f m2\n", f.id, c.x(),
                c.y(), c.z(), rad_to_deg(f.plane.orientation.dip),
                rad_to_deg(f.plane.orientation.dipdir), rad_to_deg(f.plane.sigma), f.area);
  }
  for (const auto& s : sets.sets)
    std::printf("set %s: %zu facets on %d planes\n", s.summary.label.c_str(), s.facet_ids.size(),
                s.planes);
  EXPECT_TRUE(sets.sets.empty());
  // The wall in pieces (until the plane-led growing of issue 38 it came in
  // two, 23.5 and 9.9 m2) is listed as one surface, not a set; the wall as
  // one facet makes no cluster at all (a cluster needs two facets).
  const auto wall_pieces = std::count_if(
      found.facets.begin(), found.facets.end(),
      [&](const rm::Facet& f) { return angle_deg(f.plane.fit.normal, n_wall()) < allowed_deg(f); });
  if (wall_pieces > 1) {
    ASSERT_FALSE(sets.not_sets.empty());
  }
  std::printf("%zu facets, the wall's %.1f m2 of %.1f m2 mapped\n", found.facets.size(), wall->area,
              found.mapped_area);
  for (const auto& c : sets.not_sets) std::printf("not a set: %s\n", c.reason.c_str());
}

// The area of the regions that failed the planarity tests is only what no
// facet took in the end: a region refused by the first pass may be taken
// later, by the plane-led pass or as a step between merged terraces, and
// was then counted twice (on the flat wall: 7.4 m2 "not planar" beside
// 48.7 m2 of facets, 56.1 m2 in all of 52.4 m2 mapped). Facets, rejected
// regions and the rest are disjoint parts of the mapped surface: their sums
// are of the same triangles' areas, equal up to rounding (1e-9 m2).
TEST(FacetsOnReconstruction, RejectedAreaIsNotAlsoInAFacet) {
  for (const Rendered* r : {&flat_wall(), &stepped()}) {
    const rm::FacetSearch found = facets_of(r->rec);
    std::printf("%.2f m2 of facets, %d regions not planar (%.2f m2), of %.2f m2 mapped\n",
                found.facet_area, found.rejected_regions, found.rejected_area, found.mapped_area);
    EXPECT_LE(found.facet_area + found.rejected_area, found.mapped_area + 1e-9);
    EXPECT_GE(found.rejected_area, 0.0);
    EXPECT_EQ(found.rejected_regions == 0, found.rejected_area == 0.0);
  }
}

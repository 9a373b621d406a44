// Facets on a face seen nearly square (issue 38): dense matching's
// sub-pixel locking leaves terraces, strips a few pixels wide each tilted
// a few degrees the same way, and the facets followed them (a 78-degree
// patch came out as strips 5-8 degrees off its plane, marked marginal,
// never as one facet). The face: two planar patches dipping 78 degrees,
// one facing the stations (dip direction 180, seen square) and one turned
// 40 degrees away (140, seen obliquely: it also makes the scene more than
// one plane, which the relative orientation needs), 10 m in front
// of the reconstruction tests' stations (synthetic_face.h: camera, range
// pole, compass line), rendered at 1200 x 800 with sensor noise,
// reconstructed and searched at the tablet's preset (standard).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/common/units.h"
#include "core/measure/facets/facets.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "tests/support/synthetic_face.h"
#include "tests/support/synthetic_truth.h"

namespace rm = rockface::measure;
namespace rp = rockface::photogrammetry;
namespace rg = rockface::geometry;

namespace {

struct Patch {
  Eigen::Vector3d normal;
  double x_from, x_to;  // East extent, scene frame
};

const Patch kSquare{rg::plane_normal_deg(78, 180), -5.0, 0.0};
const Patch kOblique{rg::plane_normal_deg(78, 140), 0.0, 5.0};

// The patch's plane passes through y = 10, z = 0.5 at its x-centre.
Eigen::Vector3d on_patch(const Patch& p, double x, double z) {
  const double xc = 0.5 * (p.x_from + p.x_to);
  const Eigen::Vector3d& n = p.normal;
  return {x, 10.0 - (n.x() * (x - xc) + n.z() * (z - 0.5)) / n.y(), z};
}

struct Searched {
  rp::ReconstructionResult rec;
  rm::FacetSearch facets;
  Eigen::Vector3d origin;  // the registered frame's origin in the scene (the lower target)
};

const Searched& searched() {
  static const Searched s = [] {
    auto scene = rockface::testing::synthetic_face(1200, 800, false, 2.0);
    scene.patches.clear();
    for (const Patch* p : {&kSquare, &kOblique}) {
      rockface::camera::SyntheticPatch patch;
      patch.id = "P";
      for (auto [x, z] :
           {std::pair{p->x_from, -4.5}, {p->x_to, -4.5}, {p->x_to, 5.5}, {p->x_from, 5.5}})
        patch.polygon.push_back(on_patch(*p, x, z));
      scene.patches.push_back(patch);
    }
    scene.reference_line = {{on_patch(kSquare, -3.0, 1.8), on_patch(kSquare, -1.0, 2.0)}};
    rockface::NoProgress progress;
    const auto render = rockface::camera::render_scene(scene, progress);
    Searched r;
    r.origin = render.targets[0].centre;
    const auto preset = rp::reconstruction_preset(rockface::Preset::standard);
    r.rec =
        rp::reconstruct(render.images[0], render.images[1], render.intrinsics, render.intrinsics,
                        preset, rockface::testing::pole_and_compass(scene, render, 0.0), progress);
    rm::MeasureSettings settings;
    settings.point_sigma = r.rec.accuracy.sigma_z;
    settings.correlation_length = r.rec.point_spacing * preset.sgbm_block_size;
    r.facets = rm::find_facets(r.rec.mesh, settings, rm::facet_options(rockface::Preset::standard),
                               progress);
    return r;
  }();
  return s;
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rockface::rad_to_deg(
      std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

}  // namespace

// The error a facet's orientation may have: 3 of its own sigmas, plus the
// frame (registration by pole and compass: 0.5 deg of tilt, 1 deg about the
// vertical, as facets_on_reconstruction_test.cpp allows).
double allowed_deg(const rm::Facet& f) {
  return 3 * rockface::rad_to_deg(f.plane.sigma) + 0.5 + std::sin(f.plane.orientation.dip);
}

TEST(FacetsSeenSquare, TheTerracesOfAPatchSeenSquareAreOneFacetAtItsOrientation) {
  const Searched& s = searched();
  double patch_facet_area = 0, true_area = 0;
  const rm::Facet* largest = nullptr;
  for (const auto& f : s.facets.facets) {
    const double x = f.centroid.x() + s.origin.x();
    if (x < kSquare.x_from + 0.1 || x > kSquare.x_to - 0.1) continue;
    patch_facet_area += f.area;
    const double error = angle_deg(f.plane.fit.normal, kSquare.normal);
    if (error < allowed_deg(f)) true_area += f.area;
    if (!largest || f.area > largest->area) largest = &f;
  }
  ASSERT_NE(largest, nullptr);
  const double error = angle_deg(largest->plane.fit.normal, kSquare.normal);
  std::printf(
      "seen square (78/180): %.2f m2 of facets, %.2f m2 within the stated error; largest "
      "%.2f m2, %.2f deg off (sigma %.2f)\n",
      patch_facet_area, true_area, largest->area, error,
      rockface::rad_to_deg(largest->plane.sigma));
  // Before, the facets followed the terraces: strips of 0.05-0.16 m2,
  // 6-10 deg off the plane (the terraces' tilt), all marginal; none within
  // the stated error. The strips are merged into the plane they share (its
  // mean is the true plane). Seen: 24.5 m2 of facets, all within the error;
  // the largest 17.6 m2, 0.16 deg off.
  EXPECT_GT(true_area, 0.8 * patch_facet_area);
  EXPECT_GT(largest->area, 10.0);
  EXPECT_FALSE(largest->marginal);
  EXPECT_LT(error, allowed_deg(*largest));
}

// The patch turned 40 deg away (78/140, seen obliquely at about 40 deg):
// dense matching's depth noise and terraces there are spread over a
// plane whose depth changes fast across the image, so the smoothed normals
// of single triangles scatter by more than the angle tolerance and the
// normal-led growing found no facet on it at the standard preset (issue
// 38; 12 smoothing passes would have, at the cost of the stepped faces'
// ridges). Wanted: the patch as one facet at its true orientation, within
// the facet's stated error.
TEST(FacetsSeenSquare, APatchSeenObliquelyIsOneFacetAtItsOrientation) {
  const Searched& s = searched();
  double mapped = 0;  // the patch's own triangles, away from its edges
  const auto& mesh = s.rec.mesh;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const double x = (a + b + c).x() / 3 + s.origin.x();
    if (x > kOblique.x_from + 0.1 && x < kOblique.x_to - 0.1)
      mapped += 0.5 * (b - a).cross(c - a).norm();
  }
  double patch_facet_area = 0, true_area = 0;
  const rm::Facet* largest = nullptr;
  for (const auto& f : s.facets.facets) {
    const double x = f.centroid.x() + s.origin.x();
    if (x < kOblique.x_from + 0.1 || x > kOblique.x_to - 0.1) continue;
    patch_facet_area += f.area;
    if (angle_deg(f.plane.fit.normal, kOblique.normal) < allowed_deg(f)) true_area += f.area;
    if (!largest || f.area > largest->area) largest = &f;
  }
  ASSERT_NE(largest, nullptr) << "no facet on the patch seen obliquely (" << mapped
                              << " m2 mapped there)";
  const double error = angle_deg(largest->plane.fit.normal, kOblique.normal);
  std::printf(
      "seen obliquely (78/140): %.2f m2 mapped, %.2f m2 of facets, %.2f m2 within the stated "
      "error; largest %.2f m2, %.2f deg off (sigma %.2f)\n",
      mapped, patch_facet_area, true_area, largest->area, error,
      rockface::rad_to_deg(largest->plane.sigma));
  // One facet: the largest holds most of the patch's mapped surface (the
  // rest is its border band, where triangles bridge to the other patch or
  // the background), and every facet there is the patch's plane.
  EXPECT_GT(largest->area, 0.5 * mapped);
  EXPECT_GT(true_area, 0.8 * patch_facet_area);
  EXPECT_FALSE(largest->marginal);
  EXPECT_LT(error, allowed_deg(*largest));
}

// Facets on 3D images built without photogrammetry (stepped_face.h): the
// stepped face of two joint sets, a flat wall, a folded face of three
// differently oriented facets, and degenerate meshes.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/measure/facets/facet_outline.h"
#include "core/measure/facets/facet_sets.h"
#include "core/measure/facets/facets.h"
#include "core/measure/tolerances.h"
#include "tests/support/stepped_face.h"

namespace rm = rockface::measure;
namespace rt = rockface::test;
using rockface::rad_to_deg;

namespace {

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

rm::MeasureSettings settings(double sigma) {
  rm::MeasureSettings s;
  s.point_sigma = sigma;
  return s;
}

rm::FacetSearch search(const rockface::photogrammetry::SurfaceMesh& mesh, double sigma,
                       rockface::Preset preset = rockface::Preset::standard) {
  rockface::NoProgress progress;
  return rm::find_facets(mesh, settings(sigma), rm::facet_options(preset), progress);
}

// The true facet (strip) under a found facet's centroid.
const rt::Facet& truth_under(const rt::FoldedFace& face, const rm::Facet& f) {
  for (const auto& t : face.facets)
    if (f.centroid.x() >= t.x_from && f.centroid.x() <= t.x_to) return t;
  return face.facets.front();
}

}  // namespace

TEST(Facets, SteppedFaceGivesEachStripAsAFacetAtItsTrueOrientation) {
  // 5 mm of depth noise along the rays, each point independent.
  const rt::SteppedTruth truth;
  const double sigma = 0.005;
  const rt::FoldedFace face = rt::stepped_face(truth, 800, 600, sigma);
  const rm::FacetSearch found = search(face.mesh, sigma);
  // Twelve strips in the image, each at least 0.75 m x 4.5 m: every one is a
  // facet (the outermost may be cut by the image border but stay > 1 m2).
  ASSERT_EQ(found.facets.size(), face.facets.size());
  for (const rm::Facet& f : found.facets) {
    const rt::Facet& t = truth_under(face, f);
    // The fit's own one-sigma (plane_of_points: the noise over sqrt(n) and
    // the relief) holds the error of independent noise: 3 sigma is 99.7 %.
    EXPECT_LT(angle_deg(f.plane.fit.normal, t.plane.normal), 3 * rad_to_deg(f.plane.sigma))
        << "facet " << f.id;
    // Its points are on the true plane: the centroid within 3 noise sigmas.
    EXPECT_LT(std::abs(t.plane.signed_distance(f.centroid)), 3 * sigma) << "facet " << f.id;
    // The facet is the strip without the ridge's smoothed band: at least half
    // of the strip's 0.75 m width, at most all of it (normal to the ridge).
    EXPECT_GT(f.plane.fit.relief(), 0.5 * truth.strip / std::sqrt(12.0));
    EXPECT_GT(f.planarity_margin_sigmas, 0);
    EXPECT_GT(f.orientation_margin_deg, 0);
    ASSERT_GE(f.outline.size(), 4u);
    for (const auto& p : f.outline) {
      // Outline points are mesh vertices: on the plane within the noise (4
      // sigma is the growing's gate), inside the strip up to one lattice
      // step (the triangles straddle nothing: a ridge triangle is in no
      // facet).
      EXPECT_LT(std::abs(t.plane.signed_distance(p)), 4 * sigma + 1e-9);
      EXPECT_GE(p.x(), t.x_from - 0.05);
      EXPECT_LE(p.x(), t.x_to + 0.05);
    }
  }
  // Largest first, ids 1..n.
  for (std::size_t i = 0; i < found.facets.size(); ++i) {
    EXPECT_EQ(found.facets[i].id, static_cast<int>(i) + 1);
    if (i > 0) {
      EXPECT_LE(found.facets[i].area, found.facets[i - 1].area);
    }
  }
  EXPECT_LT(found.facet_area, found.mapped_area);
  EXPECT_GT(found.facet_area, 0.7 * found.mapped_area);  // the ridges' bands are the rest
}

TEST(Facets, SteppedFaceGivesTwoSetsWithTheirSpacing) {
  const rt::SteppedTruth truth;
  const double sigma = 0.005;
  const rt::FoldedFace face = rt::stepped_face(truth, 800, 600, sigma);
  const rm::FacetSearch found = search(face.mesh, sigma);
  const rm::FacetSets sets = rm::facet_sets(found);
  ASSERT_EQ(sets.sets.size(), 2u);
  EXPECT_TRUE(sets.not_sets.empty());
  for (const rm::FacetSet& s : sets.sets) {
    const Eigen::Vector3d mean = s.summary.fisher.mean;
    const bool is_a = angle_deg(mean, truth.normal_a()) < angle_deg(mean, truth.normal_b());
    const Eigen::Vector3d true_normal = is_a ? truth.normal_a() : truth.normal_b();
    // The mean of six facets, each within 3 of its sigmas (< 0.3 deg here):
    // alpha95 is the set's own bound of the mean.
    EXPECT_LT(angle_deg(mean, true_normal), std::max(rad_to_deg(s.summary.fisher.alpha95), 0.3));
    EXPECT_EQ(s.facet_ids.size(), 6u);
    EXPECT_EQ(s.planes, 6);
    // Parallel facets of one set: K in the thousands (sub-degree scatter).
    EXPECT_GT(s.summary.fisher.kappa, 1000);
    ASSERT_TRUE(s.summary.spacing);
    // Centroids lie on their strip planes within 3 sigma / sqrt(n): the
    // mean gap over five gaps is good to a millimetre; 1 cm allows for the
    // strips cut by the image border (their centroids move, not their plane).
    EXPECT_NEAR(*s.summary.spacing, truth.spacing(), 0.01);
  }
  for (std::size_t i = 0; i < found.facets.size(); ++i) EXPECT_GE(sets.set_of[i], 0);
}

TEST(Facets, FlatWallIsOneFacetAndNoSet) {
  // A shotcrete wall: one plane, 8 mm of noise, no joints.
  const double sigma = 0.008;
  const rt::FoldedFace wall = rt::flat_wall(80, 185, 800, 600, sigma);
  for (const auto preset :
       {rockface::Preset::fast, rockface::Preset::standard, rockface::Preset::precise}) {
    const rm::FacetSearch found = search(wall.mesh, sigma, preset);
    ASSERT_FALSE(found.facets.empty()) << rockface::preset_name(preset);
    // The wall itself is found, as one facet over more than the share at
    // which it counts as the excavation surface (kFaceShare): the "no set"
    // below is a verdict on the wall, not a failure to see it. (The rest
    // are triangles whose smoothed normals stray beyond the tolerance under
    // 8 mm of noise on a 3 cm lattice.)
    EXPECT_GT(found.facets[0].area, rm::kFaceShare * found.mapped_area)
        << rockface::preset_name(preset);
    EXPECT_LT(angle_deg(found.facets[0].plane.fit.normal, wall.facets[0].plane.normal),
              3 * rad_to_deg(found.facets[0].plane.sigma));
    const rm::FacetSets sets = rm::facet_sets(found);
    EXPECT_TRUE(sets.sets.empty()) << rockface::preset_name(preset);
    ASSERT_FALSE(sets.not_sets.empty());
    EXPECT_NE(sets.not_sets[0].reason.find("excavation surface"), std::string::npos)
        << sets.not_sets[0].reason;
  }
}

TEST(Facets, PiecesOfOnePlaneAreOneSurfaceNotASet) {
  // The folded face's three facets differ by 27 to 58 degrees: three
  // facets, three clusters of one plane each, no set.
  const rt::FoldedFace face = rt::folded_face(800, 600, 0.004);
  const rm::FacetSearch found = search(face.mesh, 0.004);
  ASSERT_EQ(found.facets.size(), 3u);
  for (const rm::Facet& f : found.facets)
    EXPECT_LT(angle_deg(f.plane.fit.normal, truth_under(face, f).plane.normal),
              3 * rad_to_deg(f.plane.sigma));
  const rm::FacetSets sets = rm::facet_sets(found);
  EXPECT_TRUE(sets.sets.empty());
}

TEST(Facets, RoughSurfaceBeyondThePlanarityTestGivesNoFacet) {
  // Noise of 3 cm on a wall whose precision is claimed at 5 mm: nothing is
  // planar to 4 sigma, so no facet (and no confident wrong plane).
  const rt::FoldedFace wall = rt::flat_wall(80, 185, 400, 300, 0.03);
  const rm::FacetSearch found = search(wall.mesh, 0.005);
  EXPECT_TRUE(found.facets.empty());
  EXPECT_FALSE(found.notes.empty());
}

TEST(Facets, DegenerateMeshesGiveNoFacetAndSayWhy) {
  rockface::photogrammetry::SurfaceMesh empty;
  auto found = search(empty, 0.005);
  EXPECT_TRUE(found.facets.empty());
  ASSERT_EQ(found.notes.size(), 1u);
  EXPECT_NE(found.notes[0].find("no triangles"), std::string::npos);
  EXPECT_TRUE(rm::facet_sets(found).sets.empty());

  // Collinear vertices and indices out of range: no usable triangle.
  rockface::photogrammetry::SurfaceMesh line;
  line.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  line.triangles = {{0, 1, 2}, {0, 1, 7}, {0, 0, 1}};
  found = search(line, 0.005);
  EXPECT_TRUE(found.facets.empty());
  ASSERT_EQ(found.notes.size(), 1u);
  EXPECT_NE(found.notes[0].find("no usable triangle"), std::string::npos);

  // One small triangle: below every preset's minimum area.
  rockface::photogrammetry::SurfaceMesh tiny;
  tiny.vertices = {{0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}};
  tiny.triangles = {{0, 1, 2}};
  found = search(tiny, 0.005);
  EXPECT_TRUE(found.facets.empty());
  EXPECT_FALSE(found.notes.empty());
}

TEST(Facets, KnobsOutOfRangeAreRefusedByName) {
  rockface::NoProgress progress;
  const rt::FoldedFace wall = rt::flat_wall(80, 185, 100, 80);
  rm::FacetOptions o = rm::facet_options(rockface::Preset::fast);
  o.angle_tolerance_deg = 0;
  try {
    rm::find_facets(wall.mesh, settings(0.005), o, progress);
    FAIL() << "an angle tolerance of 0 was accepted";
  } catch (const rockface::InputError& e) {
    EXPECT_EQ(e.where(), "facets.angle_tolerance_deg");
  }
  o = rm::facet_options(rockface::Preset::fast);
  o.min_area_m2 = -1;
  EXPECT_THROW(rm::find_facets(wall.mesh, settings(0.005), o, progress), rockface::InputError);
  EXPECT_THROW(
      rm::find_facets(wall.mesh, settings(0), rm::facet_options(rockface::Preset::fast), progress),
      rockface::InputError);
}

TEST(Facets, PresetsOrderTheirKnobs) {
  const auto fast = rm::facet_options(rockface::Preset::fast);
  const auto standard = rm::facet_options(rockface::Preset::standard);
  const auto precise = rm::facet_options(rockface::Preset::precise);
  EXPECT_GT(fast.angle_tolerance_deg, standard.angle_tolerance_deg);
  EXPECT_GT(standard.angle_tolerance_deg, precise.angle_tolerance_deg);
  EXPECT_GT(fast.min_area_m2, standard.min_area_m2);
  EXPECT_GT(standard.min_area_m2, precise.min_area_m2);
  EXPECT_LT(fast.smoothing_passes, precise.smoothing_passes);
}

TEST(Facets, ThinningKeepsTheCornersOfAnOutline) {
  // A square with 100 points per side thins to its four corners.
  std::vector<Eigen::Vector3d> loop;
  const Eigen::Vector3d corners[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 100; ++i)
      loop.push_back(corners[k] + (corners[(k + 1) % 4] - corners[k]) * (i / 100.0));
  const auto thin = rm::thin_closed_polyline(loop, 0.001);
  ASSERT_EQ(thin.size(), 4u);
  for (const auto& c : corners)
    EXPECT_TRUE(std::any_of(thin.begin(), thin.end(),
                            [&](const Eigen::Vector3d& p) { return (p - c).norm() < 1e-12; }));
}

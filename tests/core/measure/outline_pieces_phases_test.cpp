// The phases of split_outline (outline_pieces_phases.h), each on its own,
// on a noise-free fold of two walls 12 degrees apart: the precision pieces
// are judged with, the 3D image inside the outline, every point labelled to
// its wall, a plane with no part of the face dropped (and with it the
// split), the walls touching, and the outline cut in two along the fold.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/measure/mesh_picker.h"
#include "core/measure/outline_pieces_phases.h"
#include "tests/support/folded_face.h"

namespace {

using namespace rockface;
using rockface::test::FoldedFace;
namespace phases = rockface::measure::outline_phases;

// Two walls y = 10 + 0.3 z -+ 0.105 x meeting at x = 0, no noise.
FoldedFace two_walls() {
  FoldedFace f;
  const double edges[3] = {-4.0, 0.0, 4.0}, slopes[2] = {-0.105, 0.105};
  for (int k = 0; k < 2; ++k) {
    geometry::Plane p;
    p.normal = Eigen::Vector3d(slopes[k], -1.0, 0.3).normalized();
    p.offset = p.normal.dot(Eigen::Vector3d(0, 10, 0));
    f.facets.push_back({p, edges[k], edges[k + 1]});
  }
  test::look_at_lattice(f, 400, 300, 0.0, 2);
  return f;
}

// 3 m each side of the fold, 1.5 m below and 2 m above the camera.
std::vector<Eigen::Vector2d> outline_of(const FoldedFace& f) {
  std::vector<Eigen::Vector3d> corners;
  for (const auto& xz : {Eigen::Vector2d(-3, -1.5), Eigen::Vector2d(3, -1.5),
                         Eigen::Vector2d(3, 2.0), Eigen::Vector2d(-3, 2.0)})
    corners.push_back(
        *f.hit(f.view.pose.centre,
               (Eigen::Vector3d(xz.x(), 10, xz.y()) - f.view.pose.centre).normalized()));
  return test::pixels_of(f, corners);
}

std::vector<geometry::Plane> walls(const FoldedFace& f) {
  return {f.facets[0].plane, f.facets[1].plane};
}

double area_px(const std::vector<Eigen::Vector2d>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& u = p[i];
    const auto& v = p[(i + 1) % p.size()];
    a += u.x() * v.y() - u.y() * v.x();
  }
  return std::abs(a) / 2;
}

TEST(OutlinePhases, PiecesAreJudgedFinerWhereTheSnapToleranceNeedsIt) {
  measure::MeasureSettings measured;
  measured.point_sigma = 0.014;  // the demo's fast preset
  measure::FacetOptions options;
  options.planarity_in_sigmas = 4.0;
  // Half the 0.05 m snap tolerance at 4 sigmas: 6.25 mm.
  EXPECT_DOUBLE_EQ(phases::piece_settings(measured, options, 0.05).point_sigma, 0.00625);
  measured.point_sigma = 0.002;
  EXPECT_EQ(phases::piece_settings(measured, options, 0.05).point_sigma, 0.002);
}

TEST(OutlinePhases, EveryPointInsideTheOutlineGoesToItsWall) {
  const FoldedFace f = two_walls();
  const measure::MeshPicker picker(f.mesh);
  const auto sub = phases::outline_submesh(picker, f.view, outline_of(f));
  ASSERT_GT(sub.size(), 1000u);
  EXPECT_LT(sub.size(), f.mesh.size());
  EXPECT_FALSE(sub.triangles.empty());
  std::vector<int> label;
  const phases::Labelled parts = phases::label_points(sub, walls(f), label);
  ASSERT_EQ(label.size(), sub.size());
  for (std::size_t v = 0; v < sub.size(); ++v) {
    const double x = sub.vertices[v].x();
    if (std::abs(x) > 0.05) {
      EXPECT_EQ(label[v], x < 0 ? 0 : 1) << x;
    }
  }
  // The outline is 6 m wide, 3.5 m high on walls leaning back 17 degrees:
  // about 11 m2 each side, within a lattice cell.
  EXPECT_NEAR(parts.area[0], parts.area[1], 0.2);
  EXPECT_EQ(parts.points[0].size() + parts.points[1].size(), sub.size());
  const auto touch = phases::touching_pieces(sub, label, 2);
  EXPECT_EQ(touch[0][1], 1);
  EXPECT_EQ(touch[1][0], 1);
  EXPECT_EQ(touch[0][0], 0);
}

TEST(OutlinePhases, APlaneWithNoPartOfTheFaceIsDroppedAndWithItTheSplit) {
  const FoldedFace f = two_walls();
  const measure::MeshPicker picker(f.mesh);
  const auto sub = phases::outline_submesh(picker, f.view, outline_of(f));
  measure::FacetOptions options;
  const double gate = 0.025;
  // A third plane 5 m behind the face gets no point: too small.
  geometry::Plane behind = f.facets[0].plane;
  behind.offset += 5.0;
  const measure::MeasureSettings measured;
  auto settled =
      phases::settle_planes(sub, {walls(f)[0], walls(f)[1], behind}, measured, options, gate);
  EXPECT_FALSE(settled.too_few);
  ASSERT_EQ(settled.planes.size(), 2u);
  ASSERT_EQ(settled.notes.size(), 1u);
  EXPECT_NE(settled.notes[0].find("too small to be a flat piece"), std::string::npos);
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_LT(std::acos(std::min(
                  1.0, std::abs(settled.estimates[k].fit.normal.dot(f.facets[k].plane.normal)))),
              1e-6);
  // With one wall and the plane behind, one plane remains: no split.
  settled = phases::settle_planes(sub, {walls(f)[0], behind}, measured, options, gate);
  EXPECT_TRUE(settled.too_few);
}

TEST(OutlinePhases, TheOutlineIsCutInTwoAlongTheFold) {
  const FoldedFace f = two_walls();
  const measure::MeshPicker picker(f.mesh);
  const auto polygon = outline_of(f);
  const auto sub = phases::outline_submesh(picker, f.view, polygon);
  const auto settled = phases::settle_planes(sub, walls(f), measure::MeasureSettings{},
                                             measure::FacetOptions{}, 0.025);
  ASSERT_FALSE(settled.too_few);
  std::vector<geometry::Plane> planes;
  for (const auto& e : settled.estimates) planes.push_back(e.fit.plane());
  const auto touch = phases::touching_pieces(sub, settled.label, 2);
  std::vector<std::vector<Eigen::Vector2d>> seen_at;
  for (const auto& pts : settled.parts.points)
    seen_at.push_back(measure::project_to_view(f.view, pts));
  const auto folds =
      phases::fold_outlines(f.view, polygon, planes, settled.estimates, touch, seen_at);
  EXPECT_TRUE(folds.notes.empty());
  ASSERT_EQ(folds.outline.size(), 2u);
  // The two halves tile the outline, the west one left in the photograph.
  EXPECT_NEAR(area_px(folds.outline[0]) + area_px(folds.outline[1]), area_px(polygon),
              1e-6 * area_px(polygon));
  EXPECT_NEAR(area_px(folds.outline[0]), area_px(folds.outline[1]), 0.2 * area_px(polygon));
  double x0 = 0, x1 = 0;
  for (const auto& p : folds.outline[0]) x0 += p.x() / static_cast<double>(folds.outline[0].size());
  for (const auto& p : folds.outline[1]) x1 += p.x() / static_cast<double>(folds.outline[1].size());
  EXPECT_LT(x0, x1);
}

}  // namespace

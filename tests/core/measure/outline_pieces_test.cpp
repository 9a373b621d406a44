// Issue 27: a face outlined on the 3D image split into the flat pieces it
// covers (core/measure/outline_pieces.h), on a synthetic folded face: two
// walls 12 degrees apart meeting along a vertical-ish fold (the demo face's
// shape), seen by a pinhole camera, with depth noise along the rays.
#include <algorithm>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/outline_pieces.h"
#include "tests/support/folded_face.h"

namespace {

using namespace rockface;
using rockface::test::FoldedFace;

constexpr double kNoise = 0.005;  // m along the rays: a stereo model's sigma_Z at 10 m
constexpr double kSnap = 0.05;    // m: the analysis' snap tolerance (SCENE.md)

// Two walls y = 10 + 0.3 z + b x with b = -0.105 West of x = 0 and +0.105
// East of it: each turned 6 degrees about the vertical, 12 degrees apart,
// 0.3 m of relief over 3 m, as the demo face.
FoldedFace two_walls(double slope) {
  FoldedFace f;
  const double a = 0.3, edges[3] = {-4.0, 0.0, 4.0}, slopes[2] = {-slope, slope};
  for (int k = 0; k < 2; ++k) {
    geometry::Plane p;
    p.normal = Eigen::Vector3d(slopes[k], -1.0, a).normalized();
    p.offset = p.normal.dot(Eigen::Vector3d(0, 10, 0));
    f.facets.push_back({p, edges[k], edges[k + 1]});
  }
  test::look_at_lattice(f, 800, 600, kNoise, 2);
  return f;
}

measure::MeasureSettings settings() {
  measure::MeasureSettings s;
  s.point_sigma = kNoise;
  return s;
}

// The outline's corners: 3 m each side of the fold, 1.5 m below and 2 m
// above the camera's height, on the true surface.
std::vector<Eigen::Vector2d> outline_of(const FoldedFace& f) {
  std::vector<Eigen::Vector3d> corners;
  for (const auto& xz : {Eigen::Vector2d(-3, -1.5), Eigen::Vector2d(3, -1.5),
                         Eigen::Vector2d(3, 2.0), Eigen::Vector2d(-3, 2.0)}) {
    const auto p = f.hit(f.view.pose.centre,
                         (Eigen::Vector3d(xz.x(), 10, xz.y()) - f.view.pose.centre).normalized());
    EXPECT_TRUE(p);
    corners.push_back(*p);
  }
  return test::pixels_of(f, corners);
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

// Whether a piece's corners turn counter-clockwise seen from the camera
// (its Newell normal toward the camera: out of the rock, SCENE.md).
bool wound_toward_camera(const measure::AreaMeasurement& a, const FoldedFace& f) {
  Eigen::Vector3d newell = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < a.outline_points.size(); ++i) {
    newell += a.outline_points[i].cross(a.outline_points[(i + 1) % a.outline_points.size()]);
    centroid += a.outline_points[i];
  }
  centroid /= static_cast<double>(a.outline_points.size());
  return newell.dot(f.view.pose.centre - centroid) > 0;
}

bool inside(const std::vector<measure::PhotoPixel>& poly, const Eigen::Vector2d& q) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Eigen::Vector2d &a = poly[i].pixel, &b = poly[j].pixel;
    if ((a.y() > q.y()) != (b.y() > q.y()) &&
        q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

TEST(OutlinePieces, AFoldedFaceGivesTwoPiecesInItsTwoPlanesMeetingAlongTheFold) {
  const FoldedFace f = two_walls(0.105);
  const measure::MeshPicker picker(f.mesh);
  const auto options = measure::facet_options(Preset::standard);
  const auto split = measure::split_outline(picker, f.view, "F1", outline_of(f), settings(),
                                            options, kSnap, "face outline");
  ASSERT_EQ(split.pieces.size(), 2u);
  for (const auto& n : split.notes) ADD_FAILURE() << "unexpected note: " << n;
  EXPECT_EQ(split.pieces[0].id, "F1a");
  EXPECT_EQ(split.pieces[1].id, "F1b");
  // Each piece in one wall's plane: its normal within 0.3 degrees of the
  // wall's. Expected error: the fit's own sigma over ~30,000 points is a
  // few hundredths of a degree, and the points within a few noise sigmas of
  // the fold given to the wrong wall tilt it by under 0.1 degree.
  for (const auto& piece : split.pieces) {
    ASSERT_TRUE(piece.plane.known) << piece.plane.problem;
    const double west = angle_deg(piece.plane.fit.normal, f.facets[0].plane.normal);
    const double east = angle_deg(piece.plane.fit.normal, f.facets[1].plane.normal);
    EXPECT_LT(std::min(west, east), 0.3) << piece.id;
    // The RMS off its plane is the noise (5 mm along rays that meet the
    // wall within 15 degrees of its normal): under 1.5 times it; a piece
    // bent over the fold would be centimetres.
    EXPECT_LT(piece.plane.fit.rms_off_plane(), 1.5 * kNoise) << piece.id;
    EXPECT_GE(piece.outline.size(), 3u);
    EXPECT_EQ(piece.outline.size(), piece.outline_points.size());
    EXPECT_TRUE(wound_toward_camera(piece, f)) << piece.id;
  }
  // The two walls, 11.5 degrees apart (each turned 6 degrees about the
  // vertical, leaning back 17 degrees): within twice the per-piece error.
  EXPECT_NEAR(angle_deg(split.pieces[0].plane.fit.normal, split.pieces[1].plane.fit.normal),
              angle_deg(f.facets[0].plane.normal, f.facets[1].plane.normal), 0.6);
  // Each piece's corners lie in its plane (lifted along their rays) and the
  // pieces share their common edge: two corners of one are corners of the
  // other (the same pixels' rays met with both planes on their common line;
  // rounding only, under a micrometre).
  std::size_t shared = 0;
  for (const auto& p : split.pieces[0].outline_points)
    for (const auto& q : split.pieces[1].outline_points) shared += (p - q).norm() < 1e-6;
  EXPECT_EQ(shared, 2u);
  for (const auto& piece : split.pieces)
    for (const auto& c : piece.outline_points)
      EXPECT_LT(std::abs(piece.plane.fit.plane().signed_distance(c)), 1e-9) << piece.id;

  // Every point of traces of two joints across both walls lies within
  // 0.05 m (the analysis' snap tolerance, SCENE.md) of a piece: in its
  // polygon seen from the camera and within 0.05 m of its plane. Expected
  // distance: the noise-free trace lies on a wall, its piece's plane within
  // 0.3 degree of it: under 2 cm at 4 m from the centroid.
  const geometry::Plane joints[2] = {test::plane_through(60, 200, Eigen::Vector3d(-1, 10, 0.5)),
                                     test::plane_through(75, 110, Eigen::Vector3d(1, 10, 0.5))};
  std::size_t checked = 0;
  for (const auto& joint : joints)
    for (std::size_t k = 0; k < f.facets.size(); ++k) {
      const auto ends = f.trace_on(joint, k);
      if (!ends) continue;
      // Not the ends: one lies on the fold, the pieces' common edge.
      for (double s = 0.025; s < 1.0; s += 0.05) {
        const Eigen::Vector3d p = (1 - s) * (*ends)[0] + s * (*ends)[1];
        const Eigen::Vector2d px = test::pixels_of(f, {p})[0];
        // Only the part inside the outline (3 m each side, -1.5..2 m).
        if (std::abs(p.x()) > 2.9 || p.z() < -1.4 || p.z() > 1.9) continue;
        bool on = false;
        for (const auto& piece : split.pieces)
          on = on || (inside(piece.outline, px) &&
                      std::abs(piece.plane.fit.plane().signed_distance(p)) < 0.05);
        EXPECT_TRUE(on) << "trace point " << p.transpose();
        ++checked;
      }
    }
  EXPECT_GT(checked, 20u);
}

TEST(OutlinePieces, AFlatFaceStaysOnePieceMeasuredAsAnArea) {
  const FoldedFace f = two_walls(0.0);  // both walls in one plane
  const measure::MeshPicker picker(f.mesh);
  // Tapped clockwise as seen from the camera: stored the other way round.
  auto polygon = outline_of(f);
  std::reverse(polygon.begin(), polygon.end());
  const auto split =
      measure::split_outline(picker, f.view, "F1", polygon, settings(),
                             measure::facet_options(Preset::standard), kSnap, "face outline");
  ASSERT_EQ(split.pieces.size(), 1u);
  EXPECT_TRUE(split.notes.empty());
  const auto area =
      measure::measure_area(picker, f.view, "F1", polygon, settings(), "face outline");
  const auto& piece = split.pieces.front();
  EXPECT_EQ(piece.id, "F1");
  EXPECT_EQ(piece.outline_points.size(), area.outline_points.size());
  // The same computation on the same points: equal.
  EXPECT_EQ(piece.plane.fit.normal, area.plane.fit.normal);
  EXPECT_EQ(piece.area, area.area);
  EXPECT_TRUE(wound_toward_camera(piece, f));
  EXPECT_FALSE(wound_toward_camera(area, f)) << "measure_area keeps the tapped order";
}

TEST(OutlinePieces, ADegenerateOutlineIsRefusedByName) {
  const FoldedFace f = two_walls(0.105);
  const measure::MeshPicker picker(f.mesh);
  const auto p = outline_of(f);
  const auto options = measure::facet_options(Preset::standard);
  auto refused = [&](const std::vector<Eigen::Vector2d>& polygon, const std::string& why) {
    try {
      measure::split_outline(picker, f.view, "F1", polygon, settings(), options, kSnap,
                             "face outline");
      ADD_FAILURE() << "accepted: " << why;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("face outline"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  refused({p[0], p[1]}, "needs 3 or more corners, got 2");
  refused({p[0], 0.5 * (p[0] + p[2]), p[2]}, "lie on one line");
  refused({p[0], p[2], p[1], p[3]}, "its edges cross");
}

TEST(OutlinePieces, ClippingKeepsTheSideOfTheLineOnTheLeftOfItsDirection) {
  const std::vector<Eigen::Vector2d> square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  // The vertical line x = 4 going up: its left is x < 4.
  const auto left = measure::clip_polygon(square, {4, 0}, {0, 1});
  ASSERT_EQ(left.size(), 4u);
  for (const auto& q : left) EXPECT_LE(q.x(), 4.0);
  const auto right = measure::clip_polygon(square, {4, 0}, {0, -1});
  ASSERT_EQ(right.size(), 4u);
  for (const auto& q : right) EXPECT_GE(q.x(), 4.0);
}

}  // namespace

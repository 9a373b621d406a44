// The range pole's targets marked where the detector found them in the
// photograph (issue 27), on the demo project: on the Model screen's
// Photograph view a ring centred on each detected pixel, and on the 3D image
// a ring laid on the mesh around the surface point under that pixel (the
// ray of the left camera through it), which the left camera sees at the
// detected pixel again.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/measure/photo_view.h"
#include "tests/ui/demo_project.h"
#include "ui/model/overlay_photo_targets.h"
#include "ui/platform/headless_session.h"
#include "ui/view3d/overlay_targets.h"

namespace {

using rockface::test::demo_project;
using namespace rockface::ui;

constexpr std::size_t kTriangles = 20000;  // the checks hold at any budget

cv::Vec3b bgr(ImU32 c) {
  return cv::Vec3b((c >> IM_COL32_B_SHIFT) & 0xFF, (c >> IM_COL32_G_SHIFT) & 0xFF,
                   (c >> IM_COL32_R_SHIFT) & 0xFF);
}

std::unique_ptr<HeadlessSession> model_screen(int width, int height) {
  UiOptions options;
  options.project = demo_project();
  options.max_display_triangles = kTriangles;
  auto s = std::make_unique<HeadlessSession>(options, FieldServices{}, width, height);
  s->settle();
  s->tap("Model");
  s->frame();
  return s;
}

TEST(OverlayTargets, ThePhotographRingsEachTargetAtItsDetectedPixel) {
  auto s = model_screen(1280, 800);
  s->tap("Photograph");
  s->frame();
  const auto targets = detected_targets(*s->state().model_view.model());
  ASSERT_EQ(targets.size(), 2u) << "the demo's pole has two targets";
  const PhotoTargetsView& view = s->state().model.photo_targets;
  const auto& rings = view.rings();
  ASSERT_EQ(rings.size(), targets.size());
  const cv::Mat shot = s->screenshot();
  const cv::Vec3b yellow = bgr(kTargetColour);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const auto& [centre, radius] = rings[i];
    // Where the detected pixel is on the screen: the photograph drawn at
    // image_min(), k screen px per photograph px, OpenCV's pixel centres at
    // whole numbers. Float arithmetic on the same numbers: a thousandth of a
    // pixel.
    const float k = view.screen_px_per_photo_px();
    const ImVec2 expected(view.image_min().x + static_cast<float>(targets[i].pixel.x() + 0.5) * k,
                          view.image_min().y + static_cast<float>(targets[i].pixel.y() + 0.5) * k);
    EXPECT_NEAR(centre.x, expected.x, 1e-3);
    EXPECT_NEAR(centre.y, expected.y, 1e-3);
    // In the picture: the ring's pixels (3 px wide, in the annulus 4 px
    // either side of its radius) are centred on that point. A ring drawn a
    // pixel off would cut the annulus unevenly and move their mean by about
    // half a pixel or more; antialiasing is symmetric about the true centre,
    // and the pixel grid's rounding moves the mean by a fraction of a pixel.
    double sx = 0, sy = 0;
    int n = 0, on_circle = 0;
    const int reach = static_cast<int>(radius) + 5;
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        const int x = static_cast<int>(std::floor(expected.x)) + dx;
        const int y = static_cast<int>(std::floor(expected.y)) + dy;
        if (x < 0 || y < 0 || x >= shot.cols || y >= shot.rows) continue;
        const double d = std::hypot(x + 0.5 - expected.x, y + 0.5 - expected.y);
        if (std::abs(d - radius) > 4 || shot.at<cv::Vec3b>(y, x) != yellow) continue;
        sx += x + 0.5;
        sy += y + 0.5;
        ++n;
      }
    for (int a = 0; a < 36; ++a) {
      const double t = a * M_PI / 18;
      const int x = static_cast<int>(std::floor(centre.x + radius * std::cos(t)));
      const int y = static_cast<int>(std::floor(centre.y + radius * std::sin(t)));
      on_circle += shot.at<cv::Vec3b>(y, x) == yellow;
    }
    ASSERT_GT(n, 20) << targets[i].which << ": no ring in the picture";
    std::printf(
        "%s target: ring at (%.2f, %.2f) px on the screen, its %d pixels centred %.2f, "
        "%.2f px from it\n",
        targets[i].which.c_str(), expected.x, expected.y, n, sx / n - expected.x,
        sy / n - expected.y);
    EXPECT_GT(on_circle, 18) << targets[i].which << ": the ring's colour on half its circle";
    EXPECT_NEAR(sx / n, expected.x, 0.35) << targets[i].which;
    EXPECT_NEAR(sy / n, expected.y, 0.35) << targets[i].which;
  }
  s->tap("3D image");
  EXPECT_FALSE(s->state().model.show_photograph);
}

TEST(OverlayTargets, TheModelRingsEachTargetOnTheMeshUnderItsDetectedPixel) {
  auto s = model_screen(1280, 800);
  const ModelView& view = s->state().model_view;
  ASSERT_TRUE(view.left_view()) << "the demo's 3D image keeps its left camera";
  const auto& targets = view.targets();
  ASSERT_EQ(targets.size(), 2u);
  const cv::Mat shot = s->screenshot();
  const cv::Vec3b yellow = bgr(kTargetColour);
  const Eigen::Vector3d n = view.drape()->direction();
  // How far a drawn vertex may be from the stored surface: the drawn surface
  // is the stored one decimated (each vertex moved by at most a cell's
  // diagonal), and a point inside a drawn triangle is further within the
  // stored surface's point spacing of the stored triangles under it.
  const double on_surface =
      std::sqrt(3.0) * view.display_mesh().cell + view.surface()->median_edge_length();
  // The stored surface seen by the left camera: a target with no point must
  // have no triangle of it over its pixel (checked here without the picker).
  const auto& surface = *view.surface();
  const auto seen = rockface::measure::project_to_view(*view.left_view(), surface.vertices);
  auto covered = [&](const Eigen::Vector2d& px) {
    for (const auto& tri : surface.triangles) {
      const Eigen::Vector2d &a = seen[tri[0]], &b = seen[tri[1]], &c = seen[tri[2]];
      auto side = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v, const Eigen::Vector2d& q) {
        return (v.x() - u.x()) * (q.y() - u.y()) - (v.y() - u.y()) * (q.x() - u.x());
      };
      const double s0 = side(a, b, px), s1 = side(b, c, px), s2 = side(c, a, px);
      if ((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) return true;
    }
    return false;
  };
  int ringed = 0;
  for (const TargetOnModel& t : targets) {
    ASSERT_TRUE(t.point) << t.detected.which << ": " << t.why_not;
    // The mesh is under the pixel exactly when the point is its hit (checked
    // here without the picker). On the demo the pole stands in front of the
    // face and is left out of the 3D image: its targets are holes.
    EXPECT_EQ(covered(t.detected.pixel), t.on_surface) << t.detected.which;
    ++ringed;
    // The left camera sees the marked point at the detected pixel: the
    // point is the ray's hit (double precision), projected back with the
    // same lens model; the lens's undistortion is solved iteratively to
    // well under a thousandth of a pixel.
    const auto back = rockface::measure::project_to_view(*view.left_view(), {*t.point});
    EXPECT_NEAR(back[0].x(), t.detected.pixel.x(), 0.01) << t.detected.which;
    EXPECT_NEAR(back[0].y(), t.detected.pixel.y(), 0.01) << t.detected.which;

    // The ring and ticks drawn: every vertex on the stored surface, the
    // ring's around the point at its radius.
    const double r = target_ring_radius(view, t, s->state().targets.scale());
    ASSERT_GT(r, 0);
    if (!t.on_surface) {
      // The point is where the ray meets the face's plane fitted around the
      // hole: its depth is as good as the plane fits the rock (its RMS, the
      // rock's relief). A tenth of the ring's radius moves the ring's centre
      // on the framed view by a tenth of the ring at most.
      EXPECT_LT(t.plane_rms_m, 0.1 * r) << t.detected.which;
      EXPECT_GT(t.plane_points, 100) << t.detected.which;
      // The ring clears the hole: the face's mesh comes within its radius.
      EXPECT_FALSE(view.picker()->vertices_near(*t.point, r).empty()) << t.detected.which;
    }
    int ring = 0, ticks = 0;
    for (const OverlayLine& l : view.drawn_overlay().lines) {
      const bool is_ring = l.what == "target " + t.detected.which + " ring";
      const bool is_tick = l.what == "target " + t.detected.which + " tick";
      if (!is_ring && !is_tick) continue;
      for (const Eigen::Vector3d& p : l.points) {
        const auto hit = view.picker()->pick({p + n * on_surface, -n});
        EXPECT_TRUE(hit && std::abs(hit->distance - on_surface) <= on_surface)
            << l.what << ": vertex (" << p.transpose() << ") off the mesh by more than "
            << on_surface << " m";
        const Eigen::Vector3d d = p - *t.point;
        const double across = (d - d.dot(n) * n).norm();  // in the plane the ring was drawn in
        if (is_ring) {
          ++ring;
          // A ring point is on the circle; one where the drape split a
          // 10° chord at a triangle's edge is within the chord's sagitta
          // (1 - cos 5°) inside it. Plus rounding.
          EXPECT_GE(across, r * std::cos(M_PI / 36) - 1e-9) << l.what;
          EXPECT_LE(across, r + 1e-9) << l.what;
        } else {
          ++ticks;
          EXPECT_GE(across, r - 1e-9) << l.what;
          EXPECT_LE(across, 1.8 * r + 1e-9) << l.what;
        }
      }
    }
    // Drawn twice (a dark rim under the yellow), 36 points each, fewer where
    // it leaves the 3D image, more where the drape splits it at edges.
    EXPECT_GE(ring, 36) << t.detected.which << ": the ring is not drawn whole";
    EXPECT_GE(ticks, 8) << t.detected.which << ": the four ticks are not drawn";
    // In the picture: the target's yellow around the projected point.
    const auto c = view.to_screen(*t.point);
    ASSERT_TRUE(c);
    const ImVec2 a = view.to_screen(*t.point + r * n.unitOrthogonal()).value_or(*c);
    const double r_px = std::hypot(a.x - c->x, a.y - c->y);
    int yellow_px = 0;
    const int reach = static_cast<int>(2 * r_px) + 4;
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        const int x = static_cast<int>(c->x) + dx, y = static_cast<int>(c->y) + dy;
        if (x >= 0 && y >= 0 && x < shot.cols && y < shot.rows &&
            shot.at<cv::Vec3b>(y, x) == yellow)
          ++yellow_px;
      }
    std::printf(
        "%s target: pixel (%.1f, %.1f), %s at (%.3f, %.3f, %.3f) (plane RMS %.1f mm of %d "
        "points), ring %.3f m (%.0f px), %d ring and %d tick vertices, %d yellow px\n",
        t.detected.which.c_str(), t.detected.pixel.x(), t.detected.pixel.y(),
        t.on_surface ? "on the mesh" : "on the face behind it", t.point->x(), t.point->y(),
        t.point->z(), 1000 * t.plane_rms_m, t.plane_points, r, r_px, ring, ticks, yellow_px);
    EXPECT_GT(yellow_px, 30) << t.detected.which << ": no ring in the picture";
  }
  EXPECT_EQ(ringed, 2);
}

}  // namespace

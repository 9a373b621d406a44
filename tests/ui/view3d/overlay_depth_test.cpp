// A trace laid on the face behind a ridge is hidden by the ridge (issue 27):
// the real GLES renderer (ModelRenderer with its OverlayRenderer, Mesa's
// software rasteriser through surfaceless EGL) draws a synthetic face, a
// flat wall with a fin standing out of its lower half, seen obliquely so
// that the fin stands between the camera and the lower half of a trace
// draped on the wall. What the GPU drew is read back: where the picker says
// the fin is in front of the trace, the fin's colour shows, never the
// trace's; where nothing is in front, the trace's colour shows.
#include <cmath>
#include <cstdio>
#include <utility>

#include <gtest/gtest.h>

#include "core/measure/mesh_picker.h"
#include "ui/mapping/face_outline.h"
#include "ui/platform/egl_context.h"
#include "ui/view3d/display_mesh.h"
#include "ui/view3d/model_renderer.h"
#include "ui/view3d/orbit_camera.h"
#include "ui/view3d/overlay_drape.h"

namespace {

using namespace rockface::ui;

constexpr int kWidth = 480, kHeight = 360;
const cv::Vec3b kWallBgr(128, 128, 128), kFinBgr(40, 120, 40);
constexpr std::uint32_t kTraceRgba = 0xFFC800FFu;  // IM_COL32(255, 0, 200, 255): magenta
const cv::Vec3b kTraceBgr(200, 0, 255);

// A wall in the plane y = 0 (x, z in [-1, 1], facing -y) and a fin on its
// lower half: a ridge of triangular section standing 0.5 m out of the wall
// toward the viewer, along z from -1 to 0, its base from x = -0.1 to 0.1.
struct Scene {
  DisplayMesh mesh;
  rockface::photogrammetry::SurfaceMesh surface;  // the same, project frame (for the picker)
};

Scene wall_with_fin() {
  Scene s;
  auto& v = s.surface.vertices;
  auto& t = s.surface.triangles;
  std::vector<cv::Vec3b> colour;
  auto quad_grid = [&](const Eigen::Vector3d& o, const Eigen::Vector3d& du,
                       const Eigen::Vector3d& dv, int nu, int nv, const cv::Vec3b& c) {
    const int base = static_cast<int>(v.size());
    for (int j = 0; j <= nv; ++j)
      for (int i = 0; i <= nu; ++i) {
        v.push_back(o + du * (static_cast<double>(i) / nu) + dv * (static_cast<double>(j) / nv));
        colour.push_back(c);
      }
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        const int a = base + j * (nu + 1) + i;
        t.push_back({a, a + 1, a + nu + 2});
        t.push_back({a, a + nu + 2, a + nu + 1});
      }
  };
  quad_grid({-1, 0, -1}, {2, 0, 0}, {0, 0, 2}, 40, 40, kWallBgr);
  // The fin's two sides, meeting at its crest (x = 0, y = -0.5).
  quad_grid({-0.1, 0, -1}, {0.1, -0.5, 0}, {0, 0, 1}, 4, 20, kFinBgr);
  quad_grid({0.1, 0, -1}, {-0.1, -0.5, 0}, {0, 0, 1}, 4, 20, kFinBgr);

  DisplayMesh& m = s.mesh;
  m.centre = Eigen::Vector3d(0, -0.1, 0);
  m.radius = 1.5;
  m.mean_normal = -Eigen::Vector3d::UnitY();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Eigen::Vector3d r = v[i] - m.centre;
    m.positions.insert(m.positions.end(), {static_cast<float>(r.x()), static_cast<float>(r.y()),
                                           static_cast<float>(r.z())});
    // BGR to the mesh's RGB.
    m.colours.insert(m.colours.end(), {colour[i][2], colour[i][1], colour[i][0]});
  }
  for (const auto& tri : t)
    for (int k = 0; k < 3; ++k) m.indices.push_back(static_cast<std::uint32_t>(tri[k]));
  return s;
}

TEST(OverlayDepth, ATraceBehindARidgeIsHiddenWhereTheRidgeIsInFront) {
  auto egl = EglContext::surfaceless();
  const Scene scene = wall_with_fin();
  ModelRenderer renderer;
  renderer.upload(scene.mesh, cv::Mat());
  // From the front left and a little above: the fin hides the wall just to
  // its right (x from 0.1 to about 0.6) on the lower half.
  OrbitCamera camera;
  camera.set_viewport(kWidth, kHeight);
  camera.frame(scene.mesh.centre, scene.mesh.radius, Eigen::Vector3d(-1, -1, 0.25));

  // A vertical trace on the wall at x = 0.3, draped as the screens drape.
  const SurfaceDrape drape(scene.mesh);
  const auto runs = drape.drape({{0.3, 0, -0.9}, {0.3, 0, 0.9}}, false);
  ASSERT_EQ(runs.size(), 1u) << "the trace lies on the wall from end to end";
  OverlayScene overlay;
  overlay.lines.push_back({"trace T1", runs.front(), kTraceRgba, 4, false});
  renderer.render(camera, overlay);
  const cv::Mat shot = renderer.read_bgr();
  ASSERT_EQ(shot.cols, kWidth);
  ASSERT_EQ(shot.rows, kHeight);

  // Whether the first surface on a screen pixel's ray is the fin (its
  // triangles stand in front of the wall, y < 0; the wall is y = 0): the
  // picker's verdict, from the geometry alone. 1: hidden, 0: the wall, -1:
  // nothing on the ray. 5 mm keeps the fin's foot, where it meets the wall,
  // with the wall.
  const rockface::measure::MeshPicker picker(scene.surface);
  auto hidden_at = [&](float x, float y) {
    const ScreenRay ray = camera.ray(x, y);
    const auto hit = picker.pick({ray.origin, ray.direction});
    if (!hit) return -1;
    return hit->point.y() < -0.005 ? 1 : 0;
  };
  int hidden = 0, visible = 0, wrong = 0;
  for (int k = 0; k <= 180; ++k) {
    const Eigen::Vector3d p(0.3, 0, -0.9 + 1.8 * k / 180.0);
    const Eigen::Vector3d q = camera.project(p);
    const float x = static_cast<float>(q.x()), y = static_cast<float>(q.y());
    // Near the fin's outline the verdict changes within the ribbon's width
    // (4 px) and the rasteriser's rounding: only pixels whose neighbours 4
    // px around agree are asserted.
    const int verdict = hidden_at(x + 0.5f, y + 0.5f);
    bool agreed = verdict >= 0;
    for (const auto& [dx, dy] :
         {std::pair{-4, 0}, std::pair{4, 0}, std::pair{0, -4}, std::pair{0, 4}})
      agreed = agreed && hidden_at(x + 0.5f + dx, y + 0.5f + dy) == verdict;
    if (!agreed) continue;
    const cv::Vec3b seen = shot.at<cv::Vec3b>(static_cast<int>(y), static_cast<int>(x));
    if (verdict == 1) {
      ++hidden;
      if (seen != kFinBgr && ++wrong <= 5)
        ADD_FAILURE() << "behind the fin at z = " << p.z() << ": pixel (" << x << ", " << y
                      << ") is " << seen << ", not the fin's " << kFinBgr;
    } else {
      ++visible;
      if (seen != kTraceBgr && ++wrong <= 5)
        ADD_FAILURE() << "in the open at z = " << p.z() << ": pixel (" << x << ", " << y << ") is "
                      << seen << ", not the trace's " << kTraceBgr;
    }
  }
  std::printf("trace samples asserted: %d hidden behind the fin, %d visible\n", hidden, visible);
  // The view was chosen so that both halves are long: a third of the samples each.
  EXPECT_GT(hidden, 50);
  EXPECT_GT(visible, 50);
  EXPECT_EQ(wrong, 0);
  // And nowhere in the picture does the trace show through the fin: no
  // pixel of the trace's colour has the fin nearer than the wall behind it.
  int through = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      if (shot.at<cv::Vec3b>(y, x) != kTraceBgr) continue;
      if (hidden_at(x + 0.5f, y + 0.5f) == 1) ++through;
    }
  EXPECT_EQ(through, 0) << through << " trace pixels drawn over the fin";
}

// The face's outline (issue 27) is laid on the surface as the traces are:
// its edges are depth-tested (the fin hides the part behind it), a corner
// behind the fin is not in sight (its dot is not drawn), and an edge to a
// corner beyond the 3D image is cut where the surface ends, never drawn in
// the air. The same wall, camera and real renderers as above.
TEST(OverlayDepth, AFaceOutlineLiesOnTheSurfaceHiddenBehindTheRidgeAndCutAtItsEdge) {
  auto egl = EglContext::surfaceless();
  const Scene scene = wall_with_fin();
  ModelRenderer renderer;
  renderer.upload(scene.mesh, cv::Mat());
  OrbitCamera camera;
  camera.set_viewport(kWidth, kHeight);
  camera.frame(scene.mesh.centre, scene.mesh.radius, Eigen::Vector3d(-1, -1, 0.25));
  const SurfaceDrape drape(scene.mesh);
  DrapeCache cache;
  const rockface::measure::MeshPicker picker(scene.surface);

  // Corners tapped on the wall right of the fin, the lower left one behind
  // it, and one beyond the wall's right edge (x = 1).
  const std::vector<Eigen::Vector3d> corners = {
      {0.3, 0, -0.8}, {0.3, 0, 0.8}, {1.4, 0, 0.8}, {0.8, 0, -0.8}};
  constexpr std::uint32_t kOutlineRgba = 0xFF00C8FFu;  // IM_COL32(255, 200, 0, 255)
  const cv::Vec3b kOutlineBgr(0, 200, 255);
  const auto lines = outline_on_surface(drape, cache, "face outline", corners, kOutlineRgba, 4);
  ASSERT_FALSE(lines.empty());
  // Every drawn vertex lies on the wall: on its plane (y = 0 to 1e-6 m: the
  // display mesh holds its positions as floats, 6e-8 m apart at 1 m) and
  // within it (x <= 1 plus the drape's tolerance, the most a vertex may
  // stand off the drawn surface).
  for (const auto& l : lines)
    for (const auto& p : l.points) {
      EXPECT_NEAR(p.y(), 0, 1e-6) << "an outline vertex off the wall's plane";
      EXPECT_LE(p.x(), 1 + drape.tolerance()) << "an outline vertex beyond the wall's edge";
    }
  OverlayScene overlay;
  overlay.lines = lines;
  renderer.render(camera, overlay);
  const cv::Mat shot = renderer.read_bgr();

  auto hidden_at = [&](float x, float y) {
    const ScreenRay ray = camera.ray(x, y);
    const auto hit = picker.pick({ray.origin, ray.direction});
    if (!hit) return -1;
    return hit->point.y() < -0.005 ? 1 : 0;  // the fin, as in the test above
  };
  // Samples along every drawn edge, asserted where the 4 px ribbon's
  // neighbours agree (the rasteriser's rounding at the fin's outline).
  int hidden = 0, visible = 0, wrong = 0;
  for (const auto& l : lines)
    for (std::size_t i = 1; i < l.points.size(); ++i)
      for (int k = 0; k < 20; ++k) {
        const Eigen::Vector3d p = l.points[i - 1] + (l.points[i] - l.points[i - 1]) * (k / 20.0);
        const Eigen::Vector3d q = camera.project(p);
        const float x = static_cast<float>(q.x()), y = static_cast<float>(q.y());
        if (x < 5 || y < 5 || x > kWidth - 6 || y > kHeight - 6) continue;
        const int verdict = hidden_at(x + 0.5f, y + 0.5f);
        bool agreed = verdict >= 0;
        for (const auto& [dx, dy] :
             {std::pair{-4, 0}, std::pair{4, 0}, std::pair{0, -4}, std::pair{0, 4}})
          agreed = agreed && hidden_at(x + 0.5f + dx, y + 0.5f + dy) == verdict;
        if (!agreed) continue;
        const cv::Vec3b seen = shot.at<cv::Vec3b>(static_cast<int>(y), static_cast<int>(x));
        const bool ok = verdict == 1 ? seen == kFinBgr : seen == kOutlineBgr;
        (verdict == 1 ? hidden : visible)++;
        if (!ok && ++wrong <= 5)
          ADD_FAILURE() << (verdict == 1 ? "behind the fin" : "in the open") << " at "
                        << p.transpose() << ": pixel (" << x << ", " << y << ") is " << seen;
      }
  std::printf("outline samples asserted: %d hidden behind the fin, %d visible\n", hidden, visible);
  EXPECT_GT(hidden, 20);  // the lower part of the left edge and of the bottom edge
  EXPECT_GT(visible, 50);
  EXPECT_EQ(wrong, 0);
  // No pixel of the outline shows through the fin, and none lies off the
  // wall farther than the ribbon's half width and a pixel of rounding (3 px).
  int through = 0, off = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      if (shot.at<cv::Vec3b>(y, x) != kOutlineBgr) continue;
      const int verdict = hidden_at(x + 0.5f, y + 0.5f);
      if (verdict == 1) ++through;
      if (verdict >= 0) continue;
      bool near_wall = false;
      for (int dy = -3; dy <= 3 && !near_wall; ++dy)
        for (int dx = -3; dx <= 3 && !near_wall; ++dx)
          near_wall = hidden_at(x + 0.5f + dx, y + 0.5f + dy) >= 0;
      if (!near_wall) ++off;
    }
  EXPECT_EQ(through, 0) << through << " outline pixels drawn over the fin";
  EXPECT_EQ(off, 0) << off << " outline pixels drawn off the wall";

  // The corners' dots: drawn only where the corner is in sight. The lower
  // left corner is behind the fin; the upper left is in the open. The
  // tolerance is the drape's, as the Mapping screen's.
  auto in_sight = [&](const Eigen::Vector3d& c) {
    const Eigen::Vector3d q = camera.project(c);
    return corner_in_sight(picker, camera.ray(static_cast<float>(q.x()), static_cast<float>(q.y())),
                           c, drape.tolerance());
  };
  EXPECT_FALSE(in_sight(corners[0])) << "a corner behind the fin is drawn";
  EXPECT_TRUE(in_sight(corners[1]));
  EXPECT_TRUE(in_sight(corners[3]));
}

}  // namespace

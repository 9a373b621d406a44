// The model renderer's frame is drawn again only when what it shows changes
// (issue 45): the same camera, viewport, overlay and mesh give back the last
// frame's texture without drawing; a change of any of them draws, and what
// is read back is what a renderer drawing every frame shows. The real GLES
// renderer (Mesa's software rasteriser through surfaceless EGL).
#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "ui/platform/egl_context.h"
#include "ui/view3d/display_mesh.h"
#include "ui/view3d/model_renderer.h"
#include "ui/view3d/orbit_camera.h"

namespace {

using namespace rockface::ui;

// A flat grey square of 2 x 2 m in the plane y = 0, facing -y.
DisplayMesh grey_square() {
  DisplayMesh m;
  m.centre = Eigen::Vector3d::Zero();
  m.radius = 1.5;
  m.mean_normal = -Eigen::Vector3d::UnitY();
  for (const auto& [x, z] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
    m.positions.insert(m.positions.end(), {x, 0.0f, z});
    m.colours.insert(m.colours.end(), {128, 128, 128});
  }
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

int pixels_differing(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size()) return -1;
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  return cv::countNonZero(diff.reshape(1));
}

TEST(ModelFrameCache, DrawsAgainOnlyWhatChanged) {
  auto egl = EglContext::surfaceless();
  const DisplayMesh mesh = grey_square();
  ModelRenderer renderer, every_frame;
  renderer.upload(mesh, cv::Mat());
  OrbitCamera camera;
  camera.set_viewport(160, 120);
  camera.frame(mesh.centre, mesh.radius, Eigen::Vector3d(-0.3, -1, 0.2));
  // What a renderer that has drawn nothing before shows: the reference.
  const auto fresh = [&](const OverlayScene& overlay) {
    every_frame.upload(mesh, cv::Mat());
    every_frame.render(camera, overlay);
    return every_frame.read_bgr();
  };

  renderer.render(camera);
  EXPECT_EQ(renderer.frames_drawn(), 1);
  const cv::Mat first = renderer.read_bgr();
  renderer.render(camera);
  renderer.render(camera, {}, true);  // turning, but the mesh has no turning copy
  EXPECT_EQ(renderer.frames_drawn(), 1) << "the same frame was drawn again";
  EXPECT_EQ(pixels_differing(renderer.read_bgr(), first), 0);

  camera.orbit(25, 0);
  renderer.render(camera);
  EXPECT_EQ(renderer.frames_drawn(), 2) << "a turned view was not drawn";
  EXPECT_GT(pixels_differing(renderer.read_bgr(), first), 0);
  EXPECT_EQ(pixels_differing(renderer.read_bgr(), fresh({})), 0);

  OverlayScene overlay;
  overlay.lines.push_back(
      {"trace T1", {{-0.5, -0.001, 0}, {0.5, -0.001, 0}}, 0xFF00FFFFu, 4, false});
  renderer.render(camera, overlay);
  EXPECT_EQ(renderer.frames_drawn(), 3) << "a new line on the model was not drawn";
  OverlayScene same = overlay;  // another scene, the same content
  renderer.render(camera, same);
  EXPECT_EQ(renderer.frames_drawn(), 3);
  EXPECT_EQ(pixels_differing(renderer.read_bgr(), fresh(overlay)), 0);
  same.lines.front().rgba = 0xFFFF0000u;
  renderer.render(camera, same);
  EXPECT_EQ(renderer.frames_drawn(), 4) << "a line's new colour was not drawn";
  EXPECT_EQ(pixels_differing(renderer.read_bgr(), fresh(same)), 0);

  camera.set_viewport(200, 120);
  renderer.render(camera, same);
  EXPECT_EQ(renderer.frames_drawn(), 5) << "a new viewport was not drawn";
  EXPECT_EQ(renderer.read_bgr().cols, 200);

  renderer.upload(mesh, cv::Mat());
  renderer.render(camera, same);
  EXPECT_EQ(renderer.frames_drawn(), 6) << "a mesh uploaded again was not drawn";
}

}  // namespace

#pragma once
// Draws an OverlayScene into the model's framebuffer after the model, with
// the model's depth buffer: a line behind a ridge of the face is hidden as
// the ridge hides the rock behind it. Lines are ribbons of constant width
// on the screen (GLES guarantees only 1 px wide GL lines), dashed in the
// fragment shader by their length on the screen. The model is drawn with a
// polygon offset (ModelRenderer) so that what lies on its surface wins the
// depth test.
#include <Eigen/Core>

#include "ui/view3d/orbit_camera.h"
#include "ui/view3d/overlay_scene.h"

namespace rockface::ui {

class OverlayRenderer {
 public:
  OverlayRenderer();
  OverlayRenderer(const OverlayRenderer&) = delete;
  OverlayRenderer& operator=(const OverlayRenderer&) = delete;
  ~OverlayRenderer();

  // Into the bound framebuffer; `origin` is the point the camera's
  // view_projection() is relative to (the display mesh's centre).
  void draw(const OverlayScene& scene, const OrbitCamera& camera, const Eigen::Vector3d& origin);

 private:
  unsigned program_ = 0, vertex_array_ = 0, buffer_ = 0;
};

}  // namespace rockface::ui

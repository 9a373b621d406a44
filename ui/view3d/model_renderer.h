#pragma once
// Draws the textured 3D image with GLES 3 into a framebuffer: the model
// view's panel shows that framebuffer's texture. What lies on the surface
// (traces, blocks: OverlayScene) is drawn into the same framebuffer with the
// model's depth; ImGui draws the flat marks (labels, markers) on top.
#include <memory>

#include <opencv2/core.hpp>

#include "ui/platform/framebuffer.h"
#include "ui/view3d/display_mesh.h"
#include "ui/view3d/orbit_camera.h"
#include "ui/view3d/overlay_renderer.h"
#include "ui/view3d/overlay_scene.h"

namespace rockface::ui {

class ModelRenderer {
 public:
  ModelRenderer();
  ModelRenderer(const ModelRenderer&) = delete;
  ModelRenderer& operator=(const ModelRenderer&) = delete;
  ~ModelRenderer();

  // Uploads a mesh and its texture (BGR; empty: vertex colours).
  void upload(const DisplayMesh& mesh, const cv::Mat& texture_bgr);
  // Renders into a framebuffer of the camera's viewport size (made or
  // resized as needed) and returns its colour texture. A frame whose
  // camera, viewport, overlay, mesh and turning are the last one's is not
  // drawn again: its texture already holds it (issue 45: the software
  // renderer drew a still model sixty times a second on both cores of the
  // tablet, beside the work the geologist waits for).
  // The overlay is drawn after the model, depth-tested against it.
  // turning: a finger is turning the view; the mesh's turning copy is drawn
  // (DisplayMesh::turning_indices) when it has one.
  unsigned render(const OrbitCamera& camera, const OverlayScene& overlay = {},
                  bool turning = false);
  // Triangles of the mesh in the frame last drawn.
  int drawn_triangles() const { return drawn_triangles_; }
  // Frames drawn since the renderer was made (a frame not drawn again
  // does not count).
  long frames_drawn() const { return frames_drawn_; }
  // The last render's pixels, BGR, top row first (the rows of
  // OrbitCamera::project); empty before the first render. For tests: the
  // depth test is checked on what the GPU drew, not on a model of it.
  cv::Mat read_bgr() const;

 private:
  unsigned program_ = 0, vertex_array_ = 0, texture_ = 0;
  // positions, texcoords, colours, indices, the turning copy's indices
  unsigned buffers_[5] = {0, 0, 0, 0, 0};
  int index_count_ = 0, turning_index_count_ = 0, drawn_triangles_ = 0;
  bool textured_ = false;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();  // the mesh's centre: positions are relative
  std::unique_ptr<OverlayRenderer> overlay_;
  std::unique_ptr<Framebuffer> target_;
  // What the framebuffer holds: the last drawn frame's inputs.
  struct Drawn {
    Eigen::Matrix4f view_projection = Eigen::Matrix4f::Zero();
    bool turning = false;
    long upload = -1;
    OverlayScene overlay;
  };
  Drawn drawn_;
  long uploads_ = 0, frames_drawn_ = 0;
};

}  // namespace rockface::ui

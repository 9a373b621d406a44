#pragma once
// Draws the textured 3D image with GLES 3 into a framebuffer: the model
// view's panel shows that framebuffer's texture, and ImGui draws the
// overlays (targets, traces, blocks) on top.
#include <memory>

#include <opencv2/core.hpp>

#include "ui/display_mesh.h"
#include "ui/orbit_camera.h"
#include "ui/platform/framebuffer.h"

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
  // resized as needed) and returns its colour texture.
  unsigned render(const OrbitCamera& camera);

 private:
  unsigned program_ = 0, vertex_array_ = 0, texture_ = 0;
  unsigned buffers_[4] = {0, 0, 0, 0};  // positions, texcoords, colours, indices
  int index_count_ = 0;
  bool textured_ = false;
  std::unique_ptr<Framebuffer> target_;
};

}  // namespace rockface::ui

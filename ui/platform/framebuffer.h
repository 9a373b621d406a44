#pragma once
// A GLES 3 framebuffer object: an RGBA colour texture and a depth buffer.
// The whole UI draws into one when headless (and its pixels become the
// screenshot); the model view draws the 3D image into one and shows the
// texture inside its ImGui panel.
#include <opencv2/core.hpp>

namespace rockface::ui {

class Framebuffer {
 public:
  Framebuffer() = default;
  Framebuffer(int width, int height);
  Framebuffer(Framebuffer&& other) noexcept;
  Framebuffer& operator=(Framebuffer&& other) noexcept;
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;
  ~Framebuffer();

  int width() const { return width_; }
  int height() const { return height_; }
  unsigned texture() const { return texture_; }
  // Makes draw calls go here, over the whole framebuffer.
  void bind() const;
  // Back to the window's default framebuffer.
  static void unbind();
  // Copies the pixels to the window's default framebuffer (same size).
  void blit_to_window() const;
  // The pixels as an 8-bit BGR image, top row first (OpenCV's order).
  cv::Mat read_bgr() const;

 private:
  void release();
  int width_ = 0, height_ = 0;
  unsigned framebuffer_ = 0, texture_ = 0, depth_ = 0;
};

}  // namespace rockface::ui

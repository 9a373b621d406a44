#include "ui/platform/framebuffer.h"

#include <GLES3/gl3.h>

#include <utility>

#include <opencv2/imgproc.hpp>

#include "core/common/error.h"

namespace rockface::ui {

Framebuffer::Framebuffer(int width, int height) : width_(width), height_(height) {
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    throw Error("GLES: framebuffer of " + std::to_string(width) + "x" + std::to_string(height) +
                " is incomplete (status " + std::to_string(status) + ")");
  }
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : width_(std::exchange(other.width_, 0)),
      height_(std::exchange(other.height_, 0)),
      framebuffer_(std::exchange(other.framebuffer_, 0u)),
      texture_(std::exchange(other.texture_, 0u)),
      depth_(std::exchange(other.depth_, 0u)) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
  if (this != &other) {
    release();
    width_ = std::exchange(other.width_, 0);
    height_ = std::exchange(other.height_, 0);
    framebuffer_ = std::exchange(other.framebuffer_, 0u);
    texture_ = std::exchange(other.texture_, 0u);
    depth_ = std::exchange(other.depth_, 0u);
  }
  return *this;
}

Framebuffer::~Framebuffer() {
  release();
}

void Framebuffer::release() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  if (texture_) glDeleteTextures(1, &texture_);
  framebuffer_ = depth_ = texture_ = 0;
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
}

void Framebuffer::unbind() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Framebuffer::blit_to_window() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

cv::Mat Framebuffer::read_bgr() const {
  cv::Mat rgba(height_, width_, CV_8UC4);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data);
  cv::Mat bgr;
  cv::cvtColor(rgba, bgr, cv::COLOR_RGBA2BGR);
  cv::flip(bgr, bgr, 0);  // GL's first row is the bottom one
  return bgr;
}

}  // namespace rockface::ui

#include "ui/widgets/picture_texture.h"

#include <algorithm>
#include <cstdint>

#include <GLES3/gl3.h>
#include <imgui.h>
#include <opencv2/imgproc.hpp>

#include "ui/platform/texture_generation.h"

namespace rockface::ui {

PictureTexture::~PictureTexture() {
  clear();
}

void PictureTexture::clear() {
  if (texture_) glDeleteTextures(1, &texture_);
  texture_ = 0;
  width_ = height_ = 0;
}

void PictureTexture::set(const cv::Mat& bgr) {
  if (bgr.empty()) {
    clear();
    return;
  }
  cv::Mat rgba;
  cv::cvtColor(bgr, rgba, cv::COLOR_BGR2RGBA);
  if (!texture_) glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, rgba.cols, rgba.rows, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               rgba.data);
  note_texture_changed();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  width_ = rgba.cols;
  height_ = rgba.rows;
}

void PictureTexture::draw(float max_width) const {
  if (!texture_) return;
  const float w = std::min(max_width, static_cast<float>(width_));
  const float h = w * static_cast<float>(height_) / static_cast<float>(width_);
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture_)), ImVec2(w, h));
}

}  // namespace rockface::ui

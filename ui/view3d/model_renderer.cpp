#include "ui/view3d/model_renderer.h"

#include <GLES3/gl3.h>

#include <algorithm>
#include <string>

#include <opencv2/imgproc.hpp>

#include "ui/platform/texture_generation.h"
#include "ui/view3d/gles_program.h"

namespace rockface::ui {

namespace {

constexpr const char* kVertexShader = R"(#version 300 es
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;
layout(location = 2) in vec3 colour;
uniform mat4 view_projection;
out vec2 v_texcoord;
out vec3 v_colour;
void main() {
  v_texcoord = texcoord;
  v_colour = colour;
  gl_Position = view_projection * vec4(position, 1.0);
}
)";

constexpr const char* kFragmentShader = R"(#version 300 es
precision mediump float;
in vec2 v_texcoord;
in vec3 v_colour;
uniform sampler2D image;
uniform bool textured;
out vec4 fragment;
void main() {
  // Texture coordinates have v up (photogrammetry's SurfaceMesh, OBJ/PLY);
  // GL's first texture row is the image's top row, at v = 0.
  vec2 uv = vec2(v_texcoord.x, 1.0 - v_texcoord.y);
  fragment = textured ? vec4(texture(image, uv).rgb, 1.0) : vec4(v_colour, 1.0);
}
)";

// The largest texture side uploaded: GLES 3 guarantees 2048, and a 6000 px
// photograph on a 1920 px screen gains nothing from more.
constexpr int kMaxTextureSide = 2048;

}  // namespace

ModelRenderer::ModelRenderer() {
  program_ = link_gles_program(kVertexShader, kFragmentShader, "model");
  glGenVertexArrays(1, &vertex_array_);
  glGenBuffers(5, buffers_);
  glGenTextures(1, &texture_);
}

ModelRenderer::~ModelRenderer() {
  glDeleteTextures(1, &texture_);
  glDeleteBuffers(5, buffers_);
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteProgram(program_);
}

void ModelRenderer::upload(const DisplayMesh& mesh, const cv::Mat& texture_bgr) {
  glBindVertexArray(vertex_array_);
  auto attribute = [&](int location, unsigned buffer, const void* data, std::size_t bytes,
                       int components, GLenum type, bool normalised) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
    if (bytes == 0) {
      glDisableVertexAttribArray(location);
      return;
    }
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, components, type, normalised ? GL_TRUE : GL_FALSE, 0, nullptr);
  };
  attribute(0, buffers_[0], mesh.positions.data(), mesh.positions.size() * sizeof(float), 3,
            GL_FLOAT, false);
  attribute(1, buffers_[1], mesh.texcoords.data(), mesh.texcoords.size() * sizeof(float), 2,
            GL_FLOAT, false);
  attribute(2, buffers_[2], mesh.colours.data(), mesh.colours.size(), 3, GL_UNSIGNED_BYTE, true);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[3]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  // The turning copy's indices, bound in place of the whole's while turning.
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[4]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(mesh.turning_indices.size() * sizeof(std::uint32_t)),
               mesh.turning_indices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  ++uploads_;
  index_count_ = static_cast<int>(mesh.indices.size());
  turning_index_count_ = static_cast<int>(mesh.turning_indices.size());
  origin_ = mesh.centre;

  textured_ = !texture_bgr.empty() && !mesh.texcoords.empty();
  if (textured_) {
    cv::Mat rgb;
    const double shrink = std::min(
        1.0, static_cast<double>(kMaxTextureSide) / std::max(texture_bgr.cols, texture_bgr.rows));
    cv::resize(texture_bgr, rgb, cv::Size(), shrink, shrink, cv::INTER_AREA);
    cv::cvtColor(rgb, rgb, cv::COLOR_BGR2RGB);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, rgb.cols, rgb.rows, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 rgb.isContinuous() ? rgb.data : rgb.clone().data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
}

unsigned ModelRenderer::render(const OrbitCamera& camera, const OverlayScene& overlay,
                               bool turning) {
  const bool coarse = turning && turning_index_count_ > 0;
  const Eigen::Matrix4f view_projection = camera.view_projection();
  if (target_ && target_->width() == camera.width() && target_->height() == camera.height() &&
      drawn_.upload == uploads_ && drawn_.turning == coarse &&
      drawn_.view_projection == view_projection && drawn_.overlay == overlay)
    return target_->texture();
  drawn_triangles_ = 0;
  if (!target_ || target_->width() != camera.width() || target_->height() != camera.height())
    target_ = std::make_unique<Framebuffer>(camera.width(), camera.height());
  drawn_ = {view_projection, coarse, uploads_, overlay};
  ++frames_drawn_;
  note_texture_changed();
  target_->bind();
  // Dark grey behind the model: the face's texture stands out in daylight.
  glClearColor(0.18f, 0.18f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (index_count_ > 0) {
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glUseProgram(program_);
    glUniformMatrix4fv(glGetUniformLocation(program_, "view_projection"), 1, GL_FALSE,
                       view_projection.data());
    glUniform1i(glGetUniformLocation(program_, "textured"), textured_ ? 1 : 0);
    glUniform1i(glGetUniformLocation(program_, "image"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glBindVertexArray(vertex_array_);
    // Pushed back in depth by a little more than its slope across the
    // widest overlay ribbon's half width (a few pixels): a line laid on the
    // surface passes the depth test along its whole width, and a ridge of
    // the face in front of it still hides it.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(4.0f, 8.0f);
    if (coarse) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[4]);
    const int count = coarse ? turning_index_count_ : index_count_;
    glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);
    drawn_triangles_ = count / 3;
    // The vertex array keeps its element buffer: the whole's again.
    if (coarse) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[3]);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glBindVertexArray(0);
    if (!overlay.empty()) {
      if (!overlay_) overlay_ = std::make_unique<OverlayRenderer>();
      overlay_->draw(overlay, camera, origin_);
    }
    glDisable(GL_DEPTH_TEST);
  }
  Framebuffer::unbind();
  return target_->texture();
}

cv::Mat ModelRenderer::read_bgr() const {
  if (!target_) return {};
  cv::Mat pixels = target_->read_bgr();
  Framebuffer::unbind();
  return pixels;
}

}  // namespace rockface::ui

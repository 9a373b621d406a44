#include "ui/view3d/overlay_renderer.h"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ui/view3d/gles_program.h"

namespace rockface::ui {

namespace {

constexpr const char* kOverlayVertexShader = R"(#version 300 es
layout(location = 0) in vec4 clip;
layout(location = 1) in vec4 colour;
layout(location = 2) in float along;
out vec4 v_colour;
out float v_along;
void main() {
  v_colour = colour;
  v_along = along;
  gl_Position = clip;
}
)";

// along < 0: solid; else the length along the line on the screen (px),
// dashed 12 px on, 8 px off.
constexpr const char* kOverlayFragmentShader = R"(#version 300 es
precision mediump float;
in vec4 v_colour;
in float v_along;
out vec4 fragment;
void main() {
  if (v_along >= 0.0 && mod(v_along, 20.0) > 12.0) discard;
  fragment = v_colour;
}
)";

struct Vertex {
  float clip[4];
  std::uint8_t colour[4];
  float along;
};

// Vertices nearer than this (clip w, in metres from the eye) are not drawn:
// the near plane cuts them.
constexpr float kMinW = 1e-3f;

class Batch {
 public:
  Batch(const Eigen::Matrix4f& vp, const Eigen::Vector3d& origin, int width, int height)
      : vp_(vp), origin_(origin), half_(0.5f * width, 0.5f * height) {}

  Eigen::Vector4f clip(const Eigen::Vector3d& p) const {
    const Eigen::Vector3f r = (p - origin_).cast<float>();
    return vp_ * Eigen::Vector4f(r.x(), r.y(), r.z(), 1);
  }
  Eigen::Vector2f screen(const Eigen::Vector4f& c) const {
    return Eigen::Vector2f(c.x() / c.w(), c.y() / c.w()).cwiseProduct(half_);
  }
  void add(const Eigen::Vector4f& c, std::uint32_t rgba, float along) {
    Vertex v{{c.x(), c.y(), c.z(), c.w()},
             {static_cast<std::uint8_t>(rgba & 0xFF), static_cast<std::uint8_t>((rgba >> 8) & 0xFF),
              static_cast<std::uint8_t>((rgba >> 16) & 0xFF),
              static_cast<std::uint8_t>((rgba >> 24) & 0xFF)},
             along};
    vertices_.push_back(v);
  }
  // A clip position moved by `px` screen pixels (x right, y up).
  Eigen::Vector4f offset(const Eigen::Vector4f& c, const Eigen::Vector2f& px) const {
    return {c.x() + px.x() / half_.x() * c.w(), c.y() + px.y() / half_.y() * c.w(), c.z(), c.w()};
  }
  void fill(const OverlayFill& f) {
    for (std::size_t i = 0; i + 2 < f.triangles.size(); i += 3) {
      const Eigen::Vector4f a = clip(f.triangles[i]), b = clip(f.triangles[i + 1]),
                            c = clip(f.triangles[i + 2]);
      if (a.w() < kMinW || b.w() < kMinW || c.w() < kMinW) continue;
      add(a, f.rgba, -1);
      add(b, f.rgba, -1);
      add(c, f.rgba, -1);
    }
  }
  void quad(const Eigen::Vector4f& a0, const Eigen::Vector4f& a1, const Eigen::Vector4f& b0,
            const Eigen::Vector4f& b1, std::uint32_t rgba, float along_a, float along_b) {
    add(a0, rgba, along_a);
    add(a1, rgba, along_a);
    add(b0, rgba, along_b);
    add(a1, rgba, along_a);
    add(b1, rgba, along_b);
    add(b0, rgba, along_b);
  }
  void line(const OverlayLine& l) {
    const float h = 0.5f * l.width_px;
    float along = 0;
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      const Eigen::Vector4f a = clip(l.points[i]);
      if (a.w() < kMinW) continue;
      const float at = l.dashed ? along : -1;
      // A square at each point joins the segments' ribbons without gaps.
      quad(offset(a, {-h, -h}), offset(a, {h, -h}), offset(a, {-h, h}), offset(a, {h, h}), l.rgba,
           at, at);
      if (i + 1 == l.points.size()) break;
      const Eigen::Vector4f b = clip(l.points[i + 1]);
      if (b.w() < kMinW) continue;
      const Eigen::Vector2f d = screen(b) - screen(a);
      const float length = d.norm();
      const Eigen::Vector2f across =
          length > 1e-6f ? Eigen::Vector2f(-d.y(), d.x()) / length * h : Eigen::Vector2f(0, h);
      const float next = along + length;
      quad(offset(a, across), offset(a, -across), offset(b, across), offset(b, -across), l.rgba, at,
           l.dashed ? next : -1);
      along = next;
    }
  }
  const std::vector<Vertex>& vertices() const { return vertices_; }

 private:
  Eigen::Matrix4f vp_;
  Eigen::Vector3d origin_;
  Eigen::Vector2f half_;
  std::vector<Vertex> vertices_;
};

}  // namespace

OverlayRenderer::OverlayRenderer() {
  program_ = link_gles_program(kOverlayVertexShader, kOverlayFragmentShader, "overlay");
  glGenVertexArrays(1, &vertex_array_);
  glGenBuffers(1, &buffer_);
}

OverlayRenderer::~OverlayRenderer() {
  glDeleteBuffers(1, &buffer_);
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteProgram(program_);
}

void OverlayRenderer::draw(const OverlayScene& scene, const OrbitCamera& camera,
                           const Eigen::Vector3d& origin) {
  if (scene.empty()) return;
  Batch batch(camera.view_projection(), origin, camera.width(), camera.height());
  for (const auto& f : scene.fills) batch.fill(f);
  for (const auto& l : scene.lines) batch.line(l);
  const auto& v = batch.vertices();
  if (v.empty()) return;
  glUseProgram(program_);
  glBindVertexArray(vertex_array_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(Vertex)), v.data(),
               GL_STREAM_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, clip)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, colour)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, along)));
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);  // overlays do not hide each other, only the model hides them
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size()));
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
}

}  // namespace rockface::ui

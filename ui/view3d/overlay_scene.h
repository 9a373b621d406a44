#pragma once
// What is drawn on the 3D image itself, in the project frame, by the GLES
// renderer with the model's depth: lines laid on the surface (traces, block
// edges; dashed where what they show goes on unknown beyond the mapped
// area) and areas of the surface tinted (a block's footprint). The screens
// fill it each frame before the model view renders; the renderer keeps what
// it drew last so that tests can check every drawn vertex.
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rockface::ui {

struct OverlayLine {
  std::string what;  // "trace T3", "block TB1 edge", ...: for tests and messages
  std::vector<Eigen::Vector3d> points;
  std::uint32_t rgba = 0xFFFFFFFF;  // ImGui's IM_COL32 layout (R in the low byte)
  float width_px = 3;
  bool dashed = false;
  bool operator==(const OverlayLine&) const = default;
};

struct OverlayFill {
  std::string what;
  std::vector<Eigen::Vector3d> triangles;  // three corners per triangle, on the surface
  std::uint32_t rgba = 0x80FFFFFF;
  bool operator==(const OverlayFill&) const = default;
};

struct OverlayScene {
  std::vector<OverlayFill> fills;  // drawn first, under the lines
  std::vector<OverlayLine> lines;
  bool empty() const { return fills.empty() && lines.empty(); }
  bool operator==(const OverlayScene&) const = default;
};

}  // namespace rockface::ui

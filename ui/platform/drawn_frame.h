#pragma once
// Whether a frame's ImGui draw data would draw what the last drawn frame
// drew (issue 45): the same display size, vertices, indices, commands and
// clip rectangles, and no texture changed since (texture_generation.h).
// Mesa's software renderer rasterises every frame on the tablet's cores
// (most of two cores at sixty frames a second on the Mapping screen, beside
// the Find traces it shows the progress of); a frame that would draw the
// same pixels is not drawn, and the window keeps showing the last one.
#include <cstdint>
#include <vector>

#include <imgui.h>

namespace rockface::ui {

class DrawnFrame {
 public:
  // True when `data` draws what the frame last passed to remember() drew.
  bool same_as_last(const ImDrawData& data);
  // `data` is being drawn.
  void remember(const ImDrawData& data);
  // The next frame is drawn whatever it holds (the window was exposed).
  void forget() { valid_ = false; }

 private:
  static void bytes_of(const ImDrawData& data, std::vector<unsigned char>& out);
  std::vector<unsigned char> last_, scratch_;
  std::uint64_t textures_ = 0;
  bool valid_ = false;
};

}  // namespace rockface::ui

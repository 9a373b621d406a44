#pragma once
// A count of the changes to the pictures the screens show through textures
// (the model view's frame, the live view, photographs): a screen whose
// ImGui draw data is the last drawn frame's shows the same pixels only if no
// texture it samples changed meanwhile (ui/platform/drawn_frame.h). Every
// upload or draw into such a texture notes it here.
#include <cstdint>

namespace rockface::ui {

void note_texture_changed();
std::uint64_t texture_generation();

}  // namespace rockface::ui

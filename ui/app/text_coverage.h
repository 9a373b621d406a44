#pragma once
// Does the walk see every text a frame draws? ImGui draws each glyph as a
// quad textured from the font atlas; this reads the glyphs back out of the
// frame's draw data (by their atlas coordinates) and compares them, panel by
// panel, with the glyphs of the strings recorded through ui/widgets/widgets_text.h.
// A glyph drawn in a panel beyond what was recorded there is text a widget
// drew unseen (ImGui's own table header, a slider's value, the "…" ImGui
// adds to a clipped label): the walk fails on it.
//
// Recorded text may draw fewer glyphs than it has (scrolled out of view,
// clipped by its button): the check is one-sided. A glyph drawn again
// within 3 px of itself (the dark halo of a label on the 3D image) counts
// once.
#include <string>
#include <vector>

#include <imgui.h>

#include "ui/app/text_check.h"

namespace rockface::ui {

struct UnrecordedText {
  std::string panel;       // the ImGui window whose draw list holds it
  std::string characters;  // the glyphs drawn beyond those recorded, in drawing order
};

// The text of `draw_data` (a frame after ImGui::Render) that `recorded`
// does not account for, per panel; empty when everything drawn was recorded.
// `font` is the font the frame drew with (the theme's only one).
std::vector<UnrecordedText> unrecorded_text(const ImDrawData& draw_data, const ImFont& font,
                                            ImTextureID font_texture,
                                            const std::vector<DrawnText>& recorded);

// The same for the last frame rendered in the current ImGui context.
std::vector<UnrecordedText> unrecorded_text_in_last_frame(const std::vector<DrawnText>& recorded);

}  // namespace rockface::ui

#pragma once
// Text drawn straight onto a picture (the 3D image, the photograph, the
// stereonet) with an ImDrawList, not laid out by ImGui: block and target
// labels, the legend's words, the scale bar's length, the north arrow's N.
// Every such string goes through draw_text(), which records it twice: with
// the text rules of ui/widgets/widgets_text.h (record_drawn_text: its width against
// the room left in the picture, keys, JSON, digits), and with the rectangle
// it must lie in (the picture it belongs to), so that the screen walk of
// tests/ui checks these too. The text is drawn clipped to that rectangle: a
// label never spills onto the side panel, and the walk says when one would.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

namespace rockface::ui {

// The rectangle a drawn text belongs to, with its name for the messages
// ("3D image", "photograph", "stereonet").
struct TextArea {
  ImVec2 min, max;
  const char* name = "picture";
};

// A dark halo (one pixel all round) keeps white text readable on rock and on
// the background alike.
enum class TextHalo { none, dark };

// Draws `text` with its top left at `at` in `area`, clipped to it, and
// records it. No folders are cut here: these are short labels.
void draw_text(ImDrawList* draw, ImVec2 at, ImU32 colour, std::string_view text,
               const TextArea& area, TextHalo halo = TextHalo::none);

// Where draw_text put a string this frame.
struct PlacedText {
  std::string text;
  ImVec2 min, max;  // the text's box (the halo included)
  TextArea area;
};
// The strings draw_text drew in the current ImGui frame (older ones are
// dropped as the next frame draws).
std::vector<PlacedText> placed_texts();
// What is wrong with where a string was drawn, in words ("… reaches 12 px
// past the 3D image's right edge"); empty when it lies inside its area.
// `slack_px` is ImGui's rounding of positions (a fraction of a pixel).
std::string placement_problem(const PlacedText& placed, float slack_px = 1.0f);

// The top left for a label of `size` beside a mark at `centre` of radius
// `r`: right of it when there is room in `area`, else left; moved up or
// down to stay inside. Nothing when the mark itself is outside the area.
std::optional<ImVec2> label_beside(ImVec2 centre, float r, ImVec2 size, const TextArea& area);

}  // namespace rockface::ui

#include "ui/view3d/overlay_text.h"

#include <algorithm>

#include "core/common/number_format.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

struct FrameLog {
  int frame = -1;
  std::vector<PlacedText> placed;
};

FrameLog& placed_log() {
  static FrameLog l;
  return l;
}

}  // namespace

void draw_text(ImDrawList* draw, ImVec2 at, ImU32 colour, std::string_view text,
               const TextArea& area, TextHalo halo) {
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  const ImVec2 size = ImGui::CalcTextSize(begin, end);
  const ImVec4 clip(area.min.x, area.min.y, area.max.x, area.max.y);
  ImFont* font = ImGui::GetFont();
  const float font_size = ImGui::GetFontSize();
  const float grow = halo == TextHalo::dark ? 1.0f : 0.0f;
  if (halo == TextHalo::dark)
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        if (dx || dy)
          draw->AddText(font, font_size, ImVec2(at.x + dx, at.y + dy), IM_COL32(0, 0, 0, 255),
                        begin, end, 0, &clip);
  draw->AddText(font, font_size, at, colour, begin, end, 0, &clip);

  // The text rules: its width against the room from where it starts to the
  // picture's right edge.
  record_drawn_text(text, size.x + 2 * grow, area.max.x - (at.x - grow));
  FrameLog& l = placed_log();
  if (l.frame != ImGui::GetFrameCount()) {
    l.frame = ImGui::GetFrameCount();
    l.placed.clear();
  }
  l.placed.push_back({std::string(text), ImVec2(at.x - grow, at.y - grow),
                      ImVec2(at.x + size.x + grow, at.y + size.y + grow), area});
}

std::vector<PlacedText> placed_texts() {
  const FrameLog& l = placed_log();
  if (l.frame != ImGui::GetFrameCount()) return {};
  return l.placed;
}

std::string placement_problem(const PlacedText& p, float slack_px) {
  std::string why;
  auto add = [&](const char* side, float px) {
    if (px <= slack_px) return;
    why += std::string(why.empty() ? "" : "; ") + format_fixed(px, 0, " px") + " past the " +
           p.area.name + "'s " + side + " edge";
  };
  add("left", p.area.min.x - p.min.x);
  add("top", p.area.min.y - p.min.y);
  add("right", p.max.x - p.area.max.x);
  add("bottom", p.max.y - p.area.max.y);
  return why.empty() ? why : "\"" + p.text + "\" drawn " + why;
}

std::optional<ImVec2> label_beside(ImVec2 centre, float r, ImVec2 size, const TextArea& area) {
  if (centre.x < area.min.x || centre.x > area.max.x || centre.y < area.min.y ||
      centre.y > area.max.y)
    return std::nullopt;
  // A pixel of halo and a gap of a quarter line between the mark and its words.
  const float gap = r + 0.25f * size.y + 1;
  float x = centre.x + gap;
  if (x + size.x + 1 > area.max.x) x = centre.x - gap - size.x;
  // Neither side has room (a panel narrower than the words): the left edge,
  // and the walk says it does not fit.
  x = std::max(x, area.min.x + 1);
  const float y = std::clamp(centre.y - size.y / 2, area.min.y + 1,
                             std::max(area.min.y + 1, area.max.y - size.y - 1));
  return ImVec2(x, y);
}

}  // namespace rockface::ui

#include "ui/app/text_coverage.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include <imgui_internal.h>

namespace rockface::ui {

namespace {

// A glyph's quad as ImFont::RenderText (ImGui 1.86) writes it: four
// vertices with UVs (U0,V0) (U1,V0) (U1,V1) (U0,V1). Its first corner's UV
// names the glyph.
std::uint64_t uv_key(float u, float v) {
  std::uint32_t a, b;
  static_assert(sizeof(float) == sizeof(std::uint32_t));
  std::memcpy(&a, &u, sizeof a);
  std::memcpy(&b, &v, sizeof b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

// A copy of the same glyph within this of one already counted is a halo
// (outlined labels draw it at every offset of -1..1 px: 2.8 px apart at
// most); two letters of real text are a glyph's advance apart, 6 px or more.
constexpr float kHaloPx = 3.0f;

struct GlyphsDrawn {
  // Per glyph index, its count; the positions of counted ones for the halo test.
  std::map<int, int> count;
  std::unordered_map<std::uint64_t, std::vector<ImVec2>> cells;
  std::vector<int> order;  // glyph indices in drawing order

  void add(int glyph, ImVec2 at) {
    const auto cx = static_cast<std::int64_t>(std::floor(at.x / kHaloPx));
    const auto cy = static_cast<std::int64_t>(std::floor(at.y / kHaloPx));
    auto key = [&](std::int64_t x, std::int64_t y) {
      return (static_cast<std::uint64_t>(glyph) << 42) ^
             (static_cast<std::uint64_t>(x & 0x1FFFFF) << 21) ^
             static_cast<std::uint64_t>(y & 0x1FFFFF);
    };
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = cells.find(key(cx + dx, cy + dy));
        if (it == cells.end()) continue;
        for (const ImVec2& p : it->second)
          if (std::hypot(p.x - at.x, p.y - at.y) <= kHaloPx) return;
      }
    cells[key(cx, cy)].push_back(at);
    ++count[glyph];
    order.push_back(glyph);
  }
};

std::string utf8(unsigned int c) {
  std::string out;
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
  return out;
}

}  // namespace

std::vector<UnrecordedText> unrecorded_text(const ImDrawData& draw_data, const ImFont& font,
                                            ImTextureID font_texture,
                                            const std::vector<DrawnText>& recorded) {
  std::unordered_map<std::uint64_t, int> glyph_at_uv;
  for (int g = 0; g < font.Glyphs.Size; ++g)
    if (font.Glyphs[g].Visible) glyph_at_uv[uv_key(font.Glyphs[g].U0, font.Glyphs[g].V0)] = g;
  auto index_of = [&](const ImFontGlyph* glyph) {
    return static_cast<int>(glyph - font.Glyphs.Data);
  };

  // What was recorded, per panel and glyph.
  std::map<std::string, std::map<int, int>> allowed;
  for (const DrawnText& d : recorded) {
    auto& counts = allowed[d.panel];
    const char* s = d.text.c_str();
    const char* end = s + d.text.size();
    while (s < end) {
      unsigned int c = 0;
      s += ImTextCharFromUtf8(&c, s, end);
      if (c == 0) break;
      if (c == '\n' || c == '\r') continue;
      const ImFontGlyph* glyph = font.FindGlyph(static_cast<ImWchar>(c));
      if (glyph && glyph->Visible) ++counts[index_of(glyph)];
    }
  }

  std::vector<UnrecordedText> out;
  for (int l = 0; l < draw_data.CmdListsCount; ++l) {
    const ImDrawList& list = *draw_data.CmdLists[l];
    // The vertices the font texture's commands draw.
    std::unordered_set<unsigned int> font_vertices;
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      if (cmd.UserCallback || cmd.TextureId != font_texture) continue;
      for (unsigned int i = 0; i < cmd.ElemCount; ++i)
        font_vertices.insert(cmd.VtxOffset + list.IdxBuffer[static_cast<int>(cmd.IdxOffset + i)]);
    }
    GlyphsDrawn drawn;
    const ImVector<ImDrawVert>& v = list.VtxBuffer;
    for (int i = 0; i + 3 < v.Size; ++i) {
      if (!font_vertices.count(static_cast<unsigned int>(i))) continue;
      const auto it = glyph_at_uv.find(uv_key(v[i].uv.x, v[i].uv.y));
      if (it == glyph_at_uv.end()) continue;
      const ImFontGlyph& g = font.Glyphs[it->second];
      if (v[i + 1].uv.x != g.U1 || v[i + 1].uv.y != g.V0 || v[i + 2].uv.x != g.U1 ||
          v[i + 2].uv.y != g.V1 || v[i + 3].uv.x != g.U0 || v[i + 3].uv.y != g.V1)
        continue;
      drawn.add(it->second, v[i].pos);
      i += 3;
    }
    const std::string panel = list._OwnerName ? list._OwnerName : "?";
    std::map<int, int> room = allowed[panel];
    UnrecordedText extra{panel, ""};
    for (const int g : drawn.order) {
      if (room[g] > 0) {
        --room[g];
        continue;
      }
      extra.characters += utf8(font.Glyphs[g].Codepoint);
    }
    if (!extra.characters.empty()) out.push_back(std::move(extra));
  }
  return out;
}

std::vector<UnrecordedText> unrecorded_text_in_last_frame(const std::vector<DrawnText>& recorded) {
  const ImDrawData* data = ImGui::GetDrawData();
  if (!data || !data->Valid) return {};
  const ImGuiIO& io = ImGui::GetIO();
  return unrecorded_text(*data, *io.Fonts->Fonts[0], io.Fonts->TexID, recorded);
}

}  // namespace rockface::ui

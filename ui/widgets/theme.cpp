#include "ui/widgets/theme.h"

#include <algorithm>
#include <filesystem>

#include <imgui.h>

#include "ui/widgets/widgets_scroll.h"

namespace rockface::ui {

namespace {
// A font with the degree sign, ², ³, ±, ×, σ and "…"; Debian's fonts-dejavu-core.
constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

void load_font(float px) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  if (std::filesystem::exists(kFontFile)) {
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x03C3, 0x03C3, 0x2013, 0x2014, 0x2026, 0x2026,
                                     0x2190, 0x2193, 0x2212, 0x2212, 0x25B8, 0x25B8, 0};
    io.Fonts->AddFontFromFileTTF(kFontFile, px, nullptr, ranges);
  } else {
    ImFontConfig config;
    config.SizePixels = px;
    io.Fonts->AddFontDefault(&config);
  }
}

void daylight_colours(ImVec4* c) {
  // Black on white and saturated accents: sunlight washes out greys.
  c[ImGuiCol_Text] = ImVec4(0, 0, 0, 1);
  c[ImGuiCol_TextDisabled] = ImVec4(0.30f, 0.30f, 0.30f, 1);
  c[ImGuiCol_WindowBg] = ImVec4(1, 1, 1, 1);
  c[ImGuiCol_ChildBg] = ImVec4(1, 1, 1, 0);
  c[ImGuiCol_PopupBg] = ImVec4(1, 1, 0.94f, 1);
  c[ImGuiCol_FrameBg] = ImVec4(0.86f, 0.86f, 0.86f, 1);
  c[ImGuiCol_SliderGrab] = ImVec4(0.1f, 0.45f, 0.9f, 1);
  c[ImGuiCol_Button] = ImVec4(0.80f, 0.86f, 0.95f, 1);
  c[ImGuiCol_ButtonHovered] = ImVec4(0.65f, 0.76f, 0.93f, 1);
  c[ImGuiCol_ButtonActive] = ImVec4(0.35f, 0.55f, 0.90f, 1);
  c[ImGuiCol_PlotHistogram] = ImVec4(0.05f, 0.35f, 0.80f, 1);
  c[ImGuiCol_TableHeaderBg] = ImVec4(0.85f, 0.85f, 0.85f, 1);
  c[ImGuiCol_Border] = ImVec4(0.3f, 0.3f, 0.3f, 1);
  c[ImGuiCol_Separator] = ImVec4(0.3f, 0.3f, 0.3f, 1);
}

void tunnel_colours(ImVec4* c) {
  // Light grey on near-black, amber accents: readable under tunnel lamps
  // without dazzling; no pure white areas.
  c[ImGuiCol_Text] = ImVec4(0.92f, 0.92f, 0.90f, 1);
  c[ImGuiCol_TextDisabled] = ImVec4(0.68f, 0.68f, 0.66f, 1);
  c[ImGuiCol_WindowBg] = ImVec4(0.06f, 0.06f, 0.07f, 1);
  c[ImGuiCol_ChildBg] = ImVec4(0, 0, 0, 0);
  c[ImGuiCol_PopupBg] = ImVec4(0.14f, 0.14f, 0.16f, 1);
  c[ImGuiCol_FrameBg] = ImVec4(0.20f, 0.20f, 0.22f, 1);
  c[ImGuiCol_SliderGrab] = ImVec4(0.95f, 0.65f, 0.15f, 1);
  c[ImGuiCol_Button] = ImVec4(0.22f, 0.24f, 0.30f, 1);
  c[ImGuiCol_ButtonHovered] = ImVec4(0.32f, 0.34f, 0.42f, 1);
  c[ImGuiCol_ButtonActive] = ImVec4(0.60f, 0.42f, 0.10f, 1);
  c[ImGuiCol_PlotHistogram] = ImVec4(0.95f, 0.65f, 0.15f, 1);
  c[ImGuiCol_TableHeaderBg] = ImVec4(0.18f, 0.18f, 0.20f, 1);
  c[ImGuiCol_TableRowBgAlt] = ImVec4(1, 1, 1, 0.05f);
  c[ImGuiCol_Border] = ImVec4(0.55f, 0.55f, 0.55f, 1);
  c[ImGuiCol_Separator] = ImVec4(0.45f, 0.45f, 0.45f, 1);
  // A selected row: a grey-blue that keeps the verdicts' colours readable.
  c[ImGuiCol_Header] = ImVec4(0.26f, 0.28f, 0.36f, 1);
  c[ImGuiCol_HeaderHovered] = ImVec4(0.30f, 0.32f, 0.42f, 1);
  c[ImGuiCol_HeaderActive] = ImVec4(0.34f, 0.36f, 0.46f, 1);
}

}  // namespace

const char* theme_name(Theme theme) {
  return theme == Theme::daylight ? "daylight" : "tunnel";
}

std::optional<Theme> theme_from_name(std::string_view name) {
  if (name == "daylight") return Theme::daylight;
  if (name == "tunnel") return Theme::tunnel;
  return std::nullopt;
}

float theme_font_px(Theme theme) {
  // 24 px in daylight (3.6 mm capitals on a 150 dpi tablet, read at arm's
  // length in glare), 20 px in the tunnel.
  return theme == Theme::daylight ? 24.0f : 20.0f;
}

void apply_theme(Theme theme, float scale, float min_target_px) {
  load_font(theme_font_px(theme) * scale);
  ImGuiStyle& style = ImGui::GetStyle();
  style = ImGuiStyle();
  if (theme == Theme::daylight)
    ImGui::StyleColorsLight();
  else
    ImGui::StyleColorsDark();
  style.ScaleAllSizes(scale);
  const float font = theme_font_px(theme) * scale;
  style.FramePadding = ImVec2(14 * scale, std::max(12 * scale, (min_target_px - font) / 2));
  style.ItemSpacing = ImVec2(12 * scale, 10 * scale);
  // Panels scroll by a drag of the finger (ui/widgets/widgets_scroll.h): the scroll
  // bar is a thin indicator of where the content is, not a touch target
  // (issue 27), and leaves the panels' width to their buttons.
  style.ScrollbarSize = kScrollIndicatorPx * scale;
  style.GrabMinSize = 28 * scale;
  style.FrameRounding = 6 * scale;
  style.WindowRounding = 0;
  style.FrameBorderSize = theme == Theme::daylight ? 1.0f : 0.0f;
  if (theme == Theme::daylight)
    daylight_colours(style.Colors);
  else
    tunnel_colours(style.Colors);
}

}  // namespace rockface::ui

#include "ui/widgets.h"

#include <filesystem>

namespace rockface::ui {

namespace {
// A font with the degree sign and good hinting; Debian's fonts-dejavu-core.
constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
// Body text of 20 px at scale 1: readable at arm's length on a 10" tablet.
constexpr float kFontPx = 20;
}  // namespace

void apply_daylight_theme(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  if (std::filesystem::exists(kFontFile)) {
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x2013, 0x2014, 0x2190, 0x2193, 0};
    io.Fonts->AddFontFromFileTTF(kFontFile, kFontPx * scale, nullptr, ranges);
  } else {
    ImFontConfig config;
    config.SizePixels = kFontPx * scale;
    io.Fonts->AddFontDefault(&config);
  }
  ImGui::StyleColorsLight();
  ImGuiStyle& style = ImGui::GetStyle();
  style.ScaleAllSizes(scale);
  style.FramePadding = ImVec2(14 * scale, 12 * scale);
  style.ItemSpacing = ImVec2(12 * scale, 10 * scale);
  style.ScrollbarSize = 28 * scale;
  style.GrabMinSize = 28 * scale;
  style.FrameRounding = 6 * scale;
  style.WindowRounding = 0;
  // Black on white and saturated accents: sunlight washes out greys.
  ImVec4* c = style.Colors;
  c[ImGuiCol_Text] = ImVec4(0, 0, 0, 1);
  c[ImGuiCol_WindowBg] = ImVec4(1, 1, 1, 1);
  c[ImGuiCol_FrameBg] = ImVec4(0.86f, 0.86f, 0.86f, 1);
  c[ImGuiCol_SliderGrab] = ImVec4(0.1f, 0.45f, 0.9f, 1);
  c[ImGuiCol_Button] = ImVec4(0.80f, 0.86f, 0.95f, 1);
  c[ImGuiCol_ButtonHovered] = ImVec4(0.65f, 0.76f, 0.93f, 1);
  c[ImGuiCol_ButtonActive] = ImVec4(0.35f, 0.55f, 0.90f, 1);
  c[ImGuiCol_PlotHistogram] = ImVec4(0.1f, 0.45f, 0.9f, 1);
  c[ImGuiCol_TableHeaderBg] = ImVec4(0.85f, 0.85f, 0.85f, 1);
  c[ImGuiCol_Border] = ImVec4(0.3f, 0.3f, 0.3f, 1);
}

ImU32 verdict_colour(BlockVerdict verdict) {
  switch (verdict) {
    case BlockVerdict::moves:
      return IM_COL32(230, 20, 20, 255);
    case BlockVerdict::marginal:
      return IM_COL32(255, 140, 0, 255);
    case BlockVerdict::holds:
      return IM_COL32(240, 220, 0, 255);
    case BlockVerdict::keyed:
      return IM_COL32(20, 180, 60, 255);
    case BlockVerdict::infinite:
      return IM_COL32(150, 150, 150, 255);
  }
  return IM_COL32(0, 0, 0, 255);
}

bool TouchTargets::button(const std::string& label, float width, bool enabled) {
  if (!enabled) ImGui::BeginDisabled();
  const bool pressed = ImGui::Button(label.c_str(), ImVec2(width, kTouchTargetPx * scale_));
  if (!enabled) ImGui::EndDisabled();
  // The visible label is what a script names (ImGui's "##id" suffix is not).
  const std::string name = label.substr(0, label.find("##"));
  rects_[name] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax(), enabled};
  return pressed && enabled;
}

std::optional<TargetRect> TouchTargets::find(const std::string& label) const {
  const auto it = rects_.find(label);
  if (it == rects_.end()) return std::nullopt;
  return it->second;
}

}  // namespace rockface::ui

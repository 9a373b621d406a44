#include "ui/widgets/widgets_text.h"

#include <algorithm>
#include <functional>

#include <imgui_internal.h>

#include "ui/widgets/format.h"
#include "ui/widgets/widgets.h"

namespace rockface::ui {

namespace {

std::vector<DrawnText>& log() {
  static std::vector<DrawnText> drawn;
  return drawn;
}

const char* panel_name() {
  const ImGuiWindow* w = ImGui::GetCurrentWindowRead();
  return w ? w->Name : "?";
}

float text_width(std::string_view text) {
  return ImGui::CalcTextSize(text.data(), text.data() + text.size()).x;
}

// Space left on the line from the cursor, at least one character (a line
// squeezed to nothing still shows "…").
float space_left() {
  return ImGui::GetContentRegionAvail().x;
}

// The whole of a shortened text, one tap away.
void whole_text_popup(const std::string& id, std::string_view text) {
  if (!ImGui::BeginPopup(id.c_str())) return;
  const float most = ImGui::GetMainViewport()->Size.x * 0.8f;
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + std::min(most, text_width(text) + 1));
  ImGui::TextUnformatted(text.data(), text.data() + text.size());
  record_drawn_text(text, std::min(most, text_width(text)), most + 1);
  ImGui::PopTextWrapPos();
  // A tap outside closes it too; the button is a thumb target (9 mm at the
  // tablet's DPI, whatever the theme's type size).
  const float side = touch_target_px();
  if (ImGui::Button("Close", ImVec2(std::max(side, 4 * ImGui::GetFontSize()), side)))
    ImGui::CloseCurrentPopup();
  record_touch_target("Close (whole text)", ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  record_drawn_text("Close", ImGui::CalcTextSize("Close").x, ImGui::GetItemRectSize().x);
  ImGui::EndPopup();
}

void one_line(std::string_view whole) {
  // No machine's folders on the screen (an error naming its file names it
  // by its file name): they mean nothing at the face and end up in
  // screenshots.
  const std::string cut = format::without_folders(whole);
  const std::string_view text = cut;
  const float room = space_left();
  const float width = text_width(text);
  if (width <= room) {
    ImGui::TextUnformatted(text.data(), text.data() + text.size());
    record_drawn_text(text, width, room);
    return;
  }
  const std::string shown = shortened(text, room);
  const std::string id = "##whole" + std::to_string(std::hash<std::string_view>{}(text));
  ImGui::PushID(id.c_str());
  // A selectable as wide as the text and a thumb high (the theme makes a
  // frame 9 mm high): the tap target that shows the whole.
  ImGui::PushStyleVar(ImGuiStyleVar_SelectableTextAlign, ImVec2(0, 0.5f));
  // Beside buttons ImGui moves text down to their text line; this target is
  // their height and centres its text itself.
  ImGui::GetCurrentWindow()->DC.CurrLineTextBaseOffset = 0;
  // At least a thumb wide when the line has the room (a label shortened to
  // "Jo…" is still a target).
  const float wide = std::max(text_width(shown), std::min(room, touch_target_px()));
  if (ImGui::Selectable((shown + "##short").c_str(), false, 0,
                        ImVec2(wide, std::max(ImGui::GetFrameHeight(), touch_target_px()))))
    ImGui::OpenPopup("whole text");
  ImGui::PopStyleVar();
  record_touch_target("whole text of " + shown, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  record_drawn_text(shown, text_width(shown), room);
  whole_text_popup("whole text", text);
  ImGui::PopID();
}

void wrapped(std::string_view whole) {
  const std::string cut = format::without_folders(whole);
  const std::string_view text = cut;
  const float room = space_left();
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted(text.data(), text.data() + text.size());
  ImGui::PopTextWrapPos();
  const float width =
      ImGui::CalcTextSize(text.data(), text.data() + text.size(), false, std::max(room, 1.0f)).x;
  record_drawn_text(text, width, room);
}

}  // namespace

void record_drawn_text(std::string_view text, float width, float available) {
  log().push_back({std::string(text), width, available, panel_name()});
}

void progress_bar(float fraction, std::string_view whole, float height) {
  const float room = space_left();
  const std::string text = shortened(whole, room - 2 * ImGui::GetStyle().FramePadding.x);
  ImGui::ProgressBar(fraction, ImVec2(-1, height), text.c_str());
  record_drawn_text(text, text_width(text), room);
}

void clear_drawn_text() {
  log().clear();
}

const std::vector<DrawnText>& drawn_text() {
  return log();
}

std::string shortened(std::string_view text, float width) {
  if (text_width(text) <= width) return std::string(text);
  static const std::string ellipsis = "…";
  // Whole UTF-8 characters only: cut before a continuation byte.
  std::size_t n = text.size();
  while (n > 0) {
    --n;
    while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80) --n;
    const std::string candidate = std::string(text.substr(0, n)) + ellipsis;
    if (text_width(candidate) <= width) return candidate;
  }
  return ellipsis;
}

void label(std::string_view text) {
  one_line(text);
}

void label_in_row(std::string_view text) {
  // Plain text is moved down to the buttons' text line; a shortened one is
  // a selectable of the buttons' height, centred already.
  if (text_width(format::without_folders(text)) <= space_left()) ImGui::AlignTextToFramePadding();
  one_line(text);
}

void label_in_row(std::string_view text, ImU32 colour) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  label_in_row(text);
  ImGui::PopStyleColor();
}

void label(std::string_view text, ImU32 colour) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  one_line(text);
  ImGui::PopStyleColor();
}

void paragraph(std::string_view text) {
  wrapped(text);
}

void paragraph(std::string_view text, ImU32 colour) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  wrapped(text);
  ImGui::PopStyleColor();
}

void note(std::string_view text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  wrapped(text);
  ImGui::PopStyleColor();
}

void bullet(std::string_view text) {
  ImGui::Bullet();
  ImGui::SameLine();
  wrapped(text);
}

void field(std::string_view title, std::string_view value) {
  one_line(std::string(title) + ": " + std::string(value));
}

void heading(std::string_view text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_PlotHistogram));
  one_line(text);
  ImGui::PopStyleColor();
}

ImU32 warning_colour() {
  // Dark red on the daylight theme's white, light red on the tunnel's
  // black: both well above 4.5 : 1 contrast.
  const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
  return bg.x > 0.5f ? IM_COL32(190, 0, 0, 255) : IM_COL32(255, 110, 110, 255);
}

}  // namespace rockface::ui

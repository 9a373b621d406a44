#include "ui/widgets/widgets_controls.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

// ImGui 1.86 insets a slider's grab by this from its frame (SliderBehaviorT).
constexpr float kGrabPaddingPx = 2;

std::string value_text(const char* format, double value) {
  char buf[128];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

// The text ImGui draws in the frame just drawn, recorded against it.
void record_in_frame(const std::string& text) {
  const float room = ImGui::GetItemRectSize().x - 2 * ImGui::GetStyle().FramePadding.x;
  record_drawn_text(text, ImGui::CalcTextSize(text.c_str()).x, room);
}

}  // namespace

GrabRect slider_grab(ImVec2 frame_min, ImVec2 frame_max, float fraction, float grab_width) {
  const float track = frame_max.x - frame_min.x - 2 * kGrabPaddingPx;
  const float grab = std::min(grab_width, track);
  const float left =
      frame_min.x + kGrabPaddingPx + std::clamp(fraction, 0.0f, 1.0f) * (track - grab);
  return {ImVec2(left, frame_min.y + kGrabPaddingPx),
          ImVec2(left + grab, frame_max.y - kGrabPaddingPx)};
}

bool slider(TouchTargets& targets, const std::string& name, float* value, float lo, float hi,
            const char* format, float width) {
  const float side = targets.target_px();
  // The frame is the grab's height and its padding: a target-high grab.
  const float pad_y = std::max(ImGui::GetStyle().FramePadding.y,
                               (side + 2 * kGrabPaddingPx - ImGui::GetFontSize()) / 2);
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, pad_y));
  ImGui::PushStyleVar(ImGuiStyleVar_GrabMinSize, side);
  ImGui::SetNextItemWidth(width);
  const bool changed = ImGui::SliderFloat(("##" + name).c_str(), value, lo, hi, format);
  ImGui::PopStyleVar(2);
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  // A slider is dragged: a drag begun on it moves it, never its panel.
  const unsigned id = ImGui::GetItemID();
  targets.record_dragged(name, min, max, id);
  const float fraction = hi > lo ? (*value - lo) / (hi - lo) : 0.0f;
  const GrabRect grab = slider_grab(min, max, fraction, side);
  targets.record_dragged(name + " grab", grab.min, grab.max, id);
  record_in_frame(value_text(format, *value));
  return changed;
}

bool checkbox(TouchTargets& targets, const std::string& name, const std::string& label,
              bool* checked) {
  // ImGui's box is the frame's height: the theme makes that a target.
  const bool changed = ImGui::Checkbox((label + "##" + name).c_str(), checked);
  targets.record(name, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  if (!label.empty()) {
    const float box = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x;
    record_drawn_text(label, ImGui::CalcTextSize(label.c_str()).x,
                      ImGui::GetItemRectSize().x - box);
  }
  return changed;
}

std::optional<std::size_t> choice(TouchTargets& targets, const std::string& name,
                                  const std::string& shown, const std::vector<std::string>& items,
                                  std::optional<std::size_t> current) {
  std::optional<std::size_t> tapped;
  ImGui::SetNextItemWidth(-1);
  // Where the frame goes: once open, ImGui's last item is the list's window.
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float width = ImGui::CalcItemWidth();
  const bool open = ImGui::BeginCombo(("##" + name).c_str(), shown.c_str());
  // Recorded after the list (whose items are a window of their own): the
  // last item is then the combo's frame.
  auto record_frame = [&] {
    targets.record(name, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
    // The arrow's square is not room for the text.
    const float room =
        ImGui::GetItemRectSize().x - ImGui::GetFrameHeight() - 2 * ImGui::GetStyle().FramePadding.x;
    record_drawn_text(shown, ImGui::CalcTextSize(shown.c_str()).x, room);
  };
  if (!open) {
    record_frame();
    return tapped;
  }
  const ImVec2 frame_min = at, frame_max(at.x + width, at.y + ImGui::GetFrameHeight());
  const float side = targets.target_px();
  for (std::size_t i = 0; i < items.size(); ++i) {
    const float room = ImGui::GetContentRegionAvail().x;
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::Selectable(items[i].c_str(), current == i, 0, ImVec2(0, side))) tapped = i;
    ImGui::PopID();
    targets.record(name + ": " + items[i], ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
    record_drawn_text(items[i], ImGui::CalcTextSize(items[i].c_str()).x, room);
  }
  ImGui::EndCombo();
  targets.record(name, frame_min, frame_max);
  const float room =
      frame_max.x - frame_min.x - ImGui::GetFrameHeight() - 2 * ImGui::GetStyle().FramePadding.x;
  record_drawn_text(shown, ImGui::CalcTextSize(shown.c_str()).x, room);
  return tapped;
}

bool collapsing_section(TouchTargets& targets, const std::string& title, bool open_at_first) {
  const bool open = ImGui::CollapsingHeader(
      title.c_str(), open_at_first ? ImGuiTreeNodeFlags_DefaultOpen : ImGuiTreeNodeFlags_None);
  targets.record(title, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  // The arrow takes a font's height and its spacing before the title.
  const float room =
      ImGui::GetItemRectSize().x - ImGui::GetFontSize() - 3 * ImGui::GetStyle().FramePadding.x;
  record_drawn_text(title, ImGui::CalcTextSize(title.c_str()).x, room);
  return open;
}

bool text_field(TouchTargets& targets, const std::string& name, std::string* text) {
  const bool changed = ImGui::InputText(("##" + name).c_str(), text);
  targets.record(name, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  // A typed line scrolls inside its field: what shows is at most the field.
  const float room = ImGui::GetItemRectSize().x - 2 * ImGui::GetStyle().FramePadding.x;
  record_drawn_text(*text, std::min(ImGui::CalcTextSize(text->c_str()).x, room), room);
  return changed;
}

bool number_field(TouchTargets& targets, const std::string& name, double* value, const char* format,
                  float width, double step) {
  ImGui::SetNextItemWidth(width);
  const bool changed = ImGui::InputDouble(("##" + name).c_str(), value, step, 10 * step, format);
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  if (step <= 0) {
    targets.record(name, min, max);
    record_in_frame(value_text(format, *value));
    return changed;
  }
  // ImGui 1.86's InputScalar: the field, then "-" and "+" squares of the
  // frame's height, each after the inner spacing, all in one group.
  const float button = ImGui::GetFrameHeight(), gap = ImGui::GetStyle().ItemInnerSpacing.x;
  const float plus = max.x - button, minus = plus - gap - button;
  targets.record(name, min, ImVec2(minus - gap, max.y));
  // The steps repeat while held (pressed as the finger lands): a drag
  // begun on one is left to it, so it never both steps and scrolls. Their
  // ids as InputScalar makes them, under the field's label.
  ImGui::PushID(("##" + name).c_str());
  const unsigned minus_id = ImGui::GetID("-"), plus_id = ImGui::GetID("+");
  ImGui::PopID();
  targets.record_dragged(name + " -", ImVec2(minus, min.y), ImVec2(minus + button, max.y),
                         minus_id);
  targets.record_dragged(name + " +", ImVec2(plus, min.y), max, plus_id);
  const float room = minus - gap - min.x - 2 * ImGui::GetStyle().FramePadding.x;
  const std::string shown = value_text(format, *value);
  record_drawn_text(shown, ImGui::CalcTextSize(shown.c_str()).x, room);
  for (const char* sign : {"-", "+"}) record_drawn_text(sign, ImGui::CalcTextSize(sign).x, button);
  return changed;
}

}  // namespace rockface::ui

#include "ui/widgets/toggle_button.h"

#include <imgui.h>

namespace rockface::ui {

bool toggle_button(TouchTargets& targets, const std::string& label, bool on, bool enabled,
                   float width) {
  if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
  const bool pressed = targets.button(label, width, enabled);
  if (on) ImGui::PopStyleColor();
  return pressed;
}

bool toggle_button_in_row(TouchTargets& targets, const std::string& label, bool on, bool enabled) {
  same_line_if_fits(button_width(label, targets.target_px()));
  return toggle_button(targets, label, on, enabled);
}

}  // namespace rockface::ui

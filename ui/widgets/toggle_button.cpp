#include "ui/widgets/toggle_button.h"

#include <imgui.h>

namespace rockface::ui {

bool toggle_button(TouchTargets& targets, const std::string& label, bool on, bool enabled) {
  if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
  const bool pressed = targets.button(label, 0, enabled);
  if (on) ImGui::PopStyleColor();
  return pressed;
}

}  // namespace rockface::ui

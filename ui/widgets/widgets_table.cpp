#include "ui/widgets/widgets_table.h"

#include <imgui.h>

#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

void table_headers_row() {
  // What ImGui's TableHeadersRow does, with each name recorded.
  const int columns = ImGui::TableGetColumnCount();
  ImGui::TableNextRow(ImGuiTableRowFlags_Headers, ImGui::GetTextLineHeight());
  for (int c = 0; c < columns; ++c) {
    if (!ImGui::TableSetColumnIndex(c)) continue;
    const char* name = ImGui::TableGetColumnName(c);
    const float room = ImGui::GetContentRegionAvail().x;
    ImGui::PushID(c);
    ImGui::TableHeader(name);
    ImGui::PopID();
    record_drawn_text(name, ImGui::CalcTextSize(name, nullptr, true).x, room);
  }
}

bool selectable_row(TouchTargets& targets, const std::string& name, bool selected) {
  const float height = targets.target_px();
  const bool tapped = ImGui::Selectable(("##row " + name).c_str(), selected,
                                        ImGuiSelectableFlags_SpanAllColumns, ImVec2(0, height));
  targets.record(name, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  ImGui::SameLine();
  return tapped;
}

}  // namespace rockface::ui

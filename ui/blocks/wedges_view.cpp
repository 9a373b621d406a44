#include "ui/blocks/wedges_view.h"

#include <memory>

#include <imgui.h>

#include "ui/app/app_state.h"
#include "ui/widgets/widgets_table.h"

namespace rockface::ui {

namespace {

void find_wedges(AppState& app) {
  WedgeRunner* runner = app.services.wedges;
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  auto result = std::make_shared<WedgeTable>();
  app.task.start(
      "Wedges",
      [runner, file, visit, result](Progress& progress) {
        *result = runner->wedges(file, visit, progress);
        return std::to_string(result->rows.size()) + " wedges around the excavation";
      },
      [&app, result](const TaskOutcome& outcome) {
        WedgesState& w = app.blocks.wedges;
        if (outcome.kind != TaskOutcome::Kind::done) {
          w.table.reset();
          w.picture.clear();
          w.message = outcome.message;
          return;
        }
        w.message.clear();
        w.picture.set(result->bgr);
        result->bgr.release();
        w.table = std::move(*result);
      });
}

void draw_wedge_table(AppState& app, const WedgeTable& t) {
  const ImGuiTableFlags flags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchSame;
  if (!ImGui::BeginTable("wedges", static_cast<int>(t.columns.size()), flags)) return;
  for (const auto& c : t.columns) ImGui::TableSetupColumn(c.c_str());
  table_headers_row();
  const float row_height = app.targets.target_px();
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    ImGui::TableNextRow(0, row_height);
    if (i < t.marginal.size() && t.marginal[i])
      ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(255, 200, 120, 255));
    for (std::size_t c = 0; c < t.rows[i].size(); ++c) {
      ImGui::TableNextColumn();
      label(t.rows[i][c]);
      if (c == 0)
        app.targets.record_area("wedge " + t.rows[i][0], ImGui::GetItemRectMin(),
                                ImGui::GetItemRectMax());
    }
  }
  ImGui::EndTable();
}

}  // namespace

void draw_wedges_view(AppState& app) {
  WedgesState& w = app.blocks.wedges;
  if (!app.session) return;
  if (w.file != app.session->file() || w.visit != app.session->visit()) {
    w.file = app.session->file();
    w.visit = app.session->visit();
    w.table.reset();
    w.message.clear();
    w.picture.clear();
  }
  const bool can = app.services.wedges && app.session->visit() && !app.task.running();
  if (app.targets.button_in_row("Find wedges", can)) find_wedges(app);
  paragraph(
      "Wedges that the visit's sets form around the tunnel's design section, "
      "each at its largest (joints of unlimited persistence).");
  if (!app.services.wedges) note("No wedge analysis in this build.");
  if (!w.message.empty()) paragraph(w.message);
  if (!w.table) return;
  const WedgeTable& t = *w.table;
  for (const auto& line : t.lines) paragraph(line);
  const SplitLayout layout = split_for_side_panel(0.4f * ImGui::GetContentRegionAvail().x);
  ImGui::BeginChild("wedge table", layout.main);
  if (t.rows.empty())
    paragraph("No removable wedge.");
  else
    draw_wedge_table(app, t);
  for (const auto& n : t.notes) paragraph(n);
  ImGui::EndChild();
  begin_side_panel("wedge picture", layout, true);
  w.picture.draw(ImGui::GetContentRegionAvail().x);
  ImGui::EndChild();
}

}  // namespace rockface::ui

// Blocks: the block table (finite, removable, mode, FoS, rotatable, margin,
// marginal rows highlighted), the blocks drawn on the model coloured by
// verdict, and the report of the block tapped (on the model or in the
// table). "Run analysis" analyses the visit on the worker.
#include <opencv2/imgproc.hpp>

#include "ui/motion_playback.h"
#include "ui/overlay_legend.h"
#include "ui/screens/screens.h"
#include "ui/wedges_view.h"

namespace rockface::ui {

namespace {

// Screen outline of a block: its footprint on the 3D image
// (ui/overlay_blocks.h), projected.
std::vector<ImVec2> outline(AppState& app, const BlockView& block) {
  return block_outline_on_screen(app, block);
}

ImVec2 centre_of(const std::vector<ImVec2>& polygon) {
  ImVec2 c(0, 0);
  for (const auto& p : polygon) c = ImVec2(c.x + p.x, c.y + p.y);
  return ImVec2(c.x / polygon.size(), c.y / polygon.size());
}

bool contains(const std::vector<ImVec2>& polygon, ImVec2 p) {
  std::vector<cv::Point2f> contour;
  for (const auto& q : polygon) contour.emplace_back(q.x, q.y);
  return cv::pointPolygonTest(contour, cv::Point2f(p.x, p.y), false) >= 0;
}

float area_of(const std::vector<ImVec2>& polygon) {
  std::vector<cv::Point2f> contour;
  for (const auto& q : polygon) contour.emplace_back(q.x, q.y);
  return static_cast<float>(cv::contourArea(contour));
}

// Blocks on the model: translucent footprint, solid outline and a solid
// marker of the verdict's colour at the footprint's centre (what tests
// count). A tap selects the smallest block under the finger.
void draw_blocks_on_model(AppState& app, std::optional<ImVec2> tap) {
  const auto& blocks = app.session->blocks();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float s = app.targets.scale();
  std::optional<std::size_t> tapped;
  float tapped_area = 0;
  // Footprints first, then labels, then markers: a later block's
  // translucent fill never tints an earlier block's marker.
  std::vector<std::vector<ImVec2>> polys(blocks.size());
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    polys[i] = outline(app, blocks[i]);
    const std::vector<ImVec2>& poly = polys[i];
    if (poly.empty()) continue;
    // Tinted and outlined on the surface by the renderer (add_blocks_to_overlay).
    if (tap && contains(poly, *tap)) {
      const float a = area_of(poly);
      if (!tapped || a < tapped_area) {
        tapped = i;
        tapped_area = a;
      }
    }
  }
  for (std::size_t i = 0; i < blocks.size(); ++i)
    if (!polys[i].empty()) {
      const ImVec2 c = block_marker_on_screen(app, blocks[i]).value_or(centre_of(polys[i]));
      draw->AddText(ImVec2(c.x + 12 * s, c.y - 10 * s), IM_COL32(255, 255, 255, 255),
                    blocks[i].label.c_str());
    }
  for (std::size_t i = 0; i < blocks.size(); ++i)
    if (!polys[i].empty()) {
      const ImVec2 c = block_marker_on_screen(app, blocks[i]).value_or(centre_of(polys[i]));
      draw->AddCircleFilled(c, 9 * s, verdict_colour(blocks[i].verdict), 20);
      app.targets.record("block " + blocks[i].label, ImVec2(c.x - 9 * s, c.y - 9 * s),
                         ImVec2(c.x + 9 * s, c.y + 9 * s));
    }
  if (tap) app.selected_block = tapped;
}

void draw_table(AppState& app) {
  const auto& blocks = app.session->blocks();
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("blocks", 9, flags, ImVec2(0, 0))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* h :
       {"block", "from", "finite", "removable", "mode", "FoS", "rotatable", "margin", "verdict"})
    ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  const float row_height = kTouchTargetPx * app.targets.scale() * 0.8f;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const BlockView& b = blocks[i];
    ImGui::TableNextRow(0, row_height);
    if (b.marginal) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(255, 200, 120, 255));
    ImGui::TableNextColumn();
    const bool selected = app.selected_block && *app.selected_block == i;
    if (ImGui::Selectable(b.label.c_str(), selected, ImGuiSelectableFlags_SpanAllColumns,
                          ImVec2(0, row_height)))
      app.selected_block = i;
    app.targets.record("row " + b.label, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(b.source.c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(b.finite ? "yes" : "no");
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(b.removable ? "yes" : "no");
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(b.mode.c_str());
    ImGui::TableNextColumn();
    if (b.fos)
      ImGui::Text("%.2f", *b.fos);
    else
      ImGui::TextUnformatted("-");
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(!b.rotatable ? "-" : *b.rotatable ? "yes" : "no");
    ImGui::TableNextColumn();
    if (b.margin_deg)
      ImGui::Text("%.1f°", *b.margin_deg);
    else
      ImGui::TextUnformatted("-");
    ImGui::TableNextColumn();
    ImGui::PushStyleColor(ImGuiCol_Text, verdict_colour(b.verdict) | 0xFF000000);
    ImGui::TextUnformatted(b.marginal ? "MARGINAL" : verdict_name(b.verdict));
    ImGui::PopStyleColor();
  }
  ImGui::EndTable();
}

void start_analysis(AppState& app) {
  if (!app.services.analysis || !app.session || !app.session->visit()) return;
  AnalysisRunner* runner = app.services.analysis;
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  app.task.start(
      "Analysis",
      [runner, file, visit](Progress& progress) {
        const storage::RecordId id = runner->analyse(file, visit, progress);
        return "analysis " + std::to_string(id) + " saved";
      },
      [&app](const TaskOutcome&) {
        if (app.session) app.session->refresh();
        app.selected_block.reset();
      });
}

}  // namespace

void draw_blocks_screen(AppState& app) {
  if (!app.session) {
    ImGui::TextWrapped("Open a project first (Project).");
    return;
  }
  // The Wedges view (wedges around the excavation) in place of the blocks.
  if (app.targets.button(app.wedges.open ? "Blocks view" : "Wedges view", 0, true))
    app.wedges.open = !app.wedges.open;
  ImGui::SameLine();
  if (app.wedges.open) {
    draw_wedges_view(app);
    return;
  }
  const bool can_run = app.services.analysis && app.session->visit() && !app.session->read_only() &&
                       !app.task.running();
  if (app.targets.button("Run analysis", 0, can_run)) start_analysis(app);
  ImGui::SameLine();
  if (app.targets.button(app.rockmass.open ? "Block report" : "Rock mass", 0,
                         app.services.rockmass != nullptr))
    app.rockmass.open = !app.rockmass.open;
  ImGui::SameLine();
  if (const auto& a = app.session->analysis())
    ImGui::Text("Analysis %lld (%s, %s): %zu blocks", static_cast<long long>(a->id),
                a->preset.c_str(), a->created_at.substr(0, 19).c_str(), a->blocks.size());
  else
    ImGui::TextUnformatted("No analysis of this visit yet.");

  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float side = 380 * app.targets.scale();
  const float model_height = avail.y * 0.55f;
  ImGui::BeginChild("blocks left", ImVec2(avail.x - side, 0));
  if (app.model_view.has_model()) {
    add_blocks_to_overlay(app);  // ui/overlay_blocks.h: on the surface, depth-tested
    const auto interaction =
        app.model_view.draw(ImVec2(ImGui::GetContentRegionAvail().x, model_height), app.gesture);
    ImGui::PushClipRect(app.model_view.panel_min(), app.model_view.panel_max(), true);
    draw_blocks_on_model(app, interaction.tap);
    draw_motion_on_model(app);
    draw_model_overlays(app, ModelScreen::blocks);  // ui/overlay_legend.h
    ImGui::PopClipRect();
  }
  draw_table(app);
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginChild("block report", ImVec2(0, 0), true);
  const auto& blocks = app.session->blocks();
  if (app.rockmass.open) {
    draw_rockmass_view(app);  // ui/rockmass_view.h
  } else if (app.selected_block && *app.selected_block < blocks.size()) {
    const BlockView& b = blocks[*app.selected_block];
    for (const auto& line : b.summary) ImGui::TextWrapped("%s", line.c_str());
    draw_motion_controls(app, b);
    if (ImGui::CollapsingHeader("Full report (JSON)"))
      ImGui::TextWrapped("%s", b.report_text.c_str());
  } else {
    ImGui::TextWrapped("Tap a block on the model or in the table to see its report.");
  }
  ImGui::EndChild();
}

}  // namespace rockface::ui

// Blocks: the block table (finite, removable, mode, FoS, rotatable, margin,
// marginal rows highlighted), the blocks drawn on the model coloured by
// verdict, and the report of the block tapped (on the model or in the
// table). "Run analysis" analyses the visit on the worker.
#include <cmath>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "core/analysis/block_reading.h"
#include "ui/app/export_to_stick.h"
#include "ui/app/screens.h"
#include "ui/blocks/motion_playback.h"
#include "ui/blocks/support_view.h"
#include "ui/blocks/wedges_view.h"
#include "ui/view3d/overlay_legend.h"
#include "ui/view3d/overlay_text.h"
#include "ui/widgets/format.h"
#include "ui/widgets/widgets_table.h"

namespace rockface::ui {

namespace {

// Screen outline of a block: its footprint on the 3D image
// (ui/view3d/overlay_blocks.h), projected.
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

// Blocks on the model: translucent footprint, solid outline and a marker
// of the verdict's colour at the footprint's centre: a solid dot (what tests
// count) in a ring as wide as a gloved thumb (9 mm at the tablet's DPI), the
// marker's touch target. A tap on a marker selects its block; elsewhere the
// smallest block under the finger.
void draw_blocks_on_model(AppState& app, std::optional<ImVec2> tap) {
  const auto& blocks = app.session->blocks();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float s = app.targets.scale();
  const float half = 0.5f * app.targets.target_px();
  std::optional<std::size_t> tapped;
  float tapped_area = 0;
  // Footprints first, then labels, then markers: a later block's
  // translucent fill never tints an earlier block's marker.
  std::vector<std::vector<ImVec2>> polys(blocks.size());
  std::vector<ImVec2> markers(blocks.size());
  std::optional<std::size_t> on_marker;
  float nearest = half * half;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    polys[i] = outline(app, blocks[i]);
    const std::vector<ImVec2>& poly = polys[i];
    if (poly.empty()) continue;
    markers[i] = block_marker_on_screen(app, blocks[i]).value_or(centre_of(poly));
    // Tinted and outlined on the surface by the renderer (add_blocks_to_overlay).
    if (!tap) continue;
    const float dx = tap->x - markers[i].x, dy = tap->y - markers[i].y;
    if (dx * dx + dy * dy <= nearest) {
      nearest = dx * dx + dy * dy;
      on_marker = i;
    }
    if (contains(poly, *tap)) {
      const float a = area_of(poly);
      if (!tapped || a < tapped_area) {
        tapped = i;
        tapped_area = a;
      }
    }
  }
  if (on_marker) tapped = on_marker;
  const TextArea area = app.model_view.text_area();
  for (std::size_t i = 0; i < blocks.size(); ++i)
    if (!polys[i].empty()) {
      const std::string& label = blocks[i].block.id;
      if (const auto at = label_beside(markers[i], half, ImGui::CalcTextSize(label.c_str()), area))
        draw_text(draw, *at, IM_COL32(255, 255, 255, 255), label, area, TextHalo::dark);
    }
  for (std::size_t i = 0; i < blocks.size(); ++i)
    if (!polys[i].empty()) {
      const ImVec2 c = markers[i];
      const ImU32 colour = verdict_colour(blocks[i].verdict);
      draw->AddCircleFilled(c, half, (colour & 0x00FFFFFFu) | (90u << 24), 40);
      draw->AddCircle(c, half - 1.5f * s, colour, 40, 3 * s);
      draw->AddCircleFilled(c, 9 * s, colour, 20);
      app.targets.record("block " + blocks[i].block.id, ImVec2(c.x - half, c.y - half),
                         ImVec2(c.x + half, c.y + half));
    }
  if (tap) app.blocks.selected_block = on_marker ? on_marker : tapped;
}

// The mode in words for the table: a block that cannot move has none.
std::string mode_cell(const analysis::ReportBlock& b) {
  if (!b.finite || !b.removable || !b.mode || b.mode->type.empty() || b.mode->type == "none")
    return format::unknown();
  return b.mode->type;
}

void draw_table(AppState& app) {
  const auto& blocks = app.session->blocks();
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp;
  if (!ImGui::BeginTable("blocks", 6, flags, ImVec2(0, 0))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  // Weights, not content: a shortened cell must not shrink its column.
  for (const auto& [h, weight] :
       {std::pair{"Block", 1.0f}, std::pair{"Verdict", 1.3f}, std::pair{"Mode", 1.4f},
        std::pair{"FoS", 0.8f}, std::pair{"Margin", 1.0f}, std::pair{"Can rotate", 1.3f}})
    ImGui::TableSetupColumn(h, ImGuiTableColumnFlags_WidthStretch, weight);
  table_headers_row();
  // Rows are touch targets: a full thumb high.
  const float row_height = app.targets.target_px();
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const analysis::ReportBlock& b = blocks[i].block;
    const analysis::BlockVerdict verdict = blocks[i].verdict;
    ImGui::TableNextRow(0, row_height);
    if (b.marginal) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(255, 200, 120, 255));
    ImGui::TableNextColumn();
    const bool selected = app.blocks.selected_block && *app.blocks.selected_block == i;
    if (selectable_row(app.targets, "row " + b.id, selected)) app.blocks.selected_block = i;
    label(b.id);
    ImGui::TableNextColumn();
    label(b.marginal ? "marginal" : analysis::verdict_name(verdict),
          b.marginal ? IM_COL32(0, 0, 0, 255) : verdict_text_colour(verdict));
    ImGui::TableNextColumn();
    label(mode_cell(b));
    ImGui::TableNextColumn();
    label(b.fos ? format::text(format::FactorOfSafety{*b.fos}) : format::unknown());
    ImGui::TableNextColumn();
    label(!std::isnan(b.margin_deg) ? format::text(format::Angle{b.margin_deg})
                                    : format::unknown());
    ImGui::TableNextColumn();
    const std::optional<bool> rotates = analysis::can_rotate(b);
    label(!rotates ? format::unknown() : *rotates ? "yes" : "no");
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
        app.blocks.selected_block.reset();
      });
}

// The visit's field report, a PDF beside the project file
// (NAME-visit-N.pdf); written again over the last one.
void draw_field_report_button(AppState& app) {
  FieldReportRunner* runner = app.services.field_report;
  if (!runner) return;
  const bool can = app.session->visit() && !app.task.running();
  if (!app.targets.button_in_row("Field report", can)) return;
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  const auto pdf =
      file.parent_path() / (file.stem().string() + "-visit-" + std::to_string(visit) + ".pdf");
  app.task.start("Field report", [runner, file, visit, pdf](Progress& progress) {
    const std::string holds = runner->write(file, visit, pdf, progress);
    return pdf.filename().string() + " written (" + holds + ")";
  });
}

}  // namespace

void draw_blocks_screen(AppState& app) {
  if (!app.session) {
    paragraph("Open a project first (Project).");
    return;
  }
  // The Wedges view (wedges around the excavation) in place of the blocks.
  if (!app.blocks.support.open &&
      app.targets.button(app.blocks.wedges.open ? "Blocks view" : "Wedges view", 0, true))
    app.blocks.wedges.open = !app.blocks.wedges.open;
  if (app.blocks.wedges.open) {
    draw_wedges_view(app);
    return;
  }
  // Issue 44: the round's support in place of the blocks.
  if (app.targets.button_in_row(app.blocks.support.open ? "Back to the blocks" : "Support view",
                                app.services.support != nullptr))
    app.blocks.support.open = !app.blocks.support.open;
  if (app.blocks.support.open) {
    draw_support_view(app);
    return;
  }
  const bool can_run = app.services.analysis && app.session->visit() && !app.session->read_only() &&
                       !app.task.running();
  if (app.targets.button_in_row("Run analysis", can_run)) start_analysis(app);
  if (app.targets.button_in_row(app.blocks.rockmass.open ? "Block report" : "Rock mass",
                                app.services.rockmass != nullptr))
    app.blocks.rockmass.open = !app.blocks.rockmass.open;
  // Issue 27: the field report of the visit, written from the tablet.
  draw_field_report_button(app);
  // Issue 43: the visit's exports for the office, onto a USB stick.
  draw_export_to_stick(app);
  if (const auto& a = app.session->analysis())
    label("Analysis " + std::to_string(a->id) + " (" + a->preset + " preset, " +
          format::date_time(a->created_at) +
          "): " + format::count(static_cast<std::int64_t>(a->blocks.size()), "block", "blocks"));
  else
    label("No analysis of this visit yet: Run analysis.");

  const SplitLayout layout = split_for_side_panel(380 * app.targets.scale(), 0.4f);
  const float model_height = layout.main.y * (layout.stacked ? 0.6f : 0.55f);
  ImGui::BeginChild("blocks left", layout.main);
  if (app.model_view.has_model()) {
    add_blocks_to_overlay(app);  // ui/view3d/overlay_blocks.h: on the surface, depth-tested
    const auto interaction =
        app.model_view.draw(ImVec2(ImGui::GetContentRegionAvail().x, model_height), app.gesture);
    ImGui::PushClipRect(app.model_view.panel_min(), app.model_view.panel_max(), true);
    draw_blocks_on_model(app, interaction.tap);
    draw_motion_on_model(app);
    draw_model_overlays(app, ModelScreen::blocks);  // ui/view3d/overlay_legend.h
    ImGui::PopClipRect();
  }
  draw_table(app);
  ImGui::EndChild();
  begin_side_panel("block report", layout, true);
  const auto& blocks = app.session->blocks();
  if (app.blocks.rockmass.open) {
    draw_rockmass_view(app);  // ui/blocks/rockmass_view.h
  } else if (app.blocks.selected_block && *app.blocks.selected_block < blocks.size()) {
    const BlockView& b = blocks[*app.blocks.selected_block];
    for (const auto& line : b.summary) paragraph(line);
    draw_motion_controls(app, b);
  } else {
    paragraph("Tap a block on the model or in the table to see its report.");
  }
  ImGui::EndChild();
}

}  // namespace rockface::ui

#include "ui/view3d/overlay_legend.h"

#include <algorithm>
#include <set>

#include "ui/app/app_state.h"
#include "ui/view3d/overlay_north_arrow.h"
#include "ui/view3d/overlay_scale_bar.h"
#include "ui/view3d/overlay_text.h"
#include "ui/view3d/overlay_traces.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

constexpr ImU32 kOpenColour = IM_COL32(255, 255, 255, 255);

void add_verdicts(const std::set<analysis::BlockVerdict>& verdicts, std::vector<LegendEntry>& out) {
  for (const analysis::BlockVerdict v : verdicts) {
    if (v == analysis::BlockVerdict::infinite)
      out.push_back({verdict_colour(v), "not finite: no block", LegendEntry::Swatch::line});
    else
      out.push_back({verdict_colour(v), std::string("block: ") + analysis::verdict_name(v),
                     LegendEntry::Swatch::area});
  }
  if (!verdicts.empty())
    out.push_back(
        {kOpenColour, "dashed: open / unknown beyond the 3D image", LegendEntry::Swatch::dashed});
}

}  // namespace

std::vector<LegendEntry> model_legend(const AppState&) {
  return {{kTargetColour, "range-pole target", LegendEntry::Swatch::ring}};
}

std::vector<LegendEntry> mapping_legend(const AppState& app) {
  std::vector<LegendEntry> out;
  if (!app.session) return out;
  std::set<std::string> joints;
  bool unassigned = false;
  for (const auto& m : app.session->measurements())
    if (m.kind == storage::Measurement::Kind::trace) {
      if (joint_colour(m.joint_label, app.session->joints()) == kTraceColour)
        unassigned = true;
      else
        joints.insert(m.joint_label);
    }
  for (const auto& j : app.session->joints())
    if (joints.count(j.label))
      out.push_back({joint_colour(j.label, app.session->joints()), "trace of " + j.label,
                     LegendEntry::Swatch::line});
  if (unassigned) out.push_back({kTraceColour, "trace, no joint", LegendEntry::Swatch::line});
  if (!app.mapping.marker.points().empty())
    out.push_back({kPendingTraceColour, "trace being marked", LegendEntry::Swatch::line});
  std::set<analysis::BlockVerdict> verdicts;
  if (const auto& v = app.mapping.blocks.verdicts)
    for (const auto& b : v->blocks)
      if (b.verdict != analysis::BlockVerdict::infinite) verdicts.insert(b.verdict);
  add_verdicts(verdicts, out);
  return out;
}

std::vector<LegendEntry> blocks_legend(const AppState& app) {
  std::vector<LegendEntry> out;
  if (!app.session) return out;
  std::set<analysis::BlockVerdict> verdicts;
  for (const auto& b : app.session->blocks()) verdicts.insert(b.verdict);
  add_verdicts(verdicts, out);
  return out;
}

void draw_legend(AppState& app, const std::vector<LegendEntry>& entries,
                 std::optional<std::pair<ImVec2, ImVec2>> keep_clear) {
  if (entries.empty()) return;
  const float s = app.targets.scale();
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float swatch = 28 * s, pad = 8 * s;
  float width = 0;
  for (const auto& e : entries) width = std::max(width, ImGui::CalcTextSize(e.words.c_str()).x);
  ImVec2 hi(app.model_view.panel_max().x - 10 * s, app.model_view.panel_max().y - 10 * s);
  const float w = width + swatch + 3 * pad, h = line * entries.size() + 2 * pad;
  // Over the scale bar's words the legend would hide them: above it then.
  if (keep_clear && hi.x - w < keep_clear->second.x && hi.y - h < keep_clear->second.y)
    hi.y = std::min(hi.y, keep_clear->first.y - 6 * s);
  const ImVec2 lo(hi.x - w, hi.y - h);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(lo, hi, IM_COL32(0, 0, 0, 170), 4 * s);
  app.model_view.add_flat_mark("legend", lo, hi);
  float y = lo.y + pad;
  for (const auto& e : entries) {
    const float mid = y + line / 2;
    const ImVec2 a(lo.x + pad, mid), b(lo.x + pad + swatch, mid);
    switch (e.swatch) {
      case LegendEntry::Swatch::line:
        draw->AddLine(a, b, e.colour, 4 * s);
        break;
      case LegendEntry::Swatch::dashed:
        for (float x = a.x; x < b.x; x += 10 * s)
          draw->AddLine(ImVec2(x, mid), ImVec2(std::min(x + 6 * s, b.x), mid), e.colour, 3 * s);
        break;
      case LegendEntry::Swatch::area:
        draw->AddRectFilled(ImVec2(a.x, mid - 7 * s), ImVec2(b.x, mid + 7 * s),
                            (e.colour & 0x00FFFFFFu) | (110u << 24));
        draw->AddRect(ImVec2(a.x, mid - 7 * s), ImVec2(b.x, mid + 7 * s), e.colour, 0, 0, 2 * s);
        break;
      case LegendEntry::Swatch::ring:
        draw->AddCircle(ImVec2((a.x + b.x) / 2, mid), 7 * s, e.colour, 20, 3 * s);
        break;
    }
    draw_text(draw, ImVec2(b.x + pad, y), IM_COL32(255, 255, 255, 255), e.words,
              app.model_view.text_area());
    y += line;
  }
}

void draw_model_overlays(AppState& app, ModelScreen screen) {
  if (!app.model_view.has_model()) return;
  const float s = app.targets.scale();
  if (screen == ModelScreen::blocks) {  // a smaller panel: the legend only
    draw_legend(app, blocks_legend(app));
    return;
  }
  // The scale bar first: the legend keeps clear of it.
  const DrawnRect bar = draw_scale_bar(app.model_view, s);
  app.model_view.add_flat_mark("scale bar", bar.min, bar.max);
  const auto clear =
      bar.min.x <= bar.max.x ? std::optional(std::pair(bar.min, bar.max)) : std::nullopt;
  draw_legend(app, screen == ModelScreen::model ? model_legend(app) : mapping_legend(app), clear);
  const DrawnRect arrow = draw_north_arrow(app.model_view, s);
  app.model_view.add_flat_mark("north arrow", arrow.min, arrow.max);
}

}  // namespace rockface::ui

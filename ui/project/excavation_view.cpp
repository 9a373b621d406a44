#include "ui/project/excavation_view.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <imgui.h>

#include "core/common/number_format.h"
#include "ui/view3d/overlay_text.h"
#include "ui/widgets/format.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

constexpr ImU32 kViewInk = IM_COL32(30, 30, 30, 255);
constexpr ImU32 kViewWhite = IM_COL32(255, 255, 255, 255);
constexpr ImU32 kViewOver = IM_COL32(255, 0, 0, 255);   // the picture's full overbreak red
constexpr ImU32 kViewUnder = IM_COL32(0, 0, 255, 255);  // and full underbreak blue
constexpr ImU32 kViewNotSeen = IM_COL32(205, 205, 205, 255);
constexpr ImU32 kViewHatch = IM_COL32(150, 150, 150, 255);
constexpr ImU32 kViewNotRock = IM_COL32(95, 95, 95, 255);

std::string volume_with_sigma(double v, const std::optional<double>& sigma) {
  return format::text(format::Volume{v}) +
         (sigma ? " ± " + format::text(format::Volume{*sigma}) : std::string());
}

// A swatch of the legend, a line high, with its words after it.
void legend_swatch(ImDrawList* dl, ImVec2 at, float size, int kind) {
  const ImVec2 to(at.x + size, at.y + size);
  switch (kind) {
    case 0:  // not seen or left out: hatched grey
      dl->AddRectFilled(at, to, kViewNotSeen);
      for (float k = 0; k < 2 * size; k += size / 3)
        dl->AddLine(ImVec2(at.x + std::max(0.0f, k - size), at.y + std::min(k, size)),
                    ImVec2(at.x + std::min(k, size), at.y + std::max(0.0f, k - size)), kViewHatch);
      break;
    case 1:  // the range pole, not rock
      dl->AddRectFilled(at, to, kViewNotRock);
      break;
    case 2:  // underbreak beyond the tolerance: outlined in black
      dl->AddRectFilled(at, to, IM_COL32(120, 120, 255, 255));
      dl->AddRect(at, to, IM_COL32(0, 0, 0, 255), 0, 0, 2);
      break;
    default: {  // the deepest underbreak: a black cross
      const float m = 0.2f * size;
      dl->AddLine(ImVec2(at.x + m, at.y + m), ImVec2(to.x - m, to.y - m), IM_COL32_BLACK, 2);
      dl->AddLine(ImVec2(at.x + m, to.y - m), ImVec2(to.x - m, at.y + m), IM_COL32_BLACK, 2);
    }
  }
  dl->AddRect(at, to, kViewInk);
}

}  // namespace

std::vector<std::string> excavation_figures(const ExcavationView& v) {
  std::vector<std::string> out;
  out.push_back("Overbreak " + volume_with_sigma(v.overbreak_m3, v.overbreak_sigma_m3) +
                ", underbreak " + volume_with_sigma(v.underbreak_m3, v.underbreak_sigma_m3) +
                " over the round; " + format::text(format::Fraction{v.seen_fraction}) +
                " of the outline seen.");
  if (v.largest_overbreak_m)
    out.push_back("Largest overbreak " + format::text(format::Length{*v.largest_overbreak_m}) +
                  " at chainage " + format_fixed(*v.largest_overbreak_chainage, 2) + " m, " +
                  format::text(format::Length{*v.largest_overbreak_s_m}) +
                  " along the design line.");
  if (v.deepest_underbreak_m)
    out.push_back("Deepest underbreak " + format::text(format::Length{*v.deepest_underbreak_m}) +
                  " at chainage " + format_fixed(*v.deepest_underbreak_chainage, 2) + " m, " +
                  format::text(format::Length{*v.deepest_underbreak_s_m}) +
                  " along the design line.");
  out.push_back(format::count(v.patches_beyond_tolerance, "patch", "patches") +
                " of underbreak beyond the tolerance of " +
                format::text(format::Length{v.tolerance_m}) + ".");
  return out;
}

ExcavationDrawn draw_excavation_view(const ExcavationView& v, const PictureTexture& cells,
                                     float width) {
  ExcavationDrawn drawn;
  heading("Excavation of this round");
  for (const auto& line : v.lines) paragraph(line);
  if (!v.compared) {
    paragraph("Nothing to show: " + v.message);
    return drawn;
  }
  drawn.figures = excavation_figures(v);
  for (const auto& line : drawn.figures) paragraph(line);
  if (cells.empty() || v.cells.empty()) return drawn;

  const float line = ImGui::GetTextLineHeightWithSpacing();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  // Chainage up the left side: as wide as its widest label.
  const std::string top = format_fixed(v.chainage_top, 2),
                    bottom = format_fixed(v.chainage_bottom, 2);
  const float axis_w =
      std::max(ImGui::CalcTextSize(top.c_str()).x, ImGui::CalcTextSize(bottom.c_str()).x) +
      0.5f * line;
  const char* chainage_title = "chainage (m), the face at the top";
  label(chainage_title);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::SetCursorScreenPos(ImVec2(origin.x + axis_w, origin.y));
  const float image_w =
      std::min(width - axis_w, static_cast<float>(v.cells.cols) * 1.5f);  // never blown up blurred
  cells.draw(image_w);
  drawn.view = true;
  // Where the cells lie in the texture drawn (its margin scaled).
  const float k = image_w / static_cast<float>(v.cells.cols);
  const float m = static_cast<float>(v.cells_margin_px) * k;
  const float x0 = origin.x + axis_w + m;
  const float cells_w = (static_cast<float>(v.cells.cols - 1) - 2 * v.cells_margin_px) * k;
  const float y_top = origin.y + m;
  const float y_bottom = origin.y + (static_cast<float>(v.cells.rows - 1) - v.cells_margin_px) * k;
  // The view's words lie beside and under its cells; the scale's under the
  // bar (recorded for the screen walk).
  const TextArea view_area{origin,
                           ImVec2(origin.x + width, ImGui::GetCursorScreenPos().y + 2.5f * line),
                           "developed view"};
  draw_text(dl, ImVec2(origin.x, y_top), kViewInk, top.c_str(), view_area);
  draw_text(dl, ImVec2(origin.x, y_bottom - line), kViewInk, bottom.c_str(), view_area);
  // The places along the outline under the view, each centred on its tick,
  // kept inside the view and clear of the one before.
  const float ty = ImGui::GetCursorScreenPos().y;
  float free_from = x0 - axis_w;
  for (const auto& p : v.places) {
    const float x = x0 + static_cast<float>(p.s_m / v.perimeter_m) * cells_w;
    dl->AddLine(ImVec2(x, y_bottom), ImVec2(x, ty + 0.3f * line), kViewInk, 2);
    const float tw = ImGui::CalcTextSize(p.name.c_str()).x;
    const float tx = std::clamp(x - tw / 2, free_from, x0 + cells_w - tw);
    draw_text(dl, ImVec2(tx, ty + 0.3f * line), kViewInk, p.name.c_str(), view_area);
    free_from = tx + tw + 0.5f * line;
  }
  const std::string along =
      "along the design line, " + format::text(format::Length{v.perimeter_m}) + " around";
  draw_text(dl, ImVec2(x0 + cells_w - ImGui::CalcTextSize(along.c_str()).x, ty + 1.3f * line),
            kViewInk, along.c_str(), view_area);
  ImGui::Dummy(ImVec2(width, 2.5f * line));

  // The legend: the colour scale in cm, then the swatches.
  const ImVec2 bar = ImGui::GetCursorScreenPos();
  const float bar_w = std::min(cells_w, 18 * line), bar_h = 0.6f * line;
  const ImVec2 mid(bar.x + bar_w / 2, bar.y + bar_h);
  dl->AddRectFilledMultiColor(bar, mid, kViewUnder, kViewWhite, kViewWhite, kViewUnder);
  dl->AddRectFilledMultiColor(ImVec2(mid.x, bar.y), ImVec2(bar.x + bar_w, bar.y + bar_h),
                              kViewWhite, kViewOver, kViewOver, kViewWhite);
  dl->AddRect(bar, ImVec2(bar.x + bar_w, bar.y + bar_h), kViewInk);
  const float tol_x = bar.x + static_cast<float>(0.5 - v.tolerance_m / v.scale_m / 2) * bar_w;
  dl->AddLine(ImVec2(tol_x, bar.y - 0.2f * line), ImVec2(tol_x, bar.y + bar_h + 0.2f * line),
              IM_COL32_BLACK, 2);
  const std::string cm = format_fixed(v.scale_m * 100, 0);
  const std::string under = "-" + cm + " cm under", over = "+" + cm + " cm over";
  const float ly = bar.y + bar_h + 0.2f * line;
  const TextArea scale_area{bar, ImVec2(bar.x + std::max(bar_w, width), ly + 1.2f * line),
                            "colour scale"};
  draw_text(dl, ImVec2(bar.x, ly), kViewInk, under.c_str(), scale_area);
  draw_text(dl, ImVec2(mid.x - ImGui::CalcTextSize("0").x / 2, ly), kViewInk, "0", scale_area);
  draw_text(dl, ImVec2(bar.x + bar_w - ImGui::CalcTextSize(over.c_str()).x, ly), kViewInk,
            over.c_str(), scale_area);
  ImGui::Dummy(ImVec2(bar_w, bar_h + 1.3f * line));
  ++drawn.legend_entries;
  const std::string entries[] = {"not seen, or left out", "the range pole (not rock)",
                                 "underbreak beyond the tolerance of " +
                                     format::text(format::Length{v.tolerance_m}) +
                                     " (black tick on the scale)",
                                 "the deepest underbreak"};
  for (int kind = 0; kind < 4; ++kind) {
    if (kind == 3 && !v.deepest_underbreak_m) continue;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    legend_swatch(dl, ImVec2(at.x, at.y + 0.1f * line), 0.8f * line, kind);
    ImGui::SetCursorScreenPos(ImVec2(at.x + 1.2f * line, at.y));
    label(entries[kind]);
    ++drawn.legend_entries;
  }
  return drawn;
}

}  // namespace rockface::ui

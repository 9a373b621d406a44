#include "ui/project/drive_chart.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include <imgui.h>

#include "core/common/number_format.h"
#include "ui/view3d/overlay_text.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

// The sets' colours (as the drive picture's palette, RGB here).
ImU32 set_colour(int id) {
  static const ImU32 palette[] = {IM_COL32(214, 40, 40, 255),   IM_COL32(31, 119, 180, 255),
                                  IM_COL32(44, 160, 44, 255),   IM_COL32(255, 127, 14, 255),
                                  IM_COL32(148, 103, 189, 255), IM_COL32(140, 86, 75, 255),
                                  IM_COL32(227, 119, 194, 255), IM_COL32(188, 189, 34, 255)};
  return palette[static_cast<std::size_t>(std::max(1, id) - 1) % std::size(palette)];
}

constexpr ImU32 kChartInk = IM_COL32(30, 30, 30, 255);
constexpr ImU32 kChartGrid = IM_COL32(215, 215, 215, 255);
constexpr ImU32 kChartPaper = IM_COL32(255, 255, 255, 255);
constexpr ImU32 kChartJoint = IM_COL32(20, 20, 20, 255);

// A tick step for chainage whose labels, `label_px` wide, do not touch.
double tick_step(double span_m, float width_px, float label_px) {
  for (double step : {0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0})
    if (step / span_m * width_px >= 1.5f * label_px) return step;
  return 2000;
}

}  // namespace

DriveChartDrawn draw_drive_chart(const DriveJoints& drive, float width) {
  DriveChartDrawn drawn;
  heading("Joints along the drive");
  if (drive.visits == 0) {
    paragraph("No visit is placed in the tunnel.");
    return drawn;
  }
  // The chainage range of the visits, padded so a mark at an end is whole.
  double c0 = 0, c1 = 0;
  bool first = true;
  for (const auto& j : drive.joints) {
    c0 = first ? j.chainage : std::min(c0, j.chainage);
    c1 = first ? j.chainage : std::max(c1, j.chainage);
    first = false;
  }
  for (const auto& t : drive.sets)
    for (const auto& p : t.points) {
      c0 = first ? p.chainage : std::min(c0, p.chainage);
      c1 = first ? p.chainage : std::max(c1, p.chainage);
      first = false;
    }
  if (first) {
    paragraph("No measured joint in the placed visits.");
    return drawn;
  }
  if (c1 - c0 < 2) {
    c0 -= 1;
    c1 += 1;
  }
  const double pad = 0.05 * (c1 - c0);
  c0 -= pad;
  c1 += pad;

  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float axis_w = ImGui::CalcTextSize("360°").x + 0.6f * line;
  // The legend beside the panels: as wide as its widest entry.
  std::vector<std::pair<std::string, ImU32>> legend{{"measured joint", kChartJoint}};
  for (const auto& t : drive.sets) {
    const auto& m = t.points.back();
    legend.push_back({"set " + std::to_string(t.id) + " " + format_fixed(m.dip_deg, 0) + "°/" +
                          format_fixed(m.dipdir_deg, 0) + "°" +
                          (t.flags.empty() ? "" : " (" + t.flags + ")"),
                      set_colour(t.id)});
  }
  float legend_w = 0;
  for (const auto& [text, colour] : legend)
    legend_w = std::max(legend_w, ImGui::CalcTextSize(text.c_str()).x);
  legend_w += 2 * line;
  const float plot_w = std::max(4 * line, width - axis_w - legend_w);
  const float panel_h = std::max(5 * line, 0.32f * plot_w);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float label_h = line;  // each panel's name above it
  const float total_h = 2 * (label_h + panel_h) + 2.5f * line;
  ImGui::Dummy(ImVec2(width, total_h));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + total_h), kChartPaper);
  // Every word of the chart lies on it (recorded for the screen walk).
  const TextArea area{origin, ImVec2(origin.x + width, origin.y + total_h), "chart of the drive"};

  const float x0 = origin.x + axis_w;
  auto x_of = [&](double c) { return x0 + static_cast<float>((c - c0) / (c1 - c0)) * plot_w; };
  struct Panel {
    float top;
    double hi;
    const char* name;
  };
  const Panel panels[2] = {{origin.y + label_h, 360, "dip direction"},
                           {origin.y + 2 * label_h + panel_h + 0.5f * line, 90, "dip"}};
  auto y_of = [&](const Panel& p, double v) {
    return p.top + panel_h - static_cast<float>(v / p.hi) * panel_h;
  };
  for (const auto& p : panels) {
    draw_text(dl, ImVec2(x0, p.top - label_h), kChartInk, p.name, area);
    const double step = p.hi == 360 ? 90 : 30;
    for (double v = 0; v <= p.hi + 1e-9; v += step) {
      const float y = y_of(p, v);
      dl->AddLine(ImVec2(x0, y), ImVec2(x0 + plot_w, y), kChartGrid);
      const std::string t = format_fixed(v, 0) + "°";
      const ImVec2 size = ImGui::CalcTextSize(t.c_str());
      draw_text(dl, ImVec2(x0 - size.x - 0.25f * line, y - size.y / 2), kChartInk, t.c_str(), area);
    }
    dl->AddRect(ImVec2(x0, p.top), ImVec2(x0 + plot_w, p.top + panel_h), kChartInk);
  }
  // Chainage along the bottom.
  const int decimals = c1 - c0 < 4 ? 1 : 0;
  const float label_px = ImGui::CalcTextSize(format_fixed(c1, decimals).c_str()).x;
  const double step = tick_step(c1 - c0, plot_w, label_px);
  const float bottom = panels[1].top + panel_h;
  for (double c = std::ceil(c0 / step) * step; c <= c1 + 1e-9; c += step) {
    const float x = x_of(c);
    for (const auto& p : panels)
      dl->AddLine(ImVec2(x, p.top + panel_h), ImVec2(x, p.top + panel_h + 0.25f * line), kChartInk);
    const std::string t = format_fixed(c, step < 1 ? 1 : decimals);
    draw_text(dl, ImVec2(x - ImGui::CalcTextSize(t.c_str()).x / 2, bottom + 0.3f * line), kChartInk,
              t.c_str(), area);
  }
  const char* axis = "chainage (m)";
  draw_text(dl, ImVec2(x0 + plot_w - ImGui::CalcTextSize(axis).x, bottom + 1.3f * line), kChartInk,
            axis, area);

  // The sets' tracks, then the joints over them.
  const float r = std::max(3.0f, 0.22f * line);
  for (const auto& t : drive.sets) {
    const ImU32 colour = set_colour(t.id);
    for (std::size_t k = 0; k < t.points.size(); ++k) {
      const DriveSetPoint& p = t.points[k];
      const ImVec2 dd(x_of(p.chainage), y_of(panels[0], p.dipdir_deg));
      const ImVec2 dip(x_of(p.chainage), y_of(panels[1], p.dip_deg));
      if (k > 0) {
        const DriveSetPoint& q = t.points[k - 1];
        // Dip direction wraps at 0 / 360: no line across the panel.
        if (std::abs(p.dipdir_deg - q.dipdir_deg) < 180)
          dl->AddLine(ImVec2(x_of(q.chainage), y_of(panels[0], q.dipdir_deg)), dd, colour, 2);
        dl->AddLine(ImVec2(x_of(q.chainage), y_of(panels[1], q.dip_deg)), dip, colour, 2);
      }
      for (const ImVec2& at : {dd, dip}) {
        dl->AddCircleFilled(at, 1.4f * r, colour);
        if (p.turned) dl->AddCircle(at, 2.4f * r, kChartInk, 0, 2);
      }
      ++drawn.set_marks;
    }
  }
  const bool labelled = drive.joints.size() <= 12;
  for (const auto& j : drive.joints) {
    const ImVec2 dd(x_of(j.chainage), y_of(panels[0], j.dipdir_deg));
    const ImVec2 dip(x_of(j.chainage), y_of(panels[1], j.dip_deg));
    for (const ImVec2& at : {dd, dip}) {
      dl->AddCircle(at, r, kChartJoint, 0, 2);
      if (labelled)
        draw_text(dl, ImVec2(at.x + 1.5f * r, at.y - line / 2), kChartInk, j.label.c_str(), area);
    }
    ++drawn.joint_marks;
  }
  // The legend.
  float ly = panels[0].top;
  const float lx = x0 + plot_w + line;
  for (const auto& [text, colour] : legend) {
    const ImVec2 at(lx + 0.4f * line, ly + line / 2);
    if (colour == kChartJoint)
      dl->AddCircle(at, r, kChartJoint, 0, 2);
    else
      dl->AddCircleFilled(at, 1.4f * r, colour);
    draw_text(dl, ImVec2(lx + line, ly), kChartInk, text.c_str(), area);
    ly += line;
  }
  if (!drive.sets.empty()) draw_text(dl, ImVec2(lx, ly), kChartInk, "ringed: turned", area);
  return drawn;
}

}  // namespace rockface::ui

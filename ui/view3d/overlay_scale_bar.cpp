#include "ui/view3d/overlay_scale_bar.h"

#include <algorithm>
#include <cmath>

#include "core/common/number_format.h"
#include "storage/project/model_registration.h"
#include "ui/view3d/overlay_text.h"

namespace rockface::ui {

void DrawnRect::add(ImVec2 a, ImVec2 b) {
  min = ImVec2(std::min({min.x, a.x, b.x}), std::min({min.y, a.y, b.y}));
  max = ImVec2(std::max({max.x, a.x, b.x}), std::max({max.y, a.y, b.y}));
}

void DrawnRect::add_text(ImVec2 at, const char* text) {
  const ImVec2 size = ImGui::CalcTextSize(text);
  // The halo reaches a pixel further.
  add(ImVec2(at.x - 1, at.y - 1), ImVec2(at.x + size.x + 1, at.y + size.y + 1));
}

bool model_is_scaled(const storage::Model& model) {
  return storage::read_model_registration(model.registration).is_scaled();
}

DrawnRect draw_scale_bar(const ModelView& view, float scale) {
  DrawnRect drawn;
  if (!view.has_model()) return drawn;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 lo = view.panel_min(), hi = view.panel_max();
  const float pad = 14 * scale;
  const ImVec2 at(lo.x + pad, hi.y - pad - ImGui::GetTextLineHeight() - 10 * scale);
  if (!model_is_scaled(*view.model())) {
    const char* words = "not to scale (no range pole or control points)";
    draw_text(draw, at, IM_COL32(255, 255, 255, 255), words, view.text_area(), TextHalo::dark);
    drawn.add_text(at, words);
    return drawn;
  }
  // The surface in the middle of the view, else the model's centre.
  const ImVec2 mid((lo.x + hi.x) / 2, (lo.y + hi.y) / 2);
  const ScreenRay ray = view.ray_at(mid);
  Eigen::Vector3d p = view.display_mesh().centre;
  if (view.picker())
    if (const auto hit = view.picker()->pick(measure::Ray{ray.origin, ray.direction}))
      p = hit->point;
  // Metres per pixel there: 100 px to the right, on the plane across the view.
  const ScreenRay side = view.ray_at(ImVec2(mid.x + 100, mid.y));
  const double depth = (p - ray.origin).dot(ray.direction);
  const double t = depth / side.direction.dot(ray.direction);
  const double metres_per_px =
      ((side.origin + t * side.direction) - (ray.origin + depth * ray.direction)).norm() / 100;
  if (!(metres_per_px > 0) || !std::isfinite(metres_per_px)) return drawn;
  // The largest round length within a quarter of the panel's width.
  const double most = 0.25 * (hi.x - lo.x) * metres_per_px;
  double length = std::pow(10.0, std::floor(std::log10(most)));
  for (const double f : {5.0, 2.0})
    if (length * f <= most) {
      length *= f;
      break;
    }
  const float px = static_cast<float>(length / metres_per_px);
  const float y = hi.y - pad;
  const float h = 8 * scale;
  draw->AddRectFilled(ImVec2(at.x - 1, y - h - 1), ImVec2(at.x + px + 1, y + 1),
                      IM_COL32(0, 0, 0, 255));
  draw->AddRectFilled(ImVec2(at.x, y - h), ImVec2(at.x + px / 2, y), IM_COL32(255, 255, 255, 255));
  const std::string label = (length >= 1 ? format_significant(length, 6, " m")
                                         : format_significant(length * 1000, 6, " mm")) +
                            " (at the middle of the view)";
  const char* text = label.c_str();
  const ImVec2 text_at(at.x, y - h - ImGui::GetTextLineHeight() - 2 * scale);
  draw_text(draw, text_at, IM_COL32(255, 255, 255, 255), text, view.text_area(), TextHalo::dark);
  drawn.add_text(text_at, text);
  drawn.add(ImVec2(at.x - 1, y - h - 1), ImVec2(at.x + px + 1, y + 1));
  return drawn;
}

}  // namespace rockface::ui

#include "ui/view3d/overlay_north_arrow.h"

#include <cmath>

#include "core/common/number_format.h"
#include "core/common/units.h"
#include "storage/project/model_registration.h"
#include "ui/view3d/overlay_text.h"

namespace rockface::ui {

bool model_is_oriented(const storage::Model& model) {
  return storage::read_model_registration(model.registration).oriented();
}

std::optional<double> view_azimuth_deg(const ModelView& view) {
  const ImVec2 mid((view.panel_min().x + view.panel_max().x) / 2,
                   (view.panel_min().y + view.panel_max().y) / 2);
  const Eigen::Vector3d d = view.ray_at(mid).direction;
  if (std::hypot(d.x(), d.y()) < 1e-6) return std::nullopt;
  double a = rad_to_deg(std::atan2(d.x(), d.y()));
  if (a < 0) a += 360;
  return a >= 360 ? 0 : a;
}

DrawnRect draw_north_arrow(const ModelView& view, float scale) {
  DrawnRect drawn;
  if (!view.has_model()) return drawn;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float pad = 14 * scale, r = 26 * scale;
  const ImVec2 centre(view.panel_min().x + pad + r, view.panel_min().y + pad + r);
  if (!model_is_oriented(*view.model())) {
    const ImVec2 at(view.panel_min().x + pad, view.panel_min().y + pad);
    draw_text(draw, at, IM_COL32(255, 255, 255, 255), "not oriented: no north", view.text_area(),
              TextHalo::dark);
    drawn.add_text(at, "not oriented: no north");
    return drawn;
  }
  // North and east as the view shows them at the model's centre: the
  // screen images of short steps along +y and +x.
  const Eigen::Vector3d c = view.display_mesh().centre;
  const double step = 0.1 * std::max(view.display_mesh().radius, 1e-3);
  const auto o = view.to_screen(c), n = view.to_screen(c + Eigen::Vector3d(0, step, 0)),
             e = view.to_screen(c + Eigen::Vector3d(step, 0, 0));
  if (!o || !n || !e) return drawn;
  const Eigen::Vector2f north(n->x - o->x, n->y - o->y), east(e->x - o->x, e->y - o->y);
  const float longest = std::max({north.norm(), east.norm(), 1e-6f});
  draw->AddCircleFilled(centre, r + 4 * scale, IM_COL32(0, 0, 0, 150), 32);
  drawn.add(ImVec2(centre.x - r - 6 * scale, centre.y - r - 6 * scale),
            ImVec2(centre.x + r + 6 * scale, centre.y + r + 6 * scale));
  draw->AddCircle(centre, r + 4 * scale, IM_COL32(255, 255, 255, 255), 32, 1.5f * scale);
  const Eigen::Vector2f tip = north / longest * r, side = east / longest * r * 0.5f;
  const ImVec2 head(centre.x + tip.x(), centre.y + tip.y());
  // A long north half in red, a short south half in white: a compass needle.
  draw->AddLine(centre, head, IM_COL32(230, 30, 30, 255), 5 * scale);
  draw->AddLine(centre, ImVec2(centre.x - tip.x() * 0.6f, centre.y - tip.y() * 0.6f),
                IM_COL32(255, 255, 255, 255), 5 * scale);
  draw->AddLine(centre, ImVec2(centre.x + side.x(), centre.y + side.y()),
                IM_COL32(255, 255, 255, 160), 2 * scale);
  draw_text(draw, ImVec2(head.x - 4 * scale, head.y - 8 * scale), IM_COL32(255, 255, 255, 255), "N",
            view.text_area(), TextHalo::dark);
  const std::optional<double> looking_to = view_azimuth_deg(view);
  const std::string looking =
      looking_to
          ? "looking " + format_zero_padded(std::fmod(std::round(*looking_to), 360.0), 3, 0, "°")
          : "looking straight down";
  const char* text = looking.c_str();
  draw_text(draw, ImVec2(view.panel_min().x + pad, centre.y + r + 8 * scale),
            IM_COL32(255, 255, 255, 255), text, view.text_area(), TextHalo::dark);
  drawn.add_text(ImVec2(view.panel_min().x + pad, centre.y + r + 8 * scale), text);
  // Seen end-on the needle is short: say where north is.
  if (north.norm() < 0.3f * longest) {
    const auto azimuth = view_azimuth_deg(view);
    const bool into = azimuth && (*azimuth < 90 || *azimuth > 270);
    const ImVec2 at(view.panel_min().x + pad,
                    centre.y + r + 8 * scale + ImGui::GetTextLineHeightWithSpacing());
    const char* words = into ? "north: into the view" : "north: out of the view";
    draw_text(draw, at, IM_COL32(255, 255, 255, 255), words, view.text_area(), TextHalo::dark);
    drawn.add_text(at, words);
  }
  return drawn;
}

}  // namespace rockface::ui

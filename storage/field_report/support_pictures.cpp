#include "storage/field_report/support_pictures.h"

#include <cairo.h>

#include <cmath>
#include <memory>
#include <string>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include "core/common/number_format.h"

namespace rockface::storage {

namespace {

// The chart's axes (log10): Q 0.001-1000, De 1-100.
constexpr double kQLo = -3, kQHi = 3, kDeLo = 0, kDeHi = 2;

struct Frame {
  double x0, y0, w, h;  // the plot area, pixels
  double x(double q) const { return x0 + (std::log10(q) - kQLo) / (kQHi - kQLo) * w; }
  double y(double de) const { return y0 + h - (std::log10(de) - kDeLo) / (kDeHi - kDeLo) * h; }
};

void text(cairo_t* cr, double x, double y, const std::string& s, double size, bool centre = false) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_move_to(cr, centre ? x - e.width / 2 : x, y);
  cairo_show_text(cr, s.c_str());
}

}  // namespace

cv::Mat q_chart_picture(const std::optional<rockmass::QChartPoint>& point, int width_px) {
  const int W = width_px, H = width_px * 2 / 3;
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, W, H), cairo_surface_destroy);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> owner(cairo_create(surface.get()),
                                                           cairo_destroy);
  cairo_t* cr = owner.get();
  const double u = W / 800.0;  // the drawing's unit: sizes follow the width
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  const Frame f{70 * u, 20 * u, W - 100 * u, H - 80 * u};

  // Grid: decades.
  cairo_set_line_width(cr, 0.5 * u);
  cairo_set_source_rgb(cr, 0.8, 0.8, 0.8);
  for (int k = -3; k <= 3; ++k) {
    cairo_move_to(cr, f.x(std::pow(10.0, k)), f.y0);
    cairo_line_to(cr, f.x(std::pow(10.0, k)), f.y0 + f.h);
  }
  for (const double de : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0}) {
    cairo_move_to(cr, f.x0, f.y(de));
    cairo_line_to(cr, f.x0 + f.w, f.y(de));
  }
  cairo_stroke(cr);

  // The boundaries, clipped to the plot.
  cairo_save(cr);
  cairo_rectangle(cr, f.x0, f.y0, f.w, f.h);
  cairo_clip(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 1.2 * u);
  for (int k = 1; k <= 8; ++k) {
    const double q0 = 1e-3, q1 = 1e3;
    cairo_move_to(cr, f.x(q0), f.y(rockmass::q_chart_boundary_de(k, q0)));
    cairo_line_to(cr, f.x(q1), f.y(rockmass::q_chart_boundary_de(k, q1)));
  }
  cairo_stroke(cr);
  // Each category's number in its region along De = 10 (between its lines).
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.6);
  for (int c = 1; c <= 9; ++c) {
    const double de = 4;
    const double hi_q =
        c == 1 ? 1e3 : std::pow(de / rockmass::q_chart_boundary_de(c - 1, 1.0), 2.5);
    const double lo_q = c == 9 ? 1e-3 : std::pow(de / rockmass::q_chart_boundary_de(c, 1.0), 2.5);
    const double q = std::sqrt(std::max(hi_q, 1e-3) * std::min(std::max(lo_q, 1e-3), 1e3));
    if (q > 1e-3 && q < 1e3) text(cr, f.x(q), f.y(de), std::to_string(c), 14 * u, true);
  }
  // The visit's point.
  if (point) {
    const rockmass::QSupport s = rockmass::q_support(*point);
    const double px = f.x(std::clamp(point->q, 1e-3, 1e3));
    const double py = f.y(std::clamp(s.equivalent_dimension, 1.0, 100.0));
    cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
    cairo_arc(cr, px, py, 5 * u, 0, 2 * M_PI);
    cairo_fill(cr);
    if (s.marginal) {
      cairo_set_line_width(cr, 1.5 * u);
      cairo_arc(cr, px, py, 10 * u, 0, 2 * M_PI);
      cairo_stroke(cr);
    }
    text(cr, px + 12 * u, py - 8 * u,
         "Q " + format_significant(point->q, 3) + ", De " +
             format_significant(s.equivalent_dimension, 3) + ": " +
             std::to_string(s.category.number) + (s.marginal ? " (marginal)" : ""),
         12 * u);
  }
  cairo_restore(cr);

  // Frame and axes.
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1 * u);
  cairo_rectangle(cr, f.x0, f.y0, f.w, f.h);
  cairo_stroke(cr);
  for (int k = -3; k <= 3; ++k)
    text(cr, f.x(std::pow(10.0, k)), f.y0 + f.h + 16 * u, format_significant(std::pow(10.0, k), 3),
         11 * u, true);
  for (const double de : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0})
    text(cr, f.x0 - 30 * u, f.y(de) + 4 * u, format_significant(de, 3), 11 * u);
  text(cr, f.x0 + f.w / 2, f.y0 + f.h + 36 * u, "Q (rock mass quality)", 12 * u, true);
  cairo_save(cr);
  cairo_translate(cr, 18 * u, f.y0 + f.h / 2);
  cairo_rotate(cr, -M_PI / 2);
  text(cr, 0, 0, "De = span / ESR (m)", 12 * u, true);
  cairo_restore(cr);
  text(cr, f.x0, H - 8 * u,
       "Q-system support chart (Grimstad & Barton 1993, NGI 2015), boundaries simplified: "
       "categories 1 (unsupported) to 9 (special evaluation)",
       9 * u);

  cairo_surface_flush(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  const cv::Mat bgra(H, W, CV_8UC4, cairo_image_surface_get_data(surface.get()),
                     static_cast<std::size_t>(stride));
  cv::Mat bgr;
  cv::cvtColor(bgra, bgr, cv::COLOR_BGRA2BGR);
  return bgr;
}

}  // namespace rockface::storage

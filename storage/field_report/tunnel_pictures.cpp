#include "storage/field_report/tunnel_pictures.h"
#include "storage/field_report/field_report.h"
#include "storage/field_report/picture_style.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace rockface::storage {

namespace {

const cv::Scalar kNotSeen{205, 205, 205};
const cv::Scalar kNotRock{95, 95, 95};

int text_width(const std::string& s, double scale = 0.5) {
  int base = 0;
  return cv::getTextSize(s, kFont, scale, 1, &base).width;
}

// White on the design line, red toward +1 (overbreak), blue toward -1.
cv::Scalar deviation_colour(double t) {
  t = std::clamp(t, -1.0, 1.0);
  const double a = 255 * (1 - std::abs(t));
  return t >= 0 ? cv::Scalar(a, a, 255) : cv::Scalar(255, a, a);
}

}  // namespace

double developed_view_scale_m(const tunnel::ProfileDeviation& dev) {
  const auto& view = dev.view;
  // The scale: the deviation's extent rounded up to 5 cm, at least twice the
  // tolerance, so a tolerance-deep underbreak is a clear mid blue.
  // (The 98th percentile of the seen deviations, so one stray spike does not
  // wash the view out.)
  std::vector<float> seen;
  for (std::size_t k = 0; k < view.deviation_m.size(); ++k)
    if (view.state[k] == 0 && std::isfinite(view.deviation_m[k]))
      seen.push_back(std::abs(view.deviation_m[k]));
  double typical = 0;
  if (!seen.empty()) {
    const auto at = seen.begin() + static_cast<std::ptrdiff_t>(0.98 * (seen.size() - 1));
    std::nth_element(seen.begin(), at, seen.end());
    typical = *at;
  }
  double extent = std::max({0.1, 2 * dev.underbreak_tolerance_m, typical});
  extent = std::ceil(extent / 0.05 - 1e-9) * 0.05;

  return extent;
}

void draw_developed_view_cells(cv::Mat& img, cv::Point at, int w, int h,
                               const tunnel::ProfileDeviation& dev,
                               const tunnel::DesignProfile& profile, double extent) {
  const auto& view = dev.view;
  const int left = at.x, top = at.y;
  const std::size_t rows = view.chainage.size(), cols = view.s.size();
  const double perimeter = profile.perimeter();
  // Cells: column j spans s[j] +- half a spacing, row i chainage[i]; the
  // last row (the face) at the top.
  auto x_of = [&](double s) { return left + static_cast<int>(std::lround(s / perimeter * w)); };
  const double ds = perimeter / static_cast<double>(cols);
  cv::Mat beyond(h, w, CV_8U, cv::Scalar(0));
  for (std::size_t i = 0; i < rows; ++i) {
    const int y1 = top + h - static_cast<int>(std::lround(static_cast<double>(i) * h / rows));
    const int y0 = top + h - static_cast<int>(std::lround(static_cast<double>(i + 1) * h / rows));
    for (std::size_t j = 0; j < cols; ++j) {
      const int x0 = x_of(std::max(0.0, view.s[j] - ds / 2));
      const int x1 = std::max(x0 + 1, x_of(std::min(perimeter, view.s[j] + ds / 2)));
      const std::uint8_t state = view.state[i * cols + j];
      const float d = view.at(i, j);
      cv::Scalar colour = kNotSeen;
      if (state == 2)
        colour = kNotRock;
      else if ((state == 0 || state == 4) && std::isfinite(d))
        colour = deviation_colour(d / extent);
      cv::rectangle(img, {x0, y0}, {x1 - 1, y1 - 1}, colour, cv::FILLED);
      // Not seen, or left out (off any plausible lining, below the invert):
      // hatched, so it never reads as "on the line".
      if (state == 1 || state == 3)
        for (int y = y0; y < y1; ++y)
          for (int x = x0; x < x1; ++x)
            if ((x + y) % 8 == 0) img.at<cv::Vec3b>(y, x) = {150, 150, 150};
      // Interpolated across a hole of the 3D image: its colour, dotted.
      if (state == 4)
        for (int y = y0; y < y1; y += 4)
          for (int x = x0 + (y / 4) % 2 * 2; x < x1; x += 4)
            img.at<cv::Vec3b>(y, x) = {150, 150, 150};
      if (state == 0 && std::isfinite(d) && d < -dev.underbreak_tolerance_m)
        cv::rectangle(beyond, {x0 - left, y0 - top}, {x1 - 1 - left, y1 - 1 - top}, 255,
                      cv::FILLED);
    }
  }
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(beyond, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE, {left, top});
  cv::drawContours(img, contours, -1, cv::Scalar(0, 0, 0), 2, cv::LINE_8);
  cv::rectangle(img, {left, top}, {left + w, top + h}, kInk, 1);

  // The deepest underbreak.
  if (dev.has_underbreak) {
    const double c0 = view.chainage.front(), c1 = view.chainage.back();
    const double f = c1 == c0 ? 0.5 : (dev.max_underbreak.chainage - c0) / (c1 - c0);
    const cv::Point at(x_of(dev.max_underbreak.s), top + h - static_cast<int>(std::lround(f * h)));
    cv::drawMarker(img, at, cv::Scalar(0, 0, 0), cv::MARKER_TILTED_CROSS, 14, 2);
  }
}

cv::Mat developed_view_picture(const tunnel::ProfileDeviation& dev,
                               const tunnel::DesignProfile& profile, int width_px) {
  const auto& view = dev.view;
  const int left = 90, right = 30, top = 74, bottom = 140;
  const int w = std::max(200, width_px - left - right);
  const std::size_t rows = view.chainage.size(), cols = view.s.size();
  // Nothing compared (no wall or roof in view, the round off the
  // alignment): the message, never a view of zeros.
  const bool nothing_compared = dev.status == tunnel::DeviationStatus::no_walls_in_view ||
                                dev.status == tunnel::DeviationStatus::outside_alignment;
  if (rows == 0 || cols == 0 || nothing_compared) {
    // The title and the message in as many lines as the picture's width needs.
    const int margin = 20, title_px = 28, line_px = 22;
    const auto title =
        wrap_label("Excavation against the design: nothing to show", width_px - 2 * margin, 0.6);
    const auto lines = wrap_label(dev.message, width_px - 2 * margin, 0.45);
    const int text_top = 50 + title_px * static_cast<int>(title.size());
    cv::Mat img(std::max(160, text_top + line_px * static_cast<int>(lines.size())), width_px,
                CV_8UC3, kPaper);
    for (std::size_t i = 0; i < title.size(); ++i)
      draw_label(img, title[i], {margin, 50 + title_px * static_cast<int>(i)}, 0.6);
    for (std::size_t i = 0; i < lines.size(); ++i)
      draw_label(img, lines[i], {margin, text_top + line_px * static_cast<int>(i)}, 0.45);
    return img;
  }
  const double perimeter = profile.perimeter();
  const double length = std::abs(view.chainage.back() - view.chainage.front());
  const double px_per_m = w / perimeter;
  const int h =
      std::clamp(static_cast<int>(std::lround(std::max(length, 0.5) * px_per_m)), 160, 900);
  cv::Mat img(top + h + bottom, left + w + right, CV_8UC3, kPaper);

  const double extent = developed_view_scale_m(dev);
  draw_developed_view_cells(img, {left, top}, w, h, dev, profile, extent);
  auto x_of = [&](double s) { return left + static_cast<int>(std::lround(s / perimeter * w)); };

  // Along the outline: where invert, walls and crown are, and metres.
  struct Named {
    double angle;
    const char* name;
  };
  for (const Named& n :
       {Named{-std::numbers::pi / 2, "invert"}, Named{0, "right wall"},
        Named{std::numbers::pi / 2, "crown"}, Named{std::numbers::pi, "left wall"}}) {
    const double s = profile.ray_hit(n.angle).s;
    const int x = x_of(s);
    cv::line(img, {x, top + h}, {x, top + h + 8}, kInk, 2);
    draw_label(img, n.name,
               {std::clamp(x - text_width(n.name, 0.45) / 2, 2, img.cols - 90), top + h + 40},
               0.45);
  }
  for (int m = 0; m <= static_cast<int>(perimeter); ++m) {
    const int x = x_of(m);
    cv::line(img, {x, top + h}, {x, top + h + 4}, kInk, 1);
    if (m % 2 == 0) draw_label(img, std::to_string(m), {x - 4, top + h + 20}, 0.38);
  }
  draw_label(img, "m along the design line",
             {left + w - text_width("m along the design line", 0.4), top + h + 20 + 34}, 0.4);
  // Chainage up the side, the face at the top.
  const int ticks = std::min<int>(6, static_cast<int>(rows));
  for (int k = 0; k < ticks; ++k) {
    const std::size_t i = ticks == 1 ? 0 : k * (rows - 1) / (ticks - 1);
    const int y = top + h - static_cast<int>(std::lround((i + 0.5) * h / rows));
    cv::line(img, {left - 5, y}, {left, y}, kInk, 1);
    draw_label(img, report_number(view.chainage[i], 2), {6, y + 5}, 0.42);
  }
  draw_label(img, "chainage (m), face at the top", {6, top - 8}, 0.42);

  // Colour scale, cm.
  const int bar_y = top + h + 66, bar_w = std::min(w, 420), bar_x = left;
  for (int x = 0; x < bar_w; ++x)
    cv::line(img, {bar_x + x, bar_y}, {bar_x + x, bar_y + 14},
             deviation_colour(2.0 * x / (bar_w - 1) - 1), 1);
  cv::rectangle(img, {bar_x, bar_y}, {bar_x + bar_w, bar_y + 14}, kInk, 1);
  const int cm = static_cast<int>(std::lround(extent * 100));
  draw_label(img, "-" + std::to_string(cm) + " cm under", {bar_x, bar_y + 32}, 0.4);
  draw_label(img, "0", {bar_x + bar_w / 2 - 4, bar_y + 32}, 0.4);
  draw_label(img, "+" + std::to_string(cm) + " cm over", {bar_x + bar_w - 80, bar_y + 32}, 0.4);
  const int tol_x =
      bar_x +
      static_cast<int>(std::lround((0.5 - dev.underbreak_tolerance_m / extent / 2) * bar_w));
  cv::line(img, {tol_x, bar_y - 4}, {tol_x, bar_y + 18}, cv::Scalar(0, 0, 0), 2);
  const std::string legend = "black outline: underbreak beyond " +
                             report_number(dev.underbreak_tolerance_m * 100, 0) +
                             " cm;  hatched: not seen or left out;  dark: range pole";
  draw_label(img, legend, {bar_x, bar_y + 54}, 0.4);

  const std::string title = "Round ch " + report_number(view.chainage.front(), 2) + " to " +
                            report_number(view.chainage.back(), 2) + ": overbreak " +
                            report_number(dev.overbreak_volume_m3, 2) + " m3, underbreak " +
                            report_number(dev.underbreak_volume_m3, 2) + " m3, seen " +
                            report_number(dev.seen_fraction * 100, 0) + " %";
  draw_label(img, title, {6, 20}, 0.5);
  if (dev.has_underbreak)
    draw_label(img,
               "deepest underbreak " + report_number(dev.max_underbreak_m * 100, 1) + " cm at ch " +
                   report_number(dev.max_underbreak.chainage, 2) + ", " +
                   report_number(dev.max_underbreak.s, 2) + " m along the line (x)",
               {6, 42}, 0.42);
  return img;
}

cv::Scalar drive_set_colour(int id) {
  static const cv::Scalar palette[] = {{40, 40, 214},   {180, 119, 31},  {44, 160, 44},
                                       {14, 127, 255},  {189, 103, 148}, {75, 86, 140},
                                       {194, 119, 227}, {34, 189, 188}};
  return palette[static_cast<std::size_t>(std::max(1, id) - 1) % std::size(palette)];
}

cv::Mat drive_picture(const tunnel::DriveSets& drive, int width_px, int height_px) {
  cv::Mat img(height_px, width_px, CV_8UC3, kPaper);
  const int left = 70, right = 190, top = 40, gap = 50, bottom = 50;
  const int w = width_px - left - right;
  const int ph = (height_px - top - gap - bottom) / 2;
  draw_label(img, "Joint sets along the drive", {8, 24}, 0.6);
  if (drive.visits.empty()) {
    draw_label(img, "no visit is placed in the tunnel", {left, top + 40}, 0.5);
    return img;
  }
  double c0 = drive.visits.front().chainage, c1 = c0;
  for (const auto& v : drive.visits) {
    c0 = std::min(c0, v.chainage);
    c1 = std::max(c1, v.chainage);
  }
  if (c1 - c0 < 1) {
    c0 -= 0.5;
    c1 += 0.5;
  }
  const double pad = 0.04 * (c1 - c0);
  c0 -= pad;
  c1 += pad;
  auto x_of = [&](double c) {
    return left + static_cast<int>(std::lround((c - c0) / (c1 - c0) * w));
  };
  struct Panel {
    int y0;
    double lo, hi;
    const char* label;
  };
  const Panel panels[2] = {{top, 0, 360, "dip direction (deg)"},
                           {top + ph + gap, 0, 90, "dip (deg)"}};
  for (const auto& p : panels) {
    cv::rectangle(img, {left, p.y0}, {left + w, p.y0 + ph}, kInk, 1);
    const double step = p.hi == 360 ? 90 : 30;
    for (double v = p.lo; v <= p.hi + 1e-9; v += step) {
      const int y = p.y0 + ph - static_cast<int>(std::lround((v - p.lo) / (p.hi - p.lo) * ph));
      cv::line(img, {left, y}, {left + w, y}, cv::Scalar(225, 225, 225), 1);
      draw_label(img, report_number(v, 0), {left - 40, y + 5}, 0.4);
    }
    draw_label(img, p.label, {left, p.y0 - 6}, 0.45);
  }
  // Chainage ticks on both panels' bottom.
  const double span = c1 - c0;
  const double tick = span > 200 ? 50 : span > 50 ? 10 : span > 10 ? 2 : 1;
  for (double c = std::ceil(c0 / tick) * tick; c <= c1; c += tick) {
    const int x = x_of(c);
    for (const auto& p : panels) cv::line(img, {x, p.y0 + ph}, {x, p.y0 + ph + 4}, kInk, 1);
    draw_label(img, report_number(c, tick < 1 ? 1 : 0), {x - 12, panels[1].y0 + ph + 20}, 0.4);
  }
  draw_label(img, "chainage (m)", {left + w - 100, panels[1].y0 + ph + 40}, 0.42);

  int legend_y = top + 10;
  for (const auto& track : drive.tracks) {
    const cv::Scalar colour = drive_set_colour(track.id);
    cv::Point prev_dd{-1, -1}, prev_dip{-1, -1};
    double prev_dd_value = 0;
    for (const auto& p : track.points) {
      const int x = x_of(p.chainage);
      const cv::Point dd(
          x, panels[0].y0 + ph - static_cast<int>(std::lround(p.dipdir_deg / 360.0 * ph)));
      const cv::Point dip(x,
                          panels[1].y0 + ph - static_cast<int>(std::lround(p.dip_deg / 90.0 * ph)));
      // Dip direction wraps at 0 / 360: no line across the panel.
      if (prev_dd.x >= 0 && std::abs(p.dipdir_deg - prev_dd_value) < 180)
        cv::line(img, prev_dd, dd, colour, 2, cv::LINE_AA);
      if (prev_dip.x >= 0) cv::line(img, prev_dip, dip, colour, 2, cv::LINE_AA);
      const int r = std::clamp(2 + static_cast<int>(std::sqrt(std::max(p.count, 1))), 3, 9);
      cv::circle(img, dd, r, colour, cv::FILLED, cv::LINE_AA);
      cv::circle(img, dip, r, colour, cv::FILLED, cv::LINE_AA);
      if (p.turned) {
        cv::circle(img, dd, r + 5, cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
        cv::circle(img, dip, r + 5, cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
      }
      prev_dd = dd;
      prev_dip = dip;
      prev_dd_value = p.dipdir_deg;
    }
    for (const auto& e : track.events) {
      const int x = x_of(e.chainage);
      const char* mark = e.kind == tunnel::TrackEvent::Kind::appears    ? "new"
                         : e.kind == tunnel::TrackEvent::Kind::vanishes ? "gone"
                                                                        : "turns";
      draw_label(img, mark, {x + 6, panels[1].y0 + 14 + 14 * (track.id % 4)}, 0.4, colour);
      cv::line(img, {x, panels[1].y0}, {x, panels[1].y0 + ph}, colour, 1, cv::LINE_4);
    }
    const auto& m = track.points.back();
    std::string entry = "set " + std::to_string(track.id) + ": " + report_number(m.dip_deg, 0) +
                        "/" + report_number(m.dipdir_deg, 0);
    cv::rectangle(img, {left + w + 14, legend_y - 10}, {left + w + 26, legend_y + 2}, colour,
                  cv::FILLED);
    draw_label(img, entry, {left + w + 32, legend_y}, 0.42);
    legend_y += 18;
    std::string flags;
    if (track.appears) flags += "new ";
    if (track.turns) flags += "turns ";
    if (track.vanishes) flags += "gone";
    if (!flags.empty()) {
      draw_label(img, "  " + flags, {left + w + 32, legend_y}, 0.38, colour);
      legend_y += 18;
    }
  }
  draw_label(img, "ringed: turned beyond its cone", {left + w + 14, top + 2 * ph + gap}, 0.36);
  return img;
}

}  // namespace rockface::storage

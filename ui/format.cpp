#include "ui/format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace rockface::ui::format {

namespace {

std::string printf_text(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

// -0.0 and rounding to zero of a small negative value print as "-0.0".
double no_negative_zero(double v, double step) {
  return std::abs(v) < step / 2 ? 0.0 : v;
}

std::string grouped(std::int64_t n) {
  std::string digits = std::to_string(n < 0 ? -n : n);
  std::string out;
  const int lead = static_cast<int>(digits.size()) % 3;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (static_cast<int>(i) - lead) % 3 == 0) out += ',';
    out += digits[i];
  }
  return (n < 0 ? "-" : "") + out;
}

}  // namespace

std::string text(Angle a) {
  if (!std::isfinite(a.deg)) return unknown();
  return printf_text("%.1f°", no_negative_zero(a.deg, 0.1));
}

std::string text(Length l) {
  if (!std::isfinite(l.m)) return unknown();
  const double m = std::abs(l.m);
  // Millimetres below 10 cm (a residual, a precision, a point spacing),
  // centimetres never (a geologist writes mm or m), metres to 10 km.
  if (m < 0.01) return printf_text("%.1f mm", no_negative_zero(l.m * 1000, 0.1));
  if (m < 0.1) return printf_text("%.0f mm", l.m * 1000);
  if (m < 10) return printf_text("%.2f m", l.m);
  if (m < 1000) return printf_text("%.1f m", l.m);
  return printf_text("%.2f km", l.m / 1000);
}

std::string text(Area a) {
  if (!std::isfinite(a.m2)) return unknown();
  return printf_text(std::abs(a.m2) < 10 ? "%.2f m²" : "%.1f m²", a.m2);
}

std::string text(Volume v) {
  if (!std::isfinite(v.m3)) return unknown();
  const double x = std::abs(v.m3);
  // Three significant digits: a block's volume from traces is good to a few
  // per cent at best.
  if (x < 0.001) return printf_text("%.1f litres", v.m3 * 1000);
  if (x < 1) return printf_text("%.3f m³", v.m3);
  if (x < 10) return printf_text("%.2f m³", v.m3);
  if (x < 100) return printf_text("%.1f m³", v.m3);
  return grouped(std::llround(v.m3)) + " m³";
}

std::string text(FactorOfSafety f) {
  if (!std::isfinite(f.value)) return unknown();
  if (f.value > 100) return "over 100";
  return printf_text("%.2f", f.value);
}

std::string text(Duration d) {
  if (!std::isfinite(d.seconds) || d.seconds < 0) return unknown();
  if (d.seconds < 1) return printf_text("%.0f ms", d.seconds * 1000);
  if (d.seconds < 10) return printf_text("%.1f s", d.seconds);
  if (d.seconds < 60) return printf_text("%.0f s", d.seconds);
  const auto total = std::llround(d.seconds);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%lld min %02lld s", total / 60, total % 60);
  return buf;
}

std::string text(Fraction f) {
  if (!std::isfinite(f.value)) return unknown();
  return printf_text("%.0f %%", f.value * 100);
}

std::string azimuth(double deg) {
  if (!std::isfinite(deg)) return unknown();
  double d = std::fmod(deg, 360.0);
  if (d < 0) d += 360;
  if (d >= 359.95) d = 0;  // 359.97 rounds to 360.0, which is 000.0
  return printf_text("%05.1f°", d);
}

std::string dip_and_direction(double dip_deg, double dipdir_deg) {
  return text(Angle{dip_deg}) + " / " + azimuth(dipdir_deg);
}

std::string plus_minus(Length sigma) {
  return "± " + text(sigma);
}

std::string pixels(double px) {
  if (!std::isfinite(px)) return unknown();
  return printf_text(std::abs(px) < 10 ? "%.2f px" : "%.0f px", px);
}

std::string factor(double value) {
  if (!std::isfinite(value)) return unknown();
  return printf_text("%.4f", value);
}

std::string one_in(double ratio) {
  if (!std::isfinite(ratio) || ratio <= 0) return unknown();
  return printf_text("1 : %.1f", 1 / ratio);
}

std::string count(std::int64_t n) {
  if (std::abs(n) >= 1000000) return printf_text("%.1f million", static_cast<double>(n) / 1e6);
  return grouped(n);
}

std::string count(std::int64_t n, std::string_view singular, std::string_view plural) {
  return count(n) + " " + std::string(n == 1 ? singular : plural);
}

std::string unknown(std::string_view why) {
  if (why.empty()) return "—";
  return "— (" + std::string(why) + ")";
}

std::string date_time(std::string_view iso) {
  std::string s(iso.substr(0, 16));
  if (s.size() > 10 && s[10] == 'T') s[10] = ' ';
  return s;
}

std::string file_name(std::string_view path) {
  const auto slash = path.find_last_of("/\\");
  return std::string(slash == std::string_view::npos ? path : path.substr(slash + 1));
}

std::string without_folders(std::string_view text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t end = std::min(text.find(' ', i), text.size());
    const std::string_view word = text.substr(i, end - i);
    out += word.find('/') == std::string_view::npos ? std::string(word) : file_name(word);
    if (end < text.size()) out += ' ';
    i = end + 1;
  }
  return out;
}

std::string in_words(std::string_view key) {
  static const std::map<std::string, std::string, std::less<>> words = {
      {"range_pole_compass", "range pole and compass line"},
      {"range pole", "range pole"},
      {"control points", "control points"},
      {"baseline", "measured camera base"},
      {"compass", "compass line on the face"},
      {"face_images", "registered onto pair 1"},
      {"rotation", "moved and turned by the typed placement"},
      {"translation", "moved by the typed placement"},
      {"fast", "fast"},
      {"standard", "standard"},
      {"precise", "precise"},
      {"traces", "traces"},
      {"sets", "joint sets"},
  };
  if (const auto it = words.find(key); it != words.end()) return it->second;
  std::string out(key);
  for (char& c : out)
    if (c == '_') c = ' ';
  return out;
}

}  // namespace rockface::ui::format

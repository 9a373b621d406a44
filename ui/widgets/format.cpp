#include "ui/widgets/format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/common/number_format.h"

namespace rockface::ui::format {

namespace {

// `v` to `decimals` places, but never more than six significant digits (a
// figure the field never measures that finely): fewer places for a large
// value, and powers of ten beyond a million.
std::string fixed(double v, int decimals, const char* unit = "") {
  const double a = std::abs(v);
  const int whole = a < 1 ? 1 : static_cast<int>(std::floor(std::log10(a))) + 1;
  if (whole > 6) return format_significant(v, 3, unit);
  return format_fixed(v, std::max(0, std::min(decimals, 6 - whole)), unit);
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
  return fixed(no_negative_zero(a.deg, 0.1), 1, "°");
}

std::string text(Length l) {
  if (!std::isfinite(l.m)) return unknown();
  const double m = std::abs(l.m);
  // Millimetres below 10 cm (a residual, a precision, a point spacing),
  // centimetres never (a geologist writes mm or m), metres to 10 km.
  if (m < 0.01) return fixed(no_negative_zero(l.m * 1000, 0.1), 1, " mm");
  if (m < 0.1) return fixed(l.m * 1000, 0, " mm");
  if (m < 10) return fixed(l.m, 2, " m");
  if (m < 1000) return fixed(l.m, 1, " m");
  return fixed(l.m / 1000, 2, " km");
}

std::string text(Area a) {
  if (!std::isfinite(a.m2)) return unknown();
  return fixed(a.m2, std::abs(a.m2) < 10 ? 2 : 1, " m²");
}

std::string text(Volume v) {
  if (!std::isfinite(v.m3)) return unknown();
  const double x = std::abs(v.m3);
  // Three significant digits: a block's volume from traces is good to a few
  // per cent at best.
  if (x < 0.001) return fixed(v.m3 * 1000, 1, " litres");
  if (x < 1) return fixed(v.m3, 3, " m³");
  if (x < 10) return fixed(v.m3, 2, " m³");
  if (x < 100) return fixed(v.m3, 1, " m³");
  return fixed(v.m3, 0, " m³");
}

std::string text(FactorOfSafety f) {
  if (!std::isfinite(f.value)) return unknown();
  if (f.value > 100) return "over 100";
  return fixed(f.value, 2, "");
}

std::string text(Duration d) {
  if (!std::isfinite(d.seconds) || d.seconds < 0) return unknown();
  if (d.seconds < 1) return fixed(d.seconds * 1000, 0, " ms");
  if (d.seconds < 10) return fixed(d.seconds, 1, " s");
  if (d.seconds < 60) return fixed(d.seconds, 0, " s");
  if (d.seconds >= 3600) return fixed(d.seconds / 3600, 1, " h");
  const auto total = std::llround(d.seconds);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%lld min %02lld s", total / 60, total % 60);
  return buf;
}

std::string text(Fraction f) {
  if (!std::isfinite(f.value)) return unknown();
  return fixed(f.value * 100, 0, " %");
}

std::string azimuth(double deg) {
  if (!std::isfinite(deg)) return unknown();
  double d = std::fmod(deg, 360.0);
  if (d < 0) d += 360;
  if (d >= 359.95) d = 0;                   // 359.97 rounds to 360.0, which is 000.0
  return format_zero_padded(d, 5, 1, "°");  // 0 to 360: never more than four digits
}

std::string dip_and_direction(double dip_deg, double dipdir_deg) {
  return text(Angle{dip_deg}) + " / " + azimuth(dipdir_deg);
}

std::string plus_minus(Length sigma) {
  return "± " + text(sigma);
}

std::string pixels(double px) {
  if (!std::isfinite(px)) return unknown();
  return fixed(px, std::abs(px) < 10 ? 2 : 0, " px");
}

std::string factor(double value) {
  if (!std::isfinite(value)) return unknown();
  return fixed(value, 4, "");
}

std::string one_in(double ratio) {
  if (!std::isfinite(ratio) || ratio <= 0) return unknown();
  return "1 : " + fixed(1 / ratio, 1);
}

std::string count(std::int64_t n) {
  if (std::abs(n) >= 1000000) return fixed(static_cast<double>(n) / 1e6, 1, " million");
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
    // An absolute path (or one from the home folder), perhaps after an
    // opening bracket or quote; "1/8" and "J1/J2" are not paths.
    const std::size_t lead = std::min(word.find_first_not_of("(\"'"), word.size());
    const std::string_view rest = word.substr(lead);
    const bool path = rest.size() > 1 && (rest[0] == '/' || (rest[0] == '~' && rest[1] == '/'));
    out += path ? std::string(word.substr(0, lead)) + file_name(rest) : std::string(word);
    if (end < text.size()) out += ' ';
    i = end + 1;
  }
  return out;
}

std::string in_words(std::string_view key) {
  static const std::map<std::string, std::string, std::less<>> words = {
      {"range_pole_compass", "range pole and compass line"},
      {"range_pole", "range pole (no compass line)"},
      {"ground_control", "control points"},
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

std::string registered_by(std::string_view kind) {
  if (kind == "range_pole_compass" || kind == "ground_control")
    return "scaled and oriented by " + in_words(kind);
  if (kind == "range_pole") return "scaled and levelled by range pole; no north (no compass line)";
  if (kind == "baseline") return "scaled by the measured camera base";
  if (kind == "scanner")
    return "imported in survey coordinates: scaled, levelled and oriented by the scanner's "
           "registration";
  if (kind == "face_images") return in_words(kind);
  if (kind == "none" || kind.empty())
    return "not scaled or oriented (no range pole, control points or baseline)";
  return "registered by " + in_words(kind);
}

}  // namespace rockface::ui::format

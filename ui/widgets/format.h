#pragma once
// Figures as the tablet shows them: each with its unit and the precision a
// geologist reads it to, never a raw double. One type per kind of value, so
// a screen cannot print a length as an angle or a factor of safety with 15
// digits; every screen goes through these.
//
//   angle        60.2°              (0.1°; a dip direction 3 digits: 005.0°)
//   length       12 mm, 0.85 m, 12.4 m, 1.25 km  (the unit that fits)
//   precision    ± 2.3 mm           (a small length: mm below 1 m)
//   area         1.25 m²
//   volume       0.709 m³           (3 significant digits)
//   fos          0.48               (2 decimals)
//   count        3 traces, 1 trace, 12,345 vertices, 2.3 million
//   ratio        1 : 6.8
//   percent      87 %
//   duration     340 ms, 12 s, 2 min 05 s
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rockface::ui::format {

struct Angle {
  double deg;
};
struct Length {
  double m;
};
struct Area {
  double m2;
};
struct Volume {
  double m3;
};
struct FactorOfSafety {
  double value;
};
struct Duration {
  double seconds;
};
// A fraction 0..1 shown in per cent.
struct Fraction {
  double value;
};

std::string text(Angle a);   // "60.2°"
std::string text(Length l);  // unit that fits
std::string text(Area a);
std::string text(Volume v);
std::string text(FactorOfSafety f);
std::string text(Duration d);
std::string text(Fraction f);  // "87 %"

// A dip direction or a trend: three digits before the point (005.0°).
std::string azimuth(double deg);
// A plane as geologists write it: dip / dip direction, "60.2° / 199.9°".
std::string dip_and_direction(double dip_deg, double dipdir_deg);
// An uncertainty of a length: "± 2.3 mm".
std::string plus_minus(Length sigma);
// Pixels, one decimal below 10 px: "0.31 px", "12 px".
std::string pixels(double px);
// A scale factor or a ratio near 1: 4 decimals ("1.0021").
std::string factor(double value);
// "1 : 6.8" (the base to distance ratio as a fraction of the distance).
std::string one_in(double ratio);

// An integer count with its noun: "1 trace", "3 traces", "12,345 vertices";
// from a million on, "2.3 million vertices" (nobody reads the last digits).
std::string count(std::int64_t n, std::string_view singular, std::string_view plural);
std::string count(std::int64_t n);  // the number alone, grouped: "12,345"

// "—" for a figure that does not exist, with the reason when one is given.
std::string unknown(std::string_view why = {});
// An optional figure: the figure, or unknown(why).
template <class T>
std::string text_or(const std::optional<T>& v, std::string_view why = {}) {
  return v ? text(*v) : unknown(why);
}

// A stored time stamp (ISO 8601, "2026-11-26T03:45:12Z") to the minute:
// "2026-11-26 03:45".
std::string date_time(std::string_view iso);

// A file's name without its folders: what a screen shows of a path (the
// machine's folders mean nothing to the geologist and leak into pictures).
std::string file_name(std::string_view path);

// Text with absolute paths in it ("replay /…/face.scene.json") with
// each cut to its file name ("replay face.scene.json"); "1/8" stays.
std::string without_folders(std::string_view text);

// An identifier of the program ("range_pole_compass") in words
// ("range pole and compass line"); unknown ones with their underscores as
// spaces.
std::string in_words(std::string_view key);

// What a stored registration kind did to the 3D image, in a phrase that
// claims no more (issue 42): "scaled and oriented by range pole and compass
// line", "scaled and levelled by range pole; no north (no compass line)".
std::string registered_by(std::string_view kind);

}  // namespace rockface::ui::format

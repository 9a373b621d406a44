#include "core/common/number_format.h"

#include <cstdio>

namespace rockface {

namespace {

// printf of one double with one precision, as long as it needs to be.
std::string print_number(const char* format, int precision, double v, std::string_view unit) {
  if (precision < 0) precision = 0;
  char small[64];
  const int n = std::snprintf(small, sizeof small, format, precision, v);
  std::string out;
  if (n < 0) return "nan";
  if (static_cast<std::size_t>(n) < sizeof small) {
    out.assign(small, static_cast<std::size_t>(n));
  } else {
    out.resize(static_cast<std::size_t>(n) + 1);
    std::snprintf(out.data(), out.size(), format, precision, v);
    out.resize(static_cast<std::size_t>(n));
  }
  out += unit;
  return out;
}

}  // namespace

std::string format_fixed(double v, int decimals, std::string_view unit) {
  return print_number("%.*f", decimals, v, unit);
}

std::string format_significant(double v, int digits, std::string_view unit) {
  return print_number("%.*g", digits, v, unit);
}

std::string format_round_trip(double v, std::string_view unit) {
  return format_significant(v, 17, unit);
}

}  // namespace rockface

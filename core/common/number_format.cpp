#include "core/common/number_format.h"

#include <cstdio>

namespace rockface {

namespace {

// printf of one double with its precision (and width), as long as it needs
// to be, then the unit.
template <typename... Ints>
std::string print_number(std::string_view unit, const char* format, Ints... ints_then_value) {
  char small[64];
  const int n = std::snprintf(small, sizeof small, format, ints_then_value...);
  std::string out;
  if (n < 0) return "nan";
  if (static_cast<std::size_t>(n) < sizeof small) {
    out.assign(small, static_cast<std::size_t>(n));
  } else {
    out.resize(static_cast<std::size_t>(n) + 1);
    std::snprintf(out.data(), out.size(), format, ints_then_value...);
    out.resize(static_cast<std::size_t>(n));
  }
  out += unit;
  return out;
}

int at_least_zero(int n) {
  return n < 0 ? 0 : n;
}

}  // namespace

std::string format_fixed(double v, int decimals, std::string_view unit) {
  return print_number(unit, "%.*f", at_least_zero(decimals), v);
}

std::string format_significant(double v, int digits, std::string_view unit) {
  return print_number(unit, "%.*g", at_least_zero(digits), v);
}

std::string format_zero_padded(double v, int width, int decimals, std::string_view unit) {
  return print_number(unit, "%0*.*f", at_least_zero(width), at_least_zero(decimals), v);
}

std::string format_round_trip(double v, std::string_view unit) {
  return format_significant(v, 17, unit);
}

}  // namespace rockface

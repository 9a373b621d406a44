#include "firmware-app/wedges/support_options.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "core/common/error.h"
#include "core/tunnel/support_ranges.h"

namespace rockface::app {

namespace {

std::vector<double> numbers(const std::string& text, const std::string& where, std::size_t min,
                            std::size_t max, const std::string& form) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    // strtod, not stod: a value beyond the range of a double (1e-320,
    // 1e309) is read as what it is and refused by its range, not as "not
    // a number".
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size())
      throw InputError(where, "\"" + text + "\" is not " + form);
    out.push_back(v);
    if (!(out.back() > 0)) throw InputError(where, "every value of " + form + " must be positive");
  }
  if (out.size() < min || out.size() > max)
    throw InputError(where, "\"" + text + "\" is not " + form);
  return out;
}

// The scene's shotcrete thickness (scene_wedges_json.cpp: 1 mm to 2 m).
constexpr tunnel::SupportRange kShotcreteThicknessRange{1e-3, 2.0, "m"};

void require_in(double v, const tunnel::SupportRange& range, const char* part,
                const std::string& where, const char* what) {
  if (!range.contains(v))
    throw InputError(where, std::string(part) + ": " + tunnel::outside_range_text(v, range, what));
}

}  // namespace

tunnel::PatternBolts parse_pattern_bolts(const std::string& text, const std::string& where) {
  const auto v = numbers(text, where, 3, 4, "LENGTH,SPACING,CAPACITY[,BOND] (m, m, N, N/m)");
  const std::pair<const char*, const tunnel::SupportRange*> parts[] = {
      {"LENGTH", &tunnel::kBoltLengthRange},
      {"SPACING", &tunnel::kBoltSpacingRange},
      {"CAPACITY", &tunnel::kBoltCapacityRange},
      {"BOND", &tunnel::kBoltBondRange}};
  for (std::size_t i = 0; i < v.size(); ++i)
    require_in(v[i], *parts[i].second, parts[i].first, where, "the bolts' setting");
  tunnel::PatternBolts b;
  b.length = v[0];
  b.spacing = v[1];
  b.capacity = v[2];
  if (v.size() == 4) b.bond_strength = v[3];
  return b;
}

tunnel::Shotcrete parse_shotcrete(const std::string& text, const std::string& where) {
  const auto v = numbers(text, where, 2, 2, "THICKNESS,SHEAR_STRENGTH (m, Pa)");
  require_in(v[0], kShotcreteThicknessRange, "THICKNESS", where, "the shotcrete's setting");
  require_in(v[1], tunnel::kShotcreteShearRange, "SHEAR_STRENGTH", where,
             "the shotcrete's setting");
  tunnel::Shotcrete sc;
  sc.thickness = v[0];
  sc.shear_strength = v[1];
  return sc;
}

}  // namespace rockface::app

#pragma once
// Angles are degrees only at the boundary of the program (files, UI,
// reports) and radians inside; these are the only conversions.
#include <numbers>

namespace rockface {

constexpr double kPi = std::numbers::pi;
constexpr double deg_to_rad(double deg) { return deg * kPi / 180.0; }
constexpr double rad_to_deg(double rad) { return rad * 180.0 / kPi; }

}  // namespace rockface

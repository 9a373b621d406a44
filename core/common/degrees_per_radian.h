#pragma once
// Degrees per radian for the reports' `angle * kDegPerRad`: the same double
// as 180.0 / std::numbers::pi, which several tunnel and wedge files each
// defined for themselves (a unity build puts such files in one translation
// unit). Kept apart from units.h so that the files including units.h did
// not all have to be compiled again.
#include "core/common/units.h"

namespace rockface {

constexpr double kDegPerRad = 180.0 / kPi;

}  // namespace rockface

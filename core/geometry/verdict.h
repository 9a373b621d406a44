#pragma once
// A geometric verdict with its margin (DESIGN.md, "Conventions"): the angle by
// which the deciding cone is open or shut. Inside the numerical tolerance or
// the orientation uncertainty of the measurements behind it, the verdict is
// marginal: reported as it came out, flagged, never silently rounded.
#include <cmath>

#include "core/geometry/tolerances.h"

namespace rockface::geometry {

struct Verdict {
  bool value = false;
  double margin = 0;      // radians, >= 0: how firmly `value` holds
  bool marginal = false;
};

// From a signed quantity whose sign decides (positive -> true) and the
// uncertainty (radians) of the orientations behind it.
inline Verdict decide(double signed_margin, double uncertainty_rad) {
  Verdict v;
  v.value = signed_margin > 0;
  v.margin = std::abs(signed_margin);
  v.marginal = v.margin <= kAngleEpsRad || v.margin < uncertainty_rad;
  return v;
}

}  // namespace rockface::geometry

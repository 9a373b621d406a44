#include "core/mechanics/shear_test.h"

#include <cmath>
#include <optional>

#include "core/common/error.h"
#include "core/mechanics/tolerances.h"

namespace rockface::mechanics {

namespace {

// A stiff joint dilating over a long step changes its normal stress by kn x
// dv within the step, which no closure can hold exactly: such a step is
// split (at most this many times in halves).
constexpr int kMaxSplits = 24;
// The boundary is held when the normal stress is within this fraction of
// its target.
constexpr double kBoundaryRel = 1e-7;

struct Driver {
  const JointLaw& law;
  ShearTestBoundary boundary;
  double c0;  // closure under the initial load
  JointState state;
  double closure;

  double target(double c) const {
    return boundary.normal_stress + boundary.normal_stiffness * (c0 - c);
  }

  // One step to shear u from the committed state; nothing if the boundary
  // cannot be held.
  std::optional<JointResponse> step(double u, double& c_out) const {
    const Eigen::Vector2d shear(u, 0);
    // h(c) = sigma_n(c) - target(c) grows with the closure c: bracket, bisect.
    auto h = [&](double c) { return law.respond(state, c, shear, 1.0).normal_stress - target(c); };
    double span = c0;
    double lo = closure - span, hi = closure + span;
    for (int k = 0; k < 60 && h(lo) > 0; ++k) lo -= (span *= 2);
    span = c0;
    for (int k = 0; k < 60 && h(hi) < 0; ++k) hi += (span *= 2);
    if (h(lo) > 0 || h(hi) < 0) return std::nullopt;
    for (int it = 0; it < kReturnMappingIterations && hi - lo > kReturnMappingRel * c0; ++it) {
      const double mid = 0.5 * (lo + hi);
      (h(mid) > 0 ? hi : lo) = mid;
    }
    c_out = 0.5 * (lo + hi);
    JointResponse r = law.respond(state, c_out, shear, 1.0);
    if (std::abs(r.normal_stress - target(c_out)) > kBoundaryRel * boundary.normal_stress)
      return std::nullopt;
    return r;
  }

  // Advances from shear `from` to `to`, splitting where needed.
  bool advance(double from, double to, int depth, JointResponse& last) {
    double c = closure;
    if (auto r = step(to, c)) {
      state = r->state;
      closure = c;
      last = *r;
      return true;
    }
    if (depth >= kMaxSplits) return false;
    const double mid = 0.5 * (from + to);
    return advance(from, mid, depth + 1, last) && advance(mid, to, depth + 1, last);
  }
};

}  // namespace

std::vector<ShearTestPoint> shear_test(const JointLaw& law, const ShearTestBoundary& boundary,
                                       const std::vector<double>& shear_path) {
  if (!(boundary.normal_stress > 0))
    throw InputError("shear_test.normal_stress", "must be a positive (compressive) stress");
  const double c0 = boundary.normal_stress / law.normal_stiffness();
  Driver d{law, boundary, c0, {}, c0};
  std::vector<ShearTestPoint> out;
  double previous = 0;
  for (double u : shear_path) {
    JointResponse r;
    if (!d.advance(previous, u, 0, r))
      throw Error("shear test: the normal stress cannot be held at shear " + std::to_string(u) +
                  " m");
    previous = u;
    ShearTestPoint p;
    p.shear = u;
    p.shear_stress = r.shear_stress.x();
    p.normal_stress = r.normal_stress;
    p.opening = c0 - d.closure;
    p.stage = r.stage;
    p.state = d.state;
    out.push_back(p);
  }
  return out;
}

}  // namespace rockface::mechanics

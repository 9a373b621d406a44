// Wedges around the tunnel-wedges sample's horseshoe drive when one set is
// the first turned by 0.0035 to 0.02 degrees (issue 40): these used to come
// out as "could not be built: the half-spaces did not give a consistent
// polyhedron" with margins of 20-70 degrees, which ones depending on the
// angle. Each must be built, with the codes that wider angles give, a
// volume and a margin that go to zero in proportion to the angle (the
// limit: two sets that coincide bound nothing), and a marginal flag
// wherever its margin is inside the uncertainty.
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/geometry/orientation.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::tunnel {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;

struct Case {
  int replaced;  // the set that becomes J1 turned
  bool by_dip;   // turned in dip (else in dip direction)
};

// The sample's three sets, with one replaced by J1 turned by `apart_deg`,
// and its profile, axis and trace-length limit; an uncertainty of 0.001
// degree, below the angles tried (at the sample's 2 degrees the sets would
// be refused as one).
WedgeAnalysis sample_wedges(const Case& c, double apart_deg) {
  std::vector<WedgeJointSet> sets{{"J1", geometry::plane_normal_deg(65, 20), 32 * kRad, 0},
                                  {"J2", geometry::plane_normal_deg(60, 145), 30 * kRad, 0},
                                  {"J3", geometry::plane_normal_deg(55, 260), 30 * kRad, 0}};
  sets[c.replaced].normal = c.by_dip ? geometry::plane_normal_deg(65 + apart_deg, 20)
                                     : geometry::plane_normal_deg(65, 20 + apart_deg);
  WedgeOptions o;
  o.density = 2650;
  o.trace_length_limit = 6.0;
  o.uncertainty = 0.001 * kRad;
  return analyse_wedges(horseshoe_profile(3.0, 1.0, 5.0, -1.5),
                        axis_frame(35 * kRad, 2 * kRad, Eigen::Vector3d::Zero(), "axis"),
                        Eigen::Vector3d::Zero(), sets, o);
}

std::map<std::string, const Wedge*> by_code(const WedgeAnalysis& a) {
  std::map<std::string, const Wedge*> out;
  for (const auto& w : a.wedges) out[w.code] = &w;
  return out;
}

TEST(NearParallelSets, EveryWedgeIsBuiltAndShrinksWithTheAngle) {
  const double reference_deg = 0.01;
  for (const Case c : {Case{1, false}, Case{1, true}, Case{2, false}, Case{2, true}}) {
    const WedgeAnalysis ref = sample_wedges(c, reference_deg);
    const auto ref_wedges = by_code(ref);
    // The codes a well-separated pair gives (0.1 degree) are the reference's.
    std::vector<std::string> wide, near;
    for (const auto& [code, w] : by_code(sample_wedges(c, 0.1))) wide.push_back(code);
    for (const auto& [code, w] : ref_wedges) near.push_back(code);
    EXPECT_EQ(near, wide);
    for (double apart : {0.0035, 0.005, 0.0075, 0.01, 0.015, 0.02}) {
      SCOPED_TRACE("set " + std::to_string(c.replaced + 1) + " is J1 turned by " +
                   std::to_string(apart) + " deg in " + (c.by_dip ? "dip" : "dip direction"));
      const WedgeAnalysis a = sample_wedges(c, apart);
      for (const NoWedge& n : a.none)
        EXPECT_EQ(n.reason.find("could not be built"), std::string::npos)
            << n.code << ": " << n.reason << " (margin " << n.margin / kRad << " deg)";
      const auto wedges = by_code(a);
      ASSERT_EQ(wedges.size(), ref_wedges.size());
      for (const auto& [code, w] : wedges) {
        ASSERT_TRUE(ref_wedges.count(code)) << code;
        const Wedge& r = *ref_wedges.at(code);
        EXPECT_EQ(w->place, r.place) << code;
        // Volume and margin vanish with the angle: V = a t + b t^2 + ...
        // The second order, measured on these wedges at 0.5 degree, moves
        // V / t by under 4 % per 0.5 degree (< 0.08 per degree), so by
        // under 8e-4 over |t - 0.01| <= 0.01 degree; the trace-length
        // bisection adds ~3e-6 (kWedgeTraceRel). 1e-3 relative.
        EXPECT_NEAR(w->mass.volume / apart, r.mass.volume / reference_deg,
                    1e-3 * r.mass.volume / reference_deg)
            << code;
        EXPECT_NEAR(w->removable.margin / apart, r.removable.margin / reference_deg,
                    1e-3 * std::abs(r.removable.margin) / reference_deg)
            << code;
        // Inside the uncertainty it says so.
        if (std::abs(w->removable.margin) < 0.001 * kRad) {
          EXPECT_TRUE(w->removable.marginal) << code;
        }
      }
    }
  }
}

}  // namespace
}  // namespace rockface::tunnel

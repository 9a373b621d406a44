// Two joint sets 0.001 to 0.04 degrees apart, drawn at random with a third
// set and the tunnel's axis, at an orientation uncertainty of 1e-4 degree
// (issue 40): 5 of 133 such draws gave "could not be built" (the thin
// pyramid's end piece was unbounded). Every pyramid of every draw must give
// its wedge, or an honest "no wedge" whose margin says why; nothing left
// unbuilt. The truth a wedge is checked against is the limit: a wedge
// between two sets that coincide has no volume, so its volume grows in
// proportion to their angle (a 1 % wider angle, a 1 % larger wedge, to
// the second order's share).
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/tunnel/wedge_analysis.h"
#include "tests/hardcases/parallel_sets/near_parallel_draws.h"

namespace rockface::tunnel {
namespace {

using test::analyse;
using test::Draw;
using test::draws;
using test::kRad;

TEST(NearParallelSetDraws, NoPyramidIsLeftUnbuilt) {
  int unbuilt = 0, wedges = 0, compared = 0;
  const std::vector<Draw> all = draws(133);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Draw& d = all[i];
    std::ostringstream what;
    what.precision(12);
    what << "draw " << i << ": J1 " << d.dip1 << "/" << d.dir1 << ", J2 turned " << d.apart
         << " deg toward " << d.turn << ", J3 " << d.dip3 << "/" << d.dir3 << ", axis " << d.trend
         << "/" << d.plunge;
    SCOPED_TRACE(what.str());
    const WedgeAnalysis a = analyse(d);
    wedges += static_cast<int>(a.wedges.size());
    for (const NoWedge& n : a.none) {
      if (n.unbuilt) ++unbuilt;
      EXPECT_FALSE(n.unbuilt) << n.code << ": " << n.reason;
      EXPECT_EQ(n.reason.find("could not be built"), std::string::npos)
          << n.code << ": " << n.reason;
    }
    // The angle 1 % wider: each wedge found at both is 1 % larger. V = a t
    // + b t^2 + ...: the higher orders make V(2t) / V(t) fall short of 2
    // by up to 0.21 on these draws (measured: 1.79-2.00; a sector edge
    // moves with the angle and the apex with it), so b t / a <= 0.27 and
    // they move V(1.01 t) / V(t) by under 0.01 x 0.27 = 0.0027; the
    // vertices' rounding (1e-8 m on wedges of 10 m) adds under 1e-4. A
    // wedge with a piece lost or doubled would be off by far more.
    std::map<std::string, double> volume_wider;
    for (const Wedge& w : analyse(d, 1.01).wedges) volume_wider[w.code] = w.mass.volume;
    for (const Wedge& w : a.wedges) {
      EXPECT_GT(w.mass.volume, 0) << w.code;
      if (std::abs(w.removable.margin) <= 1e-4 * kRad) {
        EXPECT_TRUE(w.removable.marginal) << w.code;
      }
      const auto wider = volume_wider.find(w.code);
      if (wider == volume_wider.end()) continue;
      ++compared;
      EXPECT_NEAR(wider->second / w.mass.volume, 1.01, 0.003) << w.code;
    }
  }
  // Most wedges are found at both angles (a wedge may come or go where its
  // margin is within the change of angle).
  EXPECT_GT(compared, wedges * 9 / 10);
  std::cout << "near-parallel draws: " << wedges << " wedges (" << compared
            << " compared at a 1 % wider angle), " << unbuilt << " unbuilt\n";
}

}  // namespace
}  // namespace rockface::tunnel

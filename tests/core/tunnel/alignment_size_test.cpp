// Issue 41: place() on a table of many rows searches the elements through
// bounding spheres instead of scanning every element for every point (a
// replay placed its rock points against 100 000 rows in 75 s). The answer
// is the one a scan in order gives: checked here against the closed form
// of a winding 20 000-element arc table (no timing asserted; tools/bench
// measures it).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/tunnel/alignment.h"

namespace rockface::tunnel {
namespace {

// Closed-form answers from coordinates of ~1 km: a few ulps of 1e3 m,
// plus the Newton foot's kFootChainageM on an arc.
constexpr double kExactM = 1e-8;

TEST(AlignmentSize, TwentyThousandArcsPlaceEveryPointAtItsChainage) {
  // A circle of radius 500 m in 20 000 arcs of 1/20 000 of a turn each,
  // rising 1 m in 100 (a helix), ascending counter-clockwise (radius -:
  // left-hand bends).
  const double R = 500, turn = 2 * std::numbers::pi;
  const std::size_t n = 20000;
  std::vector<AlignmentStation> st;
  std::vector<double> radii;
  for (std::size_t i = 0; i <= n; ++i) {
    const double a = 0.999 * turn * static_cast<double>(i) / static_cast<double>(n);
    st.push_back({R * a, Eigen::Vector3d(R * std::cos(a), R * std::sin(a), 0.01 * R * a)});
    if (i < n) radii.push_back(-R);
  }
  const Alignment al = Alignment::from_elements(st, radii, Eigen::Vector3d::Zero());
  // Points 2 m right of the axis (outside the circle) at 1000 chainages.
  for (int k = 0; k < 1000; ++k) {
    const double c =
        al.first_chainage() + (k + 0.5) / 1000 * (al.last_chainage() - al.first_chainage());
    const TunnelFrame f = al.frame_at(c);
    const Eigen::Vector3d p = f.origin + 2.0 * f.right + 0.5 * f.up;
    const AlignmentPlace at = al.place(p);
    ASSERT_TRUE(at.inside());
    EXPECT_NEAR(at.chainage, c, kExactM) << k;
    EXPECT_NEAR(at.offset, 2.0, kExactM) << k;
    EXPECT_NEAR(at.height, 0.5, kExactM) << k;
  }
}

}  // namespace
}  // namespace rockface::tunnel

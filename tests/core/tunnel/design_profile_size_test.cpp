// Issue 41: a design profile of many segments (a surveyed outline, a
// scanner's polyline) is validated in time linear in its chords when it is
// star-shaped (then it cannot cross itself); the pairwise crossing search,
// quadratic, runs only to say where an outline that is not star-shaped
// crosses itself. 100 000 segments took more than a minute. No timing is
// asserted here (tools/bench measures it): only that a large profile is
// judged, and judged as before.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/tunnel/design_profile.h"
#include "core/tunnel/tolerances.h"

namespace rockface::tunnel {
namespace {

// A polygon of n lines round a circle of radius 3 m; `dent` pulls one
// vertex toward the centre by that fraction of the radius.
std::vector<ProfileSegment> round_polygon(std::size_t n, std::size_t dent_at = 0, double dent = 0) {
  std::vector<Eigen::Vector2d> p;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    const double r = k == dent_at ? 3 * (1 - dent) : 3;
    p.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  std::vector<ProfileSegment> s;
  for (std::size_t k = 0; k < n; ++k) s.push_back(ProfileSegment::line(p[k], p[(k + 1) % n]));
  return s;
}

TEST(DesignProfileSize, TwentyThousandSegmentsAreJudgedStarShapedAndValid) {
  const DesignProfile p(round_polygon(20000));
  const ProfileCheck c = p.validate();
  EXPECT_TRUE(c.ok) << c.message;
  // The polygon's area is within its chords' deficit of the circle's
  // (pi r^2 (1 - sin(2 pi / n) / (2 pi / n)) ~ 1e-6 m^2 at n = 20000).
  EXPECT_NEAR(p.area(), std::numbers::pi * 9, 1e-5);
}

TEST(DesignProfileSize, ALargeOutlineThatCrossesItselfIsStillRefused) {
  // A vertex pulled through the centre and out of the far side: the outline crosses
  // itself and is not star-shaped from any centre.
  const std::size_t n = 2 * kProfileCrossingCheckChords;
  const DesignProfile p(round_polygon(n, n / 2, 2.1), Eigen::Vector2d(0.1, 0.1));
  const ProfileCheck c = p.validate();
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.message.find("not star-shaped"), std::string::npos) << c.message;
  // A small one says where it crosses itself, as before.
  const DesignProfile small(round_polygon(64, 32, 2.1), Eigen::Vector2d(0.1, 0.1));
  EXPECT_NE(small.validate().message.find("crosses itself"), std::string::npos)
      << small.validate().message;
}

}  // namespace
}  // namespace rockface::tunnel

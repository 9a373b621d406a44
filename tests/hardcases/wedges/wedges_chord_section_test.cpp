// A circular section drawn as line chords (issue 40): 1000, 2000 and 5000
// chords of a circle of radius 3 m give the circle's wedges (the same
// codes, volumes within the chords' sagitta), and the section says that
// it merged the chords.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/geometry/orientation.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::tunnel {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRad = kPi / 180;
constexpr double kRadius = 3;

DesignProfile circle_as_chords(int n) {
  std::vector<ProfileSegment> segs;
  auto at = [](int k) {
    const double a = -kPi / 2 + 2 * kPi * k / 40000.0;  // k in 1/40000 turns: exact ends
    return Eigen::Vector2d(kRadius * std::cos(a), kRadius * std::sin(a));
  };
  const int step = 40000 / n;
  for (int k = 0; k < n; ++k)
    segs.push_back(ProfileSegment::line(at(k * step), at((k + 1) * step)));
  return DesignProfile(segs, Eigen::Vector2d(0, 0), "circle as chords");
}

// The tunnel-wedges sample's sets and axis.
std::vector<WedgeJointSet> sample_sets() {
  return {{"J1", geometry::plane_normal_deg(65, 20), 32 * kRad, 0},
          {"J2", geometry::plane_normal_deg(60, 145), 30 * kRad, 0},
          {"J3", geometry::plane_normal_deg(55, 260), 30 * kRad, 0}};
}

TEST(WedgesChordSection, ChordsGiveTheCirclesWedges) {
  const TunnelFrame frame = axis_frame(35 * kRad, 2 * kRad, Eigen::Vector3d::Zero(), "axis");
  const WedgeOptions options;  // the standard sagitta, 2 mm
  const WedgeAnalysis circle = analyse_wedges(circle_profile(kRadius), frame,
                                              Eigen::Vector3d::Zero(), sample_sets(), options);
  ASSERT_GE(circle.wedges.size(), 5u);
  for (int n : {1000, 2000, 5000}) {
    const WedgeAnalysis chords =
        analyse_wedges(circle_as_chords(n), frame, Eigen::Vector3d::Zero(), sample_sets(), options);
    ASSERT_EQ(chords.wedges.size(), circle.wedges.size()) << n << " chords";
    for (std::size_t i = 0; i < circle.wedges.size(); ++i) {
      const Wedge& a = circle.wedges[i];
      const Wedge& b = chords.wedges[i];
      EXPECT_EQ(b.code, a.code) << n;
      // Both sections lie between the circle and the circle shrunk by the
      // sagitta s (2 mm; the given chords' own, under 0.15 mm, adds to
      // it), so each point where a wedge's sector touches the section, and
      // its base, moves by at most s: the wedge's size h (its apex height)
      // changes by at most about 2 s, its volume by 3 x 2 s / h relative.
      const double tol = 3 * 2 * (options.sagitta_m + kRadius * (1 - std::cos(kPi / n))) /
                         std::max(a.apex_height, 1e-3);
      EXPECT_NEAR(b.mass.volume, a.mass.volume, tol * a.mass.volume) << n << " " << a.code;
    }
    for (const auto& none : chords.none)
      EXPECT_EQ(none.reason.find("could not be built"), std::string::npos) << n << " " << none.code;
    bool said = false;
    for (const auto& note : chords.notes) said = said || note.find("merged") != std::string::npos;
    EXPECT_TRUE(said) << n << " chords: the merge is said in the notes";
  }
}

TEST(WedgesChordSection, AWedgeOnMergedChordsListsEveryProfileSegmentUnderItsFace) {
  // Each perimeter wedge's face covers an arc of the circle from one end
  // of its outline to the other; the given chords under that arc are its
  // profile segments. (A merged chord reported only the first segment it
  // replaced: a wedge over 40 given chords listed 3 of them.)
  const TunnelFrame frame = axis_frame(35 * kRad, 2 * kRad, Eigen::Vector3d::Zero(), "axis");
  const int n = 1000;
  const WedgeAnalysis a =
      analyse_wedges(circle_as_chords(n), frame, Eigen::Vector3d::Zero(), sample_sets(), {});
  const double per = 2 * kPi / n;  // each given chord's angle
  int perimeter = 0;
  for (const Wedge& w : a.wedges) {
    if (w.place == WedgePlace::face) continue;
    ++perimeter;
    // The face's ends (the outline's second and last points) as angles
    // from the profile's start (-90 deg, counter-clockwise).
    auto angle = [](const Eigen::Vector2d& p) {
      const double t = std::atan2(p.y(), p.x()) + kPi / 2;
      return t < 0 ? t + 2 * kPi : t;
    };
    double from = angle(w.outline[1]), to = angle(w.outline.back());
    if (from > to) std::swap(from, to);
    if (to - from > kPi) std::swap(from, to);  // the face crosses the start: runs from `from` round
    const double extent = from <= to ? to - from : to + 2 * kPi - from;
    // The chords under it: every one whose angle range meets (from, to).
    // A face end lies on a chord within the sagitta (2 mm on 3 m, under
    // 1e-3 rad): one chord either side is allowed for.
    const int expected = static_cast<int>(std::floor(extent / per));
    EXPECT_GE(static_cast<int>(w.segments.size()), expected - 1) << w.code;
    EXPECT_LE(static_cast<int>(w.segments.size()), expected + 3) << w.code;
    for (std::size_t k : w.segments) {
      const double mid = (k + 0.5) * per;
      const double past = std::fmod(mid - from + 4 * kPi, 2 * kPi);
      EXPECT_LE(past, extent + 2 * per) << w.code << " segment " << k;
    }
  }
  EXPECT_GE(perimeter, 4);
}

}  // namespace
}  // namespace rockface::tunnel

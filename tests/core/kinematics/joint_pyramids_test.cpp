#include "core/kinematics/joint_pyramids.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/common/units.h"
#include "core/geometry/orientation.h"

namespace rockface::kinematics {
namespace {

using geometry::HalfSpace;

JointSpec joint(double dip, double dipdir, std::optional<double> phi_deg = std::nullopt) {
  JointSpec j{geometry::plane_normal_deg(dip, dipdir), std::nullopt};
  if (phi_deg) j.friction = deg_to_rad(*phi_deg);
  return j;
}
FreeFaceSpec face(double dip, double dipdir, HalfSpace rock) {
  return {geometry::plane_normal_deg(dip, dipdir), rock};
}

std::vector<std::string> removable_codes(const std::vector<PyramidVerdict>& vs) {
  std::vector<std::string> codes;
  for (const auto& v : vs)
    if (v.removable.value) codes.push_back(v.code_text);
  return codes;
}

TEST(JointPyramids, PublishedPyramid000IsOpenWithItsEdges) {
  const std::vector<JointSpec> js{joint(10, 110), joint(85, 70), joint(90, 180)};
  const geometry::Cone jp =
      joint_pyramid(js, {HalfSpace::Upper, HalfSpace::Upper, HalfSpace::Upper});
  EXPECT_GT(jp.margin().angle, 0);
  EXPECT_EQ(jp.edges().size(), 3u);
}

TEST(JointPyramids, RoofKeyblockOfThreeSymmetricJoints) {
  // Three joints dipping 60 towards 0, 120 and 240 above a horizontal roof
  // (rock on the upper side). Their lines of intersection plunge 40.9 degrees,
  // so only the pyramid below all three (111) lies wholly in the space below
  // the roof: the one removable block, and gravity makes it fall.
  const std::vector<JointSpec> js{joint(60, 0, 30), joint(60, 120, 30), joint(60, 240, 30)};
  const geometry::Cone ep = excavation_pyramid({face(0, 0, HalfSpace::Upper)});
  PyramidOptions opt;
  opt.uncertainty = deg_to_rad(1);
  opt.resultant = Eigen::Vector3d(0, 0, -9.81);
  const auto vs = analyse_joint_pyramids(js, ep, opt);
  ASSERT_EQ(vs.size(), 8u);
  EXPECT_EQ(removable_codes(vs), std::vector<std::string>{"111"});
  const PyramidVerdict& key = vs[7];
  EXPECT_EQ(key.code_text, "111");
  EXPECT_GT(key.removable.margin, 0);
  EXPECT_FALSE(key.removable.marginal);
  // The verdict's margin is the weaker of its two conditions, exactly.
  EXPECT_EQ(key.removable.margin, std::min(key.jp_margin, -key.jp_ep_margin));
  ASSERT_TRUE(key.mode);
  EXPECT_EQ(key.mode->type, ModeType::Falling);
  // Opposite pyramid 000 points up: infinite, and JP itself open.
  EXPECT_FALSE(vs[0].finite);
  EXPECT_FALSE(vs[0].empty);
}

TEST(JointPyramids, FloorBlockIsRemovableButStable) {
  // Same joints, a horizontal floor (rock below): 000 is removable but gravity
  // pushes it into the rock.
  const std::vector<JointSpec> js{joint(60, 0, 30), joint(60, 120, 30), joint(60, 240, 30)};
  PyramidOptions opt;
  opt.resultant = Eigen::Vector3d(0, 0, -9.81);
  const auto vs =
      analyse_joint_pyramids(js, excavation_pyramid({face(0, 0, HalfSpace::Lower)}), opt);
  EXPECT_EQ(removable_codes(vs), std::vector<std::string>{"000"});
  ASSERT_TRUE(vs[0].mode);
  EXPECT_EQ(vs[0].mode->type, ModeType::None);
  EXPECT_TRUE(std::isinf(*vs[0].mode->fos));
}

TEST(JointPyramids, SymmetricWedgeInACutSlidesOnBothJoints) {
  // A wedge on joints 60/135 and 60/225 in a cut face 75/180 with a flat top
  // (one excavation pyramid of two faces). The block sits on both joints
  // (code 00) and slides down their intersection with the wedge factor:
  // FoS = tan(phi) / (tan(psi_i) sin(xi / 2)).
  const std::vector<JointSpec> js{joint(60, 135, 30), joint(60, 225, 30)};
  const geometry::Cone ep =
      excavation_pyramid({face(75, 180, HalfSpace::Lower), face(0, 0, HalfSpace::Lower)});
  PyramidOptions opt;
  opt.resultant = Eigen::Vector3d(0, 0, -9.81);
  const auto vs = analyse_joint_pyramids(js, ep, opt);
  EXPECT_EQ(removable_codes(vs), std::vector<std::string>{"00"});
  const auto& mode = *vs[0].mode;
  ASSERT_EQ(mode.type, ModeType::Sliding);
  ASSERT_EQ(mode.planes, (std::vector<int>{0, 1}));
  const Eigen::Vector3d line = js[0].normal.cross(js[1].normal).normalized();
  const double psi_i = std::asin(std::abs(line.z()));
  const double xi = std::numbers::pi - std::acos(js[0].normal.dot(js[1].normal));
  // Closed form in double precision: 1e-12.
  EXPECT_NEAR(*mode.fos, std::tan(deg_to_rad(30)) / (std::tan(psi_i) * std::sin(xi / 2)), 1e-12);
}

TEST(JointPyramids, PlaneFailureWithoutLateralReleaseIsMarginalNotRemovable) {
  // A joint 35/180 daylighting in a cut 70/180 with a flat top, and a release
  // joint 90/90 on one side only: joint, cut and top all strike East-West, so
  // the pyramids on the release's west side (x <= 0) touch the excavation
  // pyramid along the strike line -x: JP cap EP is a ray, margin zero. The
  // block could run off along the strike forever; block theory says
  // "marginal", whichever way rounding falls.
  const std::vector<JointSpec> js{joint(35, 180, 30), joint(90, 90, 30)};
  const geometry::Cone ep =
      excavation_pyramid({face(70, 180, HalfSpace::Lower), face(0, 0, HalfSpace::Lower)});
  PyramidOptions opt;
  opt.uncertainty = deg_to_rad(1);
  opt.resultant = Eigen::Vector3d(0, 0, -1);
  const auto vs = analyse_joint_pyramids(js, ep, opt);
  const auto it =
      std::find_if(vs.begin(), vs.end(), [](const auto& v) { return v.code_text == "01"; });
  ASSERT_NE(it, vs.end());
  EXPECT_TRUE(it->removable.marginal);
  // The deciding cone is a ray: its margin is zero to rounding (1e-15 rad).
  EXPECT_NEAR(it->jp_ep_margin, 0, 1e-15);
}

}  // namespace
}  // namespace rockface::kinematics

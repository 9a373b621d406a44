// Geometry that breaks naive block theory: parallel and nearly parallel
// joints, horizontal and vertical planes, dip direction 0 = 360, resultants on
// mode boundaries, reordered joints, the whole scene turned about the
// vertical. Each case asserts the same verdict or an honest "marginal".
#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/joint_pyramids.h"

namespace rockface::kinematics {
namespace {

using geometry::HalfSpace;

struct Orient {
  double dip, dipdir;  // degrees
};

std::vector<JointSpec> joints_of(const std::vector<Orient>& os, double turn_deg = 0) {
  std::vector<JointSpec> js;
  for (const auto& o : os)
    js.push_back({geometry::plane_normal_deg(o.dip, o.dipdir + turn_deg), deg_to_rad(30)});
  return js;
}

geometry::Cone ep_of(const std::vector<Orient>& faces, HalfSpace rock, double turn_deg = 0) {
  std::vector<FreeFaceSpec> fs;
  for (const auto& f : faces)
    fs.push_back({geometry::plane_normal_deg(f.dip, f.dipdir + turn_deg), rock});
  return excavation_pyramid(fs);
}

PyramidOptions gravity(double uncertainty_deg = 1) {
  PyramidOptions o;
  o.uncertainty = deg_to_rad(uncertainty_deg);
  o.resultant = Eigen::Vector3d(0, 0, -9.81);
  return o;
}

// The verdict as a comparable string: removable or not, or marginal.
std::string verdict(const PyramidVerdict& v) {
  if (v.removable.marginal) return "marginal";
  return v.removable.value ? "removable" : "keyed";
}

TEST(PyramidHardCases, NearlyParallelJointsGiveTheSameVerdictsOrMarginal) {
  // Two joints 40/120 and 40/120 tilted by eps, a third 70/250, in a roof.
  // Codes that separate the near-parallel pair (01x, 10x) have a sliver of a
  // pyramid: marginal. The others agree with the exactly parallel case.
  const geometry::Cone roof = ep_of({{0, 0}}, HalfSpace::Upper);
  std::map<std::string, std::string> reference;
  for (double eps : {0.0, 1e-9, 1e-7, 1e-5}) {
    auto js = joints_of({{40, 120}, {40, 120}, {70, 250}});
    js[1].normal = geometry::plane_normal({deg_to_rad(40) + eps, deg_to_rad(120)});
    for (const auto& v : analyse_joint_pyramids(js, roof, gravity())) {
      const std::string& c = v.code_text;
      if (c[0] != c[1]) {
        EXPECT_TRUE(v.removable.marginal || !v.removable.value) << c << " eps " << eps;
        EXPECT_LE(v.jp_margin, std::max(eps, 1e-12)) << c << " eps " << eps;
        continue;
      }
      if (eps == 0)
        reference[c] = verdict(v);
      else
        EXPECT_EQ(verdict(v), reference[c]) << c << " eps " << eps;
    }
  }
  EXPECT_EQ(reference.size(), 4u);
}

TEST(PyramidHardCases, HorizontalAndVerticalJoints) {
  // A horizontal joint and two vertical ones (0/0, 90/0, 90/90) under a
  // horizontal roof: the pyramid below the horizontal joint has edges in the
  // roof's plane, so removability is marginal, never a confident yes or no.
  const auto js = joints_of({{0, 0}, {90, 0}, {90, 90}});
  const auto vs = analyse_joint_pyramids(js, ep_of({{0, 0}}, HalfSpace::Upper), gravity());
  for (const auto& v : vs) {
    if (v.code_text[0] == '1') {
      EXPECT_TRUE(v.removable.marginal) << v.code_text;
    } else {
      // Above the horizontal joint the pyramid is an octant wholly in the
      // rock: JP cap EP = JP, open by the octant's margin asin(1/sqrt 3).
      EXPECT_FALSE(v.removable.value) << v.code_text;
      EXPECT_FALSE(v.removable.marginal) << v.code_text;
      EXPECT_NEAR(v.removable.margin, std::asin(1 / std::sqrt(3.0)), 1e-12) << v.code_text;
    }
  }
  // Gravity along the vertical edge of 111 (the two vertical joints meet in
  // a vertical line): falling, flagged as on a mode boundary.
  const auto& v111 = vs[7];
  ASSERT_EQ(v111.code_text, "111");
  if (v111.mode) {
    EXPECT_EQ(v111.mode->type, ModeType::Falling);
    EXPECT_TRUE(v111.mode->marginal);
    EXPECT_EQ(*v111.mode->fos, 0.0);
  }
}

TEST(PyramidHardCases, DipDirection360IsZero) {
  const auto a = analyse_joint_pyramids(joints_of({{50, 0}, {60, 120}, {70, 240}}),
                                        ep_of({{0, 0}}, HalfSpace::Upper), gravity());
  const auto b = analyse_joint_pyramids(joints_of({{50, 360}, {60, 120}, {70, 240}}),
                                        ep_of({{0, 360}}, HalfSpace::Upper), gravity());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(verdict(a[i]), verdict(b[i]));
    // sin/cos of 2 pi differ from those of 0 by ~2.4e-16.
    EXPECT_NEAR(a[i].removable.margin, b[i].removable.margin, 1e-13);
  }
}

TEST(PyramidHardCases, ResultantExactlyInAJointPlane) {
  // A vertical joint 90/90 and a gentle one 20/270 in a cut (rock below):
  // gravity lies in the vertical joint's plane, and the joints meet in a
  // horizontal line. Tilting gravity off the plane either way must not change
  // the mode or make the factor of safety jump.
  const auto js = joints_of({{90, 90}, {20, 270}});
  const auto vs =
      analyse_joint_pyramids(js, ep_of({{60, 270}, {0, 0}}, HalfSpace::Lower), gravity());
  bool seen = false;
  for (const auto& v : vs) {
    if (!v.mode) continue;
    seen = true;
    // Tilting gravity by +-1e-9 rad about North moves it off the plane each way.
    for (double tilt : {-1e-9, 1e-9}) {
      PyramidOptions o = gravity();
      o.resultant = Eigen::Vector3d(9.81 * std::sin(tilt), 0, -9.81 * std::cos(tilt));
      const auto w =
          analyse_joint_pyramid(js, v.code, ep_of({{60, 270}, {0, 0}}, HalfSpace::Lower), o);
      ASSERT_TRUE(w.mode);
      EXPECT_EQ(w.mode->type, v.mode->type) << v.code_text;
      ASSERT_EQ(w.mode->fos.has_value(), v.mode->fos.has_value());
      if (v.mode->fos && std::isfinite(*v.mode->fos)) {
        // FoS varies with the tilt at rate ~ tan(phi)/sin^2(psi): 1e-9 rad
        // moves it by ~1e-8.
        EXPECT_NEAR(*w.mode->fos, *v.mode->fos, 1e-7) << v.code_text;
      }
    }
  }
  EXPECT_TRUE(seen);
}

TEST(PyramidHardCases, ReorderedJointsGiveTheSameVerdicts) {
  const std::vector<Orient> os{{35, 110}, {75, 200}, {60, 330}, {15, 20}};
  const geometry::Cone ep = ep_of({{70, 160}, {0, 0}}, HalfSpace::Lower);
  const auto base = analyse_joint_pyramids(joints_of(os), ep, gravity());
  std::vector<int> perm{0, 1, 2, 3};
  std::mt19937 rng(5);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(perm.begin(), perm.end(), rng);
    std::vector<Orient> shuffled;
    for (int p : perm) shuffled.push_back(os[p]);
    const auto vs = analyse_joint_pyramids(joints_of(shuffled), ep, gravity());
    for (const auto& v : vs) {
      std::string original(4, ' ');
      for (int k = 0; k < 4; ++k) original[perm[k]] = v.code_text[k];
      const auto& b = *std::find_if(base.begin(), base.end(),
                                    [&](const auto& x) { return x.code_text == original; });
      EXPECT_EQ(verdict(v), verdict(b)) << original;
      // The same half-spaces in another order: the margin optimum is the
      // same candidate, equal to rounding.
      EXPECT_NEAR(v.removable.margin, b.removable.margin, 1e-12) << original;
      ASSERT_EQ(v.mode.has_value(), b.mode.has_value());
      if (v.mode && v.mode->fos && std::isfinite(*v.mode->fos)) {
        EXPECT_NEAR(*v.mode->fos, *b.mode->fos, 1e-12);
      }
    }
  }
}

TEST(PyramidHardCases, SceneTurnedAboutTheVerticalKeepsItsVerdicts) {
  const std::vector<Orient> os{{35, 110}, {75, 200}, {60, 330}};
  const auto base = analyse_joint_pyramids(joints_of(os),
                                           ep_of({{70, 160}, {0, 0}}, HalfSpace::Lower), gravity());
  for (double turn : {17.0, 90.0, 203.5, 359.999999}) {
    const auto vs = analyse_joint_pyramids(
        joints_of(os, turn), ep_of({{70, 160}, {0, 0}}, HalfSpace::Lower, turn), gravity());
    for (size_t i = 0; i < vs.size(); ++i) {
      EXPECT_EQ(vs[i].code_text, base[i].code_text);
      EXPECT_EQ(verdict(vs[i]), verdict(base[i])) << base[i].code_text << " turned " << turn;
      // Rotating the normals costs ~1e-16 per component: margins agree to 1e-12.
      EXPECT_NEAR(vs[i].removable.margin, base[i].removable.margin, 1e-12);
      if (vs[i].mode && vs[i].mode->fos && std::isfinite(*vs[i].mode->fos)) {
        // FoS is a ratio of sums of such products: 1e-9 leaves room for the
        // amplification near small driving forces.
        EXPECT_NEAR(*vs[i].mode->fos, *base[i].mode->fos, 1e-9);
      }
    }
  }
}

}  // namespace
}  // namespace rockface::kinematics

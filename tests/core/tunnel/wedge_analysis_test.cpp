// Wedges around an excavation: closed-form tetrahedra in a square section,
// the circle's and the horseshoe's roof wedge against bounds and each
// other, rigid-motion invariance, sets along the axis, and support.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/error.h"
#include "core/geometry/orientation.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::tunnel {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRad = kPi / 180.0;

std::vector<WedgeJointSet> symmetric_sets(double dip_deg, double turn_deg = 0,
                                          double friction_deg = 30) {
  std::vector<WedgeJointSet> s;
  for (int i = 0; i < 3; ++i)
    s.push_back({"J" + std::to_string(i + 1),
                 geometry::plane_normal_deg(dip_deg, std::fmod(120.0 * i + turn_deg, 360.0)),
                 friction_deg * kRad, 0});
  return s;
}

const Wedge* find(const WedgeAnalysis& a, const std::string& code) {
  for (const auto& w : a.wedges)
    if (w.code == code) return &w;
  return nullptr;
}

TunnelFrame north_axis(double turn_deg = 0) {
  return axis_frame(turn_deg * kRad, 0, Eigen::Vector3d::Zero(), "axis");
}

// The three planes dip at alpha toward 0, 120 and 240 degrees: below all
// three (code 111) the block is a regular-based tetrahedron with its apex
// up. Its base on a horizontal roof is an equilateral triangle of inradius
// r = h / tan(alpha) (h: apex height), corners toward 60, 180, 300 degrees,
// so across a north-running tunnel it is 2 sqrt(3) r wide: the largest
// wedge spans the roof, r = B / (2 sqrt 3), volume sqrt(3) r^3 tan(alpha).
struct SquareCase {
  double B = 6, alpha = 60 * kRad, density = 2700, g = 9.81;
  double r() const { return B / (2 * std::sqrt(3.0)); }
  double h() const { return r() * std::tan(alpha); }
  double volume() const { return std::sqrt(3.0) * std::pow(r(), 3) * std::tan(alpha); }
  double weight() const { return volume() * density * g; }
};

// Rounding only: the wedge is built from planes through one apex and its
// volume summed over tetrahedra, ~1e-15 relative per operation.
constexpr double kExactRel = 1e-9;

TEST(WedgeAnalysis, SquareRoofWedgeIsTheClosedFormTetrahedron) {
  const SquareCase c;
  const WedgeAnalysis a = analyse_wedges(rectangle_profile(c.B, c.B, 0), north_axis(),
                                         Eigen::Vector3d::Zero(), symmetric_sets(60), {});
  const Wedge* w = find(a, "111");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->place, WedgePlace::roof);
  EXPECT_NEAR(w->mass.volume, c.volume(), kExactRel * c.volume());
  EXPECT_NEAR(w->apex_height, c.h(), kExactRel * c.h());
  EXPECT_NEAR(w->bolt_length_to_apex, c.h(), kExactRel * c.h());
  EXPECT_NEAR(w->apex.z(), c.B + c.h(), kExactRel * c.h());
  EXPECT_NEAR(w->apex.x(), 0, kExactRel * c.B);
  EXPECT_NEAR(w->weight, c.weight(), kExactRel * c.weight());
  // The base: an equilateral triangle of side 2 sqrt(3) r on the roof.
  const double side = 2 * std::sqrt(3.0) * c.r();
  EXPECT_NEAR(w->face_area, std::sqrt(3.0) / 4 * side * side, kExactRel * side * side);
  EXPECT_NEAR(w->face_perimeter, 3 * side, kExactRel * side);
  EXPECT_NEAR(w->weight_pressure, c.weight() / (std::sqrt(3.0) / 4 * side * side),
              kExactRel * c.weight());
  for (const auto& [id, len] : w->trace_lengths) EXPECT_NEAR(len, side, kExactRel * side) << id;
  ASSERT_TRUE(w->mode);
  EXPECT_EQ(w->mode->type, kinematics::ModeType::Falling);
  ASSERT_TRUE(w->fos);
  EXPECT_EQ(*w->fos, 0.0);
  EXPECT_TRUE(w->removable.value);
  EXPECT_GT(w->removable.margin, 0);
  EXPECT_TRUE(w->corners.empty());
  EXPECT_EQ(a.effects_simulated, std::vector<std::string>{"gravity"});
  EXPECT_EQ(w->effects_used, std::vector<std::string>{"gravity"});
  EXPECT_FALSE(w->fos_supported);  // no support asked: none computed
  EXPECT_TRUE(w->bolts.empty());
}

TEST(WedgeAnalysis, TraceLengthLimitScalesTheWedgeDown) {
  const SquareCase c;
  WedgeOptions o;
  const double side = 2 * std::sqrt(3.0) * c.r();
  o.trace_length_limit = 0.5 * side;
  const WedgeAnalysis a = analyse_wedges(rectangle_profile(c.B, c.B, 0), north_axis(),
                                         Eigen::Vector3d::Zero(), symmetric_sets(60), o);
  const Wedge* w = find(a, "111");
  ASSERT_NE(w, nullptr);
  EXPECT_TRUE(w->scaled);
  // On a flat roof the scaled wedge is the same tetrahedron at half size:
  // an eighth of the volume. Bisection stops at kWedgeTraceRel (1e-6) of
  // the limit, three times that in volume.
  EXPECT_NEAR(w->scale, 0.5, 1e-5);
  EXPECT_NEAR(w->mass.volume, c.volume() / 8, 1e-5 * c.volume());
  for (const auto& [id, len] : w->trace_lengths) EXPECT_LE(len, *o.trace_length_limit * (1 + 1e-9));
}

TEST(WedgeAnalysis, PatternBoltsAndShotcreteRaiseTheFallingWedgesFosByTheirCapacity) {
  const SquareCase c;
  WedgeOptions o;
  PatternBolts b;
  b.length = c.h() + 0.5;  // every bolt reaches past the apex height
  b.spacing = 0.7;
  b.capacity = 1e5;
  o.bolts = b;
  Shotcrete s;
  s.thickness = 0.05;
  s.shear_strength = 1e6;
  o.shotcrete = s;
  const WedgeAnalysis a = analyse_wedges(rectangle_profile(c.B, c.B, 0), north_axis(),
                                         Eigen::Vector3d::Zero(), symmetric_sets(60), o);
  EXPECT_EQ(a.effects_simulated, (std::vector<std::string>{"gravity", "bolts", "shotcrete"}));
  const Wedge* w = find(a, "111");
  ASSERT_NE(w, nullptr);
  // The pattern: bolts at (u, w) = (i, j) x 0.7 m from the crown, vertical
  // on the roof; the base triangle (apex above u = w = 0) holds those with
  // y <= r, 0.866 x - 0.5 y <= r and -0.866 x - 0.5 y <= r.
  int inside = 0;
  const double r = c.r();
  for (int i = -10; i <= 10; ++i)
    for (int j = -10; j <= 10; ++j) {
      const double x = i * 0.7, y = j * 0.7;
      const double m = std::min(
          {r - y, r - (std::sqrt(3.0) / 2 * x - 0.5 * y), r - (-std::sqrt(3.0) / 2 * x - 0.5 * y)});
      ASSERT_GT(std::abs(m), 1e-6) << "a pattern point on the base's edge: choose another spacing";
      if (m > 0) ++inside;
    }
  ASSERT_GT(inside, 3);
  EXPECT_EQ(w->bolts_anchored, inside);
  EXPECT_EQ(static_cast<int>(w->bolts.size()), inside);
  const double side = 2 * std::sqrt(3.0) * r;
  const double shotcrete = s.thickness * s.shear_strength * 3 * side;
  EXPECT_NEAR(w->shotcrete_force, shotcrete, kExactRel * shotcrete);
  ASSERT_TRUE(w->fos_supported);
  // Falling: FoS = (n T + tau t perimeter) / W.
  const double expected = (inside * b.capacity + shotcrete) / c.weight();
  EXPECT_NEAR(*w->fos_supported, expected, kExactRel * expected);
  EXPECT_EQ(*w->fos, 0.0);
  EXPECT_NEAR(w->support_pressure,
              (inside * b.capacity + shotcrete) / (std::sqrt(3.0) / 4 * side * side),
              kExactRel * expected * c.weight());
  EXPECT_EQ(w->effects_used, (std::vector<std::string>{"gravity", "bolts", "shotcrete"}));
}

TEST(WedgeAnalysis, BoltsThatEndInsideTheWedgeHoldNothing) {
  const SquareCase c;
  WedgeOptions o;
  PatternBolts b;
  b.length = 0.3 * c.h();  // shorter than the wedge is deep near its middle
  b.spacing = 0.7;
  b.capacity = 1e5;
  o.bolts = b;
  const WedgeAnalysis a = analyse_wedges(rectangle_profile(c.B, c.B, 0), north_axis(),
                                         Eigen::Vector3d::Zero(), symmetric_sets(60), o);
  const Wedge* w = find(a, "111");
  ASSERT_NE(w, nullptr);
  int anchored = 0;
  for (const auto& bolt : w->bolts) {
    // Depth in the wedge at a head (x, y) on the roof: the planes rise at
    // tan(alpha) from the base's edges, so the depth is tan(alpha) times the
    // distance to the nearest edge.
    const double x = bolt.head.x(), y = bolt.head.y();
    const double m = std::min({c.r() - y, c.r() - (std::sqrt(3.0) / 2 * x - 0.5 * y),
                               c.r() - (-std::sqrt(3.0) / 2 * x - 0.5 * y)});
    EXPECT_NEAR(bolt.depth_in_wedge, m * std::tan(c.alpha), 1e-9);
    if (b.length > m * std::tan(c.alpha)) ++anchored;
  }
  EXPECT_EQ(w->bolts_anchored, anchored);
  EXPECT_LT(w->bolts_anchored, static_cast<int>(w->bolts.size()));
  ASSERT_TRUE(w->fos_supported);
  EXPECT_NEAR(*w->fos_supported, anchored * b.capacity / c.weight(), 1e-9);
}

TEST(WedgeAnalysis, SlidingWedgeGainsTheClosedFormFosFromBolts) {
  // Dip 40: the symmetric roof wedge still falls (down lies inside the
  // pyramid). Tilting one set makes it slide: take the wedge on J1's face.
  // Rather than a special geometry, check the formula on the computed
  // wedge: with bolts of force T along the normal n_b (into the rock), on
  // one plane of block-side normal n and direction s,
  //   FoS = (N tan(phi) - S . s) / (W . s),  N = -(W + S) . n.
  std::vector<WedgeJointSet> sets{{"J1", geometry::plane_normal_deg(35, 10), 30 * kRad, 0},
                                  {"J2", geometry::plane_normal_deg(80, 130), 30 * kRad, 0},
                                  {"J3", geometry::plane_normal_deg(70, 250), 30 * kRad, 0}};
  WedgeOptions o;
  PatternBolts b;
  b.length = 20;
  b.spacing = 0.5;
  b.capacity = 5e4;
  o.bolts = b;
  const WedgeAnalysis a =
      analyse_wedges(rectangle_profile(6, 6, 0), north_axis(), Eigen::Vector3d::Zero(), sets, o);
  int sliding = 0;
  for (const auto& w : a.wedges) {
    if (!w.mode || w.mode->type != kinematics::ModeType::Sliding || w.mode->planes.size() != 1 ||
        w.bolts_anchored == 0)
      continue;
    ++sliding;
    const Eigen::Vector3d W = w.mass.mass * Eigen::Vector3d(0, 0, -9.81);
    Eigen::Vector3d S = Eigen::Vector3d::Zero();
    for (const auto& bolt : w.bolts) S += bolt.force * bolt.direction;
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (const auto& p : w.block.planes())
      if (p.index == w.mode->planes[0]) n = p.inward_normal();
    const Eigen::Vector3d s = w.mode->direction;
    const double N = -(W + S).dot(n);
    ASSERT_GT(N, 0);
    const double expected = (N * std::tan(30 * kRad) - S.dot(s)) / W.dot(s);
    ASSERT_TRUE(w.fos_supported);
    // Rounding of the sums over bolts and faces.
    EXPECT_NEAR(*w.fos_supported, expected, 1e-9 * std::max(1.0, expected)) << w.id;
    EXPECT_GT(*w.fos_supported, *w.fos) << w.id;
    // Without bolts: sliding_mode's own factor of safety.
    const double dry = -W.dot(n) * std::tan(30 * kRad) / W.dot(s);
    EXPECT_NEAR(*w.fos, dry, 1e-9 * std::max(1.0, dry)) << w.id;
  }
  EXPECT_GT(sliding, 0);
}

TEST(WedgeAnalysis, TheSameWedgeTurnedWithTheAxisAndTheSets) {
  const WedgeAnalysis a = analyse_wedges(rectangle_profile(6, 5, -1), north_axis(),
                                         Eigen::Vector3d::Zero(), symmetric_sets(55, 10), {});
  for (double turn : {37.0, 151.0, 290.0}) {
    const WedgeAnalysis b =
        analyse_wedges(rectangle_profile(6, 5, -1), north_axis(turn), Eigen::Vector3d::Zero(),
                       symmetric_sets(55, 10 + turn), {});
    ASSERT_EQ(a.wedges.size(), b.wedges.size()) << turn;
    for (std::size_t i = 0; i < a.wedges.size(); ++i) {
      const Wedge& x = a.wedges[i];
      const Wedge* y = find(b, x.code);
      ASSERT_NE(y, nullptr) << x.code;
      // Rounding of the rotated normals (~1e-15) through the construction.
      EXPECT_NEAR(y->mass.volume, x.mass.volume, 1e-9 * x.mass.volume) << x.code;
      EXPECT_NEAR(y->apex_height, x.apex_height, 1e-9 * x.apex_height) << x.code;
      EXPECT_EQ(y->place, x.place) << x.code;
      ASSERT_EQ(x.fos.has_value(), y->fos.has_value());
      if (x.fos && std::isfinite(*x.fos)) {
        EXPECT_NEAR(*y->fos, *x.fos, 1e-9) << x.code;
      }
    }
  }
}

TEST(WedgeAnalysis, TheSameWedgeMovedToSurveyCoordinates) {
  const WedgeAnalysis a = analyse_wedges(rectangle_profile(6, 5, -1), north_axis(),
                                         Eigen::Vector3d::Zero(), symmetric_sets(55, 10), {});
  // A section 300 m from the datum, the datum at survey coordinates of 10^6 m.
  const Eigen::Vector3d datum(2.6e6, 1.2e6, 450), origin(120, -250, 31);
  const WedgeAnalysis b =
      analyse_wedges(rectangle_profile(6, 5, -1), axis_frame(0, 0, origin, "axis"), datum,
                     symmetric_sets(55, 10), {});
  ASSERT_EQ(a.wedges.size(), b.wedges.size());
  for (std::size_t i = 0; i < a.wedges.size(); ++i) {
    const Wedge& x = a.wedges[i];
    const Wedge& y = b.wedges[i];
    EXPECT_EQ(x.code, y.code);
    // Datum-relative coordinates of a few hundred metres: rounding ~1e-13.
    EXPECT_NEAR(y.mass.volume, x.mass.volume, 1e-9 * x.mass.volume) << x.code;
    EXPECT_LT((y.apex - (x.apex + datum + origin)).norm(), 1e-6) << x.code;
  }
}

TEST(WedgeAnalysis, CircleRoofWedgeLiesBetweenItsClosedFormBounds) {
  // Symmetric sets: seen along the axis the pyramid's sector is symmetric
  // about the vertical with half-angle theta, tan(theta) = sqrt(3) / tan(alpha);
  // its edges touch the circle, so the apex is R / sin(theta) above the centre.
  const double R = 3, alpha = 60 * kRad;
  const double theta = std::atan(std::sqrt(3.0) / std::tan(alpha));
  WedgeOptions fine;
  fine.sagitta_m = 1e-5;
  const WedgeAnalysis a = analyse_wedges(circle_profile(R, 0), north_axis(),
                                         Eigen::Vector3d::Zero(), symmetric_sets(60), fine);
  const Wedge* w = find(a, "111");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->place, WedgePlace::roof);
  // The chords lie inside the circle by at most the sagitta; the apex
  // moves with them by sagitta / sin(theta).
  const double apex = R / std::sin(theta);
  EXPECT_NEAR(w->apex.z(), apex, fine.sagitta_m / std::sin(theta) * 1.01);
  EXPECT_NEAR(w->bolt_length_to_apex, apex - R, 2 * fine.sagitta_m / std::sin(theta));
  // Bounds: the tetrahedron of the pyramid down to the plane of the
  // crown (inside the wedge) and down to the chord through the tangent
  // points (containing it).
  auto tet = [&](double h) {
    const double r = h / std::tan(alpha);
    return std::sqrt(3.0) * r * r * r * std::tan(alpha);
  };
  const double lower = tet(apex - R), upper = tet(apex - R * std::sin(theta));
  EXPECT_GT(w->mass.volume, lower);
  EXPECT_LT(w->mass.volume, upper);
  // A coarser drawing of the arc gives the same wedge to its sagitta.
  WedgeOptions coarse;
  coarse.sagitta_m = 1e-3;
  const WedgeAnalysis b = analyse_wedges(circle_profile(R, 0), north_axis(),
                                         Eigen::Vector3d::Zero(), symmetric_sets(60), coarse);
  const Wedge* v = find(b, "111");
  ASSERT_NE(v, nullptr);
  // The volume changes by about the base area times the sagitta.
  EXPECT_NEAR(v->mass.volume, w->mass.volume, w->face_area * coarse.sagitta_m * 2);
}

TEST(WedgeAnalysis, HorseshoeRoofWedgeIsTheCrownCirclesAndCornersAreNamed) {
  const double R = 3;
  WedgeOptions o;
  o.sagitta_m = 1e-4;
  const WedgeAnalysis circle = analyse_wedges(circle_profile(R, 0), north_axis(),
                                              Eigen::Vector3d::Zero(), symmetric_sets(75), o);
  const WedgeAnalysis shoe = analyse_wedges(horseshoe_profile(R, 0, 5, -2.5), north_axis(),
                                            Eigen::Vector3d::Zero(), symmetric_sets(75), o);
  const Wedge* a = find(circle, "111");
  const Wedge* b = find(shoe, "111");
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  // The roof wedge touches the crown above the springline: it is the
  // circle's, to the two drawings' sagitta times the face area.
  EXPECT_NEAR(b->mass.volume, a->mass.volume, 2 * o.sagitta_m * a->face_area);
  bool corner = false;
  for (const auto& w : shoe.wedges) {
    EXPECT_TRUE(std::isfinite(w.mass.volume));
    if (!w.corners.empty()) {
      corner = true;
      EXPECT_NE(w.corners.front().find("segment"), std::string::npos);
      EXPECT_GE(w.segments.size(), 2u);
    }
  }
  // Steep sets: seen along the axis the floor wedge's pyramid is narrower
  // (25 deg from the vertical) than the walls are steep where they meet the
  // invert (30 deg), so its edges touch the walls above the corners.
  EXPECT_TRUE(corner) << "the floor wedge spans the wall-to-invert corners";
}

TEST(WedgeAnalysis, TwoSetsAlongTheAxisFormNoWedgeAndSaySo) {
  // J1 and J2 strike along the (north) axis: they meet in a line parallel
  // to it, so every pyramid of the three has an edge along the tunnel.
  std::vector<WedgeJointSet> sets{{"J1", geometry::plane_normal_deg(60, 90), 30 * kRad, 0},
                                  {"J2", geometry::plane_normal_deg(60, 270), 30 * kRad, 0},
                                  {"J3", geometry::plane_normal_deg(45, 0), 30 * kRad, 0}};
  const WedgeAnalysis a =
      analyse_wedges(rectangle_profile(6, 6, 0), north_axis(), Eigen::Vector3d::Zero(), sets, {});
  EXPECT_TRUE(a.wedges.empty());
  ASSERT_FALSE(a.none.empty());
  for (const auto& n : a.none) {
    EXPECT_TRUE(std::isfinite(n.margin));
    EXPECT_LE(n.margin, 0);
    EXPECT_NE(n.reason.find("without end"), std::string::npos) << n.reason;
  }
  ASSERT_FALSE(a.notes.empty());
  EXPECT_NE(a.notes.back().find("no removable wedge"), std::string::npos);
}

TEST(WedgeAnalysis, OneSetAlongTheAxisLeavesOnlyFiniteWedges) {
  std::vector<WedgeJointSet> sets{{"J1", geometry::plane_normal_deg(70, 90), 30 * kRad, 0},
                                  {"J2", geometry::plane_normal_deg(50, 200), 30 * kRad, 0},
                                  {"J3", geometry::plane_normal_deg(45, 330), 30 * kRad, 0}};
  const WedgeAnalysis a =
      analyse_wedges(rectangle_profile(6, 6, 0), north_axis(), Eigen::Vector3d::Zero(), sets, {});
  bool along = false;
  for (const auto& n : a.none)
    if (n.reason.find("without end") != std::string::npos) along = true;
  EXPECT_TRUE(along) << "the pyramids with J1's face across the axis run along the tunnel";
  for (const auto& w : a.wedges) {
    EXPECT_TRUE(std::isfinite(w.mass.volume) && w.mass.volume > 0) << w.code;
    EXPECT_TRUE(std::isfinite(w.apex_height)) << w.code;
  }
}

TEST(WedgeAnalysis, FaceWedgeFitsInsideTheSection) {
  const WedgeAnalysis a = analyse_wedges(rectangle_profile(6, 6, 0), north_axis(),
                                         Eigen::Vector3d::Zero(), symmetric_sets(60, 0), {});
  for (const auto& w : a.wedges) {
    if (w.place != WedgePlace::face) continue;
    for (const auto& v : w.block.vertices()) {
      // Every corner of the wedge is at or ahead of the face, and its face
      // triangle inside the 6 x 6 section (to rounding).
      EXPECT_GE(v.y(), -1e-9);
      if (std::abs(v.y()) < 1e-9) {
        EXPECT_LE(std::abs(v.x()), 3 + 1e-9);
        EXPECT_GE(v.z(), -1e-9);
        EXPECT_LE(v.z(), 6 + 1e-9);
      }
    }
    EXPECT_NEAR(w.apex_height, w.apex.y(), 1e-9);
  }
}

TEST(WedgeAnalysis, BadInputIsRefusedByName) {
  auto sets = symmetric_sets(60);
  sets.pop_back();
  try {
    analyse_wedges(rectangle_profile(6, 6, 0), north_axis(), Eigen::Vector3d::Zero(), sets, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sets"), std::string::npos);
  }
  DesignProfile flat({ProfileSegment::line({0, 0}, {1, 0}), ProfileSegment::line({1, 0}, {0, 0})});
  EXPECT_THROW(analyse_wedges(flat, north_axis(), Eigen::Vector3d::Zero(), symmetric_sets(60), {}),
               InputError);
  EXPECT_THROW(axis_frame(0, kPi / 2, Eigen::Vector3d::Zero(), "axis"), InputError);
}

}  // namespace
}  // namespace rockface::tunnel

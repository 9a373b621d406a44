// Over- and underbreak against closed forms. The meshes are tubes about the
// alignment, faceted with one vertex every 0.5 degrees; the rays are set one
// per facet, through the facet's middle, so every ray meets a facet at
// distance R cos(0.25 deg) (the chord's middle) instead of R: the tests
// compare with that exact faceted value (to rounding) and with the smooth
// closed form (to the facets' sagitta, R (1 - cos 0.25 deg) = 9.5e-6 R).
#include "core/tunnel/profile_deviation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "core/common/error.h"

namespace rockface::tunnel {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kFacets = 720;
const double kHalfFacet = kPi / kFacets;  // 0.25 deg
// Sums of ~10^4 products of metre-sized doubles: 1e-9 is thousands of ulps.
constexpr double kRounding = 1e-9;

// Chord-middle radius of a facet of a tube of radius R.
double faceted(double R) {
  return R * std::cos(kHalfFacet);
}

const Eigen::Vector3d kDatum(2690000, 1250000, 500);

// A straight tunnel heading north, chainage 0..20, on survey coordinates
// of 10^6 m.
Alignment north_tunnel() {
  return Alignment::from_elements(
      {{0, kDatum + Eigen::Vector3d(5, 7, 1)}, {20, kDatum + Eigen::Vector3d(5, 27, 1)}}, {0},
      kDatum);
}

struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::uint8_t> not_rock;  // per triangle
  SurfaceInput input() const { return {vertices, triangles, {}, not_rock}; }
};

// A tube about the ray centre `centre` (u, v): vertex columns at
// theta_i = -90 deg + i * 0.5 deg, rows at `chainages`; the quad of column
// i and row j is kept when keep(theta of its middle, chainage of its
// middle) and lies at radius(theta mid, chainage mid).
void add_tube(Mesh& m, const Alignment& al, const Eigen::Vector2d& centre,
              const std::vector<double>& chainages,
              const std::function<double(double, double)>& radius,
              const std::function<bool(double, double)>& keep, bool not_rock = false) {
  for (std::size_t j = 0; j + 1 < chainages.size(); ++j) {
    for (int i = 0; i < kFacets; ++i) {
      const double t0 = -kPi / 2 + 2 * kPi * i / kFacets, t1 = t0 + 2 * kPi / kFacets;
      const double tm = (t0 + t1) / 2, cm = (chainages[j] + chainages[j + 1]) / 2;
      if (!keep(tm, cm)) continue;
      const double r = radius(tm, cm);
      const int base = static_cast<int>(m.vertices.size());
      for (double c : {chainages[j], chainages[j + 1]}) {
        const TunnelFrame f = al.frame_at(c);
        for (double t : {t0, t1})
          m.vertices.push_back(
              f.to_local(centre.x() + r * std::cos(t), centre.y() + r * std::sin(t)));
      }
      m.triangles.push_back({base, base + 1, base + 3});
      m.triangles.push_back({base, base + 3, base + 2});
      m.not_rock.push_back(not_rock);
      m.not_rock.push_back(not_rock);
    }
  }
}

std::vector<double> steps(double from, double to, double step) {
  std::vector<double> out;
  const int n = static_cast<int>(std::lround((to - from) / step));
  for (int k = 0; k <= n; ++k) out.push_back(from + (to - from) * k / n);
  return out;
}

// One ray per facet for a circle of radius r: P / 720 (a hair more, so the
// ceiling in the ray count does not add a ray).
DeviationOptions one_ray_per_facet(double r, double from, double to, double spacing) {
  DeviationOptions o;
  o.chainage_from = from;
  o.chainage_to = to;
  o.section_spacing_m = spacing;
  o.ray_spacing_m = 2 * kPi * r / kFacets * (1 + 1e-12);
  o.underbreak_tolerance_m = 0.05;
  // One ray per cell, through the facet's middle: the exact faceted value
  // (the cell's median over n x n rays is tested below, issue 38).
  o.rays_per_cell_side = 1;
  return o;
}

const auto kEverywhere = [](double, double) { return true; };

TEST(ProfileDeviation, FullRingOfOverbreakIsPiTimesTheDifferenceOfSquares) {
  const Alignment al = north_tunnel();
  const DesignProfile design = circle_profile(3.0, 0.0);
  Mesh m;
  const double R = 3.25;
  add_tube(
      m, al, {0, 0}, steps(0, 12, 0.1), [&](double, double) { return R; }, kEverywhere);
  const ProfileDeviation d =
      profile_deviation(m.input(), al, design, one_ray_per_facet(3.0, 2, 10, 0.5));
  EXPECT_EQ(d.status, DeviationStatus::ok) << d.message;
  ASSERT_EQ(d.sections.size(), 17u);
  const double exact = kPi * (faceted(R) * faceted(R) - 9);
  for (const auto& s : d.sections) {
    EXPECT_NEAR(s.overbreak_area_m2, exact, kRounding) << s.chainage;
    // The smooth closed form pi (R^2 - r^2), within the facets' sagitta
    // (3.1e-5 m) times the perimeter (20.4 m): 6.3e-4 m^2.
    EXPECT_NEAR(s.overbreak_area_m2, kPi * (R * R - 9), 7e-4);
    EXPECT_EQ(s.underbreak_area_m2, 0);
    EXPECT_DOUBLE_EQ(s.seen_fraction, 1.0);
    EXPECT_NEAR(s.max_overbreak_m, faceted(R) - 3, kRounding);
  }
  EXPECT_NEAR(d.overbreak_volume_m3, exact * 8, 1e-8);
  EXPECT_EQ(d.underbreak_volume_m3, 0);
  EXPECT_FALSE(d.has_underbreak);
  EXPECT_TRUE(d.beyond_tolerance.empty());
  ASSERT_EQ(d.view.s.size(), 720u);
  for (float v : d.view.deviation_m) EXPECT_NEAR(v, faceted(R) - 3, 1e-6);  // float storage
}

TEST(ProfileDeviation, RaysThroughVerticesAndSeamsStillHitTheSurface) {
  // 360 rays on a 720-facet tube: every ray meets a vertex column, and the
  // sections (every 0.5 m) lie on the mesh's row seams (every 0.1 m): each
  // ray passes exactly through a vertex shared by six triangles. It must
  // hit (there it meets the tube at exactly R), never slip between them.
  const Alignment al = north_tunnel();
  Mesh m;
  const double R = 3.25;
  add_tube(
      m, al, {0, 0}, steps(0, 12, 0.1), [&](double, double) { return R; }, kEverywhere);
  DeviationOptions o = one_ray_per_facet(3.0, 2, 10, 0.5);
  o.ray_spacing_m *= 2;
  const ProfileDeviation d = profile_deviation(m.input(), al, circle_profile(3.0), o);
  EXPECT_EQ(d.status, DeviationStatus::ok) << d.message;
  EXPECT_EQ(d.seen_fraction, 1.0);
  // Through vertices at radius R: the smooth closed form, to rounding.
  for (const auto& s : d.sections) EXPECT_NEAR(s.overbreak_area_m2, kPi * (R * R - 9), 1e-8);
}

// A rectangular pocket on the developed view: columns 150..269 (60 deg) and
// chainage 3.05..5.05, the surface there at radius `pocket` instead of 3 m.
// Sections every 0.1 m from 1.0 put the pocket's ends halfway between two
// sections, where the trapezoidal rule is exact for a step; the facets'
// edges are the rays' cell edges, so the angular sum is exact too.
Mesh pocket_mesh(const Alignment& al, double pocket) {
  Mesh m;
  const double t_from = -kPi / 2 + 2 * kPi * 150 / kFacets;
  const double t_to = -kPi / 2 + 2 * kPi * 270 / kFacets;
  auto in_pocket = [=](double t, double c) {
    return t > t_from && t < t_to && c > 3.05 && c < 5.05;
  };
  add_tube(
      m, al, {0, 0}, steps(0, 10, 0.05), [](double, double) { return 3.0; },
      [&](double t, double c) { return !in_pocket(t, c); });
  add_tube(
      m, al, {0, 0}, steps(0, 10, 0.05), [&](double, double) { return pocket; }, in_pocket);
  return m;
}

TEST(ProfileDeviation, PocketOfKnownOverbreakVolume) {
  const Alignment al = north_tunnel();
  const Mesh m = pocket_mesh(al, 3.2);
  const ProfileDeviation d =
      profile_deviation(m.input(), al, circle_profile(3.0), one_ray_per_facet(3.0, 1, 8, 0.1));
  EXPECT_EQ(d.status, DeviationStatus::ok) << d.message;
  const double sector = kPi / 3;  // 120 facets of 0.5 deg
  const double area = 0.5 * (faceted(3.2) * faceted(3.2) - 9) * sector;
  EXPECT_NEAR(d.overbreak_volume_m3, area * 2.0, kRounding);
  // Against the smooth pocket: 1/2 (3.2^2 - 3^2) pi/3 * 2 m = 1.2985 m^3,
  // within the sagitta (3.0e-5 m) over the pocket's 6.7 m^2: 2e-4 m^3.
  EXPECT_NEAR(d.overbreak_volume_m3, 0.5 * (3.2 * 3.2 - 9) * sector * 2.0, 3e-4);
  EXPECT_NEAR(d.max_overbreak_m, faceted(3.2) - 3, kRounding);
  // The rest of the ring is the faceted 3 m tube: 2.9e-5 m of "underbreak",
  // well inside the 5 cm tolerance.
  EXPECT_TRUE(d.beyond_tolerance.empty());
  EXPECT_NEAR(d.max_underbreak_m, 3 - faceted(3.0), kRounding);
}

TEST(ProfileDeviation, UnderbreakBeyondToleranceIsListedWithItsPosition) {
  const Alignment al = north_tunnel();
  const Mesh m = pocket_mesh(al, 2.9);
  const DeviationOptions o = one_ray_per_facet(3.0, 1, 8, 0.1);
  const ProfileDeviation d = profile_deviation(m.input(), al, circle_profile(3.0), o);
  ASSERT_EQ(d.beyond_tolerance.size(), 1u);
  const UnderbreakPatch& p = d.beyond_tolerance[0];
  EXPECT_NEAR(p.max_depth_m, 3 - faceted(2.9), kRounding);
  EXPECT_NEAR(p.chainage_from, 3.1, kRounding);
  EXPECT_NEAR(p.chainage_to, 5.0, kRounding);
  const double P = 2 * kPi * 3;
  EXPECT_NEAR(p.s_from, P * 150 / 720, 1e-9);
  EXPECT_NEAR(p.s_to, P * 270 / 720, 1e-9);
  EXPECT_EQ(p.cells, 120u * 20u);
  EXPECT_TRUE(d.has_underbreak);
  EXPECT_NEAR(d.max_underbreak_m, 3 - faceted(2.9), kRounding);
  const ProfilePosition& at = d.max_underbreak;
  EXPECT_GE(at.chainage, 3.1 - kRounding);
  EXPECT_LE(at.chainage, 5.0 + kRounding);
  EXPECT_NEAR((at.survey - at.local - kDatum).norm(), 0, 1e-6);  // 2.7e6 m carry ~5e-10 m ulps
  EXPECT_NEAR(al.place(at.local).distance(), faceted(2.9), 1e-9);
  // Underbreak volume: the pocket plus the faceting of the rest of the ring
  // over the 7 m evaluated.
  const double pocket = 0.5 * (9 - faceted(2.9) * faceted(2.9)) * (kPi / 3) * 2.0;
  const double facets = 0.5 * (9 - faceted(3.0) * faceted(3.0)) * (2 * kPi * 7 - (kPi / 3) * 2.0);
  EXPECT_NEAR(d.underbreak_volume_m3, pocket + facets, kRounding);
  EXPECT_EQ(d.overbreak_volume_m3, 0);
}

TEST(ProfileDeviation, AnUnseenWallIsReportedUnseenNotZero) {
  const Alignment al = north_tunnel();
  Mesh m;  // only the right half: floor middle, right wall, crown middle
  add_tube(
      m, al, {0, 0}, steps(0, 10, 0.1), [](double, double) { return 3.25; },
      [](double t, double) { return t < kPi / 2; });
  DeviationOptions o = one_ray_per_facet(3.0, 2, 8, 0.5);
  o.min_seen_fraction = 0.6;
  const ProfileDeviation d = profile_deviation(m.input(), al, circle_profile(3.0), o);
  EXPECT_EQ(d.status, DeviationStatus::partly_seen);
  EXPECT_NE(d.message.find("saw less than 60 %"), std::string::npos) << d.message;
  EXPECT_NEAR(d.seen_fraction, 0.5, 1e-12);
  for (const auto& s : d.sections) {
    EXPECT_NEAR(s.seen_fraction, 0.5, 1e-12);
    // Only the seen half counts: half the ring's area.
    EXPECT_NEAR(s.overbreak_area_m2, 0.5 * kPi * (faceted(3.25) * faceted(3.25) - 9), kRounding);
    EXPECT_NEAR(s.roof_seen, 0.5, 1e-12);
    EXPECT_GT(s.walls_seen, 0.4);
  }
  // The left half is NaN ("not seen") in the developed view, never 0.
  const std::size_t cols = d.view.s.size();
  for (std::size_t j = 0; j < cols; ++j) {
    const bool left = d.view.s[j] > 3 * kPi;
    EXPECT_EQ(std::isnan(d.view.at(0, j)), left) << j;
    EXPECT_EQ(d.view.state[j], left ? 1 : 0) << j;
  }
  o.min_seen_fraction = 0.4;
  EXPECT_EQ(profile_deviation(m.input(), al, circle_profile(3.0), o).status, DeviationStatus::ok);
}

TEST(ProfileDeviation, NoWallsInViewIsSaidSo) {
  const Alignment al = north_tunnel();
  const DeviationOptions o = one_ray_per_facet(3.0, 2, 8, 0.5);
  // An empty mesh.
  const ProfileDeviation empty = profile_deviation(Mesh{}.input(), al, circle_profile(3.0), o);
  EXPECT_EQ(empty.status, DeviationStatus::no_walls_in_view);
  EXPECT_NE(empty.message.find("nothing of the profile"), std::string::npos) << empty.message;
  EXPECT_NE(empty.message.find("not zero"), std::string::npos) << empty.message;
  // Only the face, a disc across the tunnel at chainage 10, ahead of the
  // evaluated range.
  Mesh face;
  const TunnelFrame f = al.frame_at(10);
  face.vertices.push_back(f.origin);
  for (int i = 0; i <= 36; ++i)
    face.vertices.push_back(f.to_local(3 * std::cos(i * kPi / 18), 3 * std::sin(i * kPi / 18)));
  for (int i = 1; i <= 36; ++i) face.triangles.push_back({0, i, i + 1});
  EXPECT_EQ(profile_deviation(face.input(), al, circle_profile(3.0), o).status,
            DeviationStatus::no_walls_in_view);
  // Only the floor (within 45 deg of straight down).
  Mesh floor;
  add_tube(
      floor, al, {0, 0}, steps(0, 10, 0.1), [](double, double) { return 3.1; },
      // Within 30 deg of straight down (the columns run from -90 to 270 deg).
      [](double t, double) { return std::abs(std::remainder(t + kPi / 2, 2 * kPi)) < kPi / 6; });
  const ProfileDeviation fl = profile_deviation(floor.input(), al, circle_profile(3.0), o);
  EXPECT_EQ(fl.status, DeviationStatus::no_walls_in_view);
  EXPECT_NE(fl.message.find("only the floor"), std::string::npos) << fl.message;
  EXPECT_NEAR(fl.sections[0].floor_seen, 120.0 / 180, 1e-12);  // 60 of the floor's 90 deg
}

TEST(ProfileDeviation, NotRockIsExcludedAndCounted) {
  const Alignment al = north_tunnel();
  Mesh m;
  const double R = 3.25;
  // The range pole's strip: 20 facets (10 deg) flagged not rock.
  auto pole = [](double t, double) { return t > 0.1745 && t < 0.1745 + 20 * 2 * kPi / kFacets; };
  add_tube(
      m, al, {0, 0}, steps(0, 10, 0.1), [&](double, double) { return R; },
      [&](double t, double c) { return !pole(t, c); });
  add_tube(
      m, al, {0, 0}, steps(0, 10, 0.1), [&](double, double) { return R; }, pole, true);
  const ProfileDeviation d =
      profile_deviation(m.input(), al, circle_profile(3.0), one_ray_per_facet(3.0, 2, 8, 0.5));
  EXPECT_NEAR(d.excluded_fraction, 20.0 / 720, 1e-12);
  EXPECT_NEAR(d.seen_fraction, 700.0 / 720, 1e-12);
  const double seen_angle = 2 * kPi * 700 / 720;
  EXPECT_NEAR(d.sections[0].overbreak_area_m2, 0.5 * (faceted(R) * faceted(R) - 9) * seen_angle,
              kRounding);
  EXPECT_NEAR(d.sections[0].excluded_fraction, 20.0 / 720, 1e-12);
  // Per-vertex flags: a triangle with any flagged vertex is excluded.
  std::vector<std::uint8_t> by_vertex(m.vertices.size(), 0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (m.not_rock[t])
      for (int k : m.triangles[t]) by_vertex[static_cast<std::size_t>(k)] = 1;
  const SurfaceInput vertex_masked{m.vertices, m.triangles, by_vertex, {}};
  const ProfileDeviation dv =
      profile_deviation(vertex_masked, al, circle_profile(3.0), one_ray_per_facet(3.0, 2, 8, 0.5));
  EXPECT_NEAR(dv.excluded_fraction, 20.0 / 720, 1e-12);  // the strip's own vertices only
}

TEST(ProfileDeviation, HorseshoeFloorDepthIsMeasuredNormalToTheInvert) {
  // The invert excavated 0.3 m deeper than designed; walls and crown on
  // the design line. Rays leave the crown's centre, 4 m above the invert,
  // and meet the floor obliquely: along the ray the deviation is 0.3 /
  // cos(incidence), normal to the invert it is 0.3 m everywhere.
  const Alignment al = north_tunnel();
  const DesignProfile design = horseshoe_profile(5, 1.5, 10, -2.5);
  const double P = design.perimeter();
  const int n = static_cast<int>(std::ceil(P / 0.01));
  std::vector<Eigen::Vector2d> outline;
  for (int k = 0; k < n; ++k) {
    Eigen::Vector2d q = design.point_at_length(P * k / n);
    if (q.y() < -2.5 + 1e-9) q.y() -= 0.3;
    outline.push_back(q);
  }
  Mesh m;
  const auto cs = steps(0, 10, 0.5);
  for (std::size_t j = 0; j < cs.size(); ++j) {
    const TunnelFrame f = al.frame_at(cs[j]);
    for (const auto& q : outline) m.vertices.push_back(f.to_local(q.x(), q.y()));
  }
  for (std::size_t j = 0; j + 1 < cs.size(); ++j)
    for (int k = 0; k < n; ++k) {
      const int a = static_cast<int>(j) * n + k, b = static_cast<int>(j) * n + (k + 1) % n;
      m.triangles.push_back({a, b, b + n});
      m.triangles.push_back({a, b + n, a + n});
    }
  DeviationOptions o;
  o.chainage_from = 2;
  o.chainage_to = 8;
  o.section_spacing_m = 1;
  o.ray_spacing_m = 0.05;
  const ProfileDeviation d = profile_deviation(m.input(), al, design, o);
  EXPECT_EQ(d.status, DeviationStatus::ok) << d.message;
  const double half = design.segments()[0].length();
  int floor_rays = 0;
  for (std::size_t j = 0; j < d.view.s.size(); ++j) {
    const Eigen::Vector2d q = design.point_at_length(d.view.s[j]);
    if (q.y() < -2.5 + 1e-9 && std::abs(q.x()) < half - 0.6) {
      // The floor is flat in the mesh and in the design: exact but for
      // float storage of the view (1e-7 relative).
      EXPECT_NEAR(d.view.at(3, j), 0.3, 1e-6) << q.transpose();
      ++floor_rays;
    } else if (q.y() > -2.0) {
      // Walls and crown on the line but for the mesh's 1 cm chords
      // (sagitta 0.01^2 / (8 * 5 m) = 2.5e-6 m).
      EXPECT_NEAR(d.view.at(3, j), 0.0, 1e-5) << q.transpose();
    }
  }
  EXPECT_GT(floor_rays, 50);
  EXPECT_TRUE(d.beyond_tolerance.empty());
  EXPECT_GT(d.sections[0].overbreak_area_m2, 0.3 * 2 * (half - 0.3));
}

TEST(ProfileDeviation, BadInputIsRefusedByName) {
  const Alignment al = north_tunnel();
  DeviationOptions o = one_ray_per_facet(3.0, 2, 8, 0.5);
  o.ray_spacing_m = 0;
  try {
    profile_deviation(Mesh{}.input(), al, circle_profile(3.0), o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("options.ray_spacing_m"), std::string::npos);
  }
  Mesh bad;
  bad.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  bad.triangles = {{0, 1, 7}};
  try {
    profile_deviation(bad.input(), al, circle_profile(3.0), one_ray_per_facet(3.0, 2, 8, 0.5));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("triangles[0]"), std::string::npos) << e.what();
  }
  const ProfileDeviation out = profile_deviation(Mesh{}.input(), al, circle_profile(3.0),
                                                 one_ray_per_facet(3.0, 30, 40, 0.5));
  EXPECT_EQ(out.status, DeviationStatus::outside_alignment);
  EXPECT_NE(out.message.find("outside the alignment"), std::string::npos);
}

}  // namespace
}  // namespace rockface::tunnel

namespace rockface::tunnel {
namespace {

// The preset's knobs sit beside the component (issue 37): a finer preset

// ---- issue 38: robust figures ----

// A deterministic speck of noise per facet, uniform in [-amplitude,
// amplitude] (a hash of the facet's place; no generator state).
double facet_noise(double theta, double chainage, double amplitude) {
  const double h = std::sin(theta * 12.9898 + chainage * 78.233) * 43758.5453;
  return amplitude * (2 * (h - std::floor(h)) - 1);
}

TEST(ProfileDeviation, OneStrayTriangleBehindAHoleDoesNotMakeTheMaximum) {
  // A wall on the design line with a hole of one facet by two rows; behind
  // the hole, 1.8 m outside the wall, a stray piece of mesh (what a
  // reconstruction leaves in the background). One ray per cell meets it.
  const Alignment al = north_tunnel();
  const double hole_theta = 2 * kPi * 200.5 / kFacets - kPi / 2;  // facet 200's middle
  const auto in_hole = [&](double t, double c) {
    return std::abs(t - hole_theta) < 1e-9 && c > 4.9 && c < 5.1;
  };
  Mesh m;
  add_tube(
      m, al, {0, 0}, steps(0, 12, 0.1), [](double, double) { return 3.0; },
      [&](double t, double c) { return !in_hole(t, c); });
  add_tube(
      m, al, {0, 0}, steps(4.8, 5.4, 0.1), [](double, double) { return 4.8; },
      [&](double t, double) { return std::abs(t - hole_theta) < 0.05; });
  const ProfileDeviation d =
      profile_deviation(m.input(), al, circle_profile(3.0), one_ray_per_facet(3.0, 2, 10, 0.5));
  ASSERT_EQ(d.status, DeviationStatus::ok) << d.message;
  EXPECT_EQ(d.cells_off_lining, 1u) << d.message;
  // The wall itself is on the design line (to the facets' sagitta).
  EXPECT_LT(d.max_overbreak_m, 1e-3) << d.max_overbreak.chainage << " " << d.max_overbreak.s;
  EXPECT_LT(d.overbreak_volume_m3, 1e-6);
  EXPECT_NE(d.message.find("1 cells off any plausible lining"), std::string::npos) << d.message;
}

TEST(ProfileDeviation, OneCellFarOffItsBreaksFlankDoesNotMakeTheLargest) {
  // A smooth overbreak (sin^2 over chainage 3-7 and 60 deg of the ring,
  // 0.30 m deep at chainage 5 and 30 deg) with one facet on its flank, at
  // chainage 4.9-5.1, 0.45 m out where the bump is 0.14 m (issue 38: the
  // sample heading read 0.40 m on a flank the scene has at 0.03 m). Its
  // neighbours along the chainage are 0.25 m away, so a slope of 1.2 keeps
  // it on a plausible lining and the flank rule counts it with the break.
  const Alignment al = north_tunnel();
  const double from = 0, to = kPi / 3;
  auto bump = [](double x, double a, double b) {
    if (!(x > a && x < b)) return 0.0;
    const double t = std::sin(kPi * (x - a) / (b - a));
    return t * t;
  };
  auto depth = [&](double t, double c) { return 0.30 * bump(c, 3, 7) * bump(t, from, to); };
  const double spike_theta = 2 * kPi * 208.5 / kFacets - kPi / 2;  // facet 208: 14.25 deg
  auto is_spike = [&](double t, double c) {
    return std::abs(t - spike_theta) < 1e-9 && c > 4.9 && c < 5.1;
  };
  Mesh m;
  add_tube(
      m, al, {0, 0}, steps(0, 10, 0.05),
      [&](double t, double c) { return is_spike(t, c) ? 3.45 : 3.0 + depth(t, c); }, kEverywhere);
  ASSERT_NEAR(depth(spike_theta, 5.0), 0.14, 0.01);  // the flank under the spike
  const ProfileDeviation d =
      profile_deviation(m.input(), al, circle_profile(3.0), one_ray_per_facet(3.0, 1, 9, 0.25));
  ASSERT_EQ(d.status, DeviationStatus::ok) << d.message;
  EXPECT_EQ(d.cells_off_lining, 0u) << d.message;
  // The crest's depth: the crest cell capped by its second deepest
  // neighbour, those along the outline 0.5 deg away (0.30 x sin^2 of 89.25
  // deg: 0.2995 m; along the chainage, 0.25 m away, 0.289 m); the facets'
  // sagitta is 3e-5 m. 1 mm holds the first and not the spike (0.45 m).
  EXPECT_NEAR(d.max_overbreak_m, 0.30, 1e-3)
      << d.max_overbreak.chainage << " / " << d.max_overbreak.angle;
  // At the crest: its cell or the next along the outline (0.5 deg, 2.6 cm).
  EXPECT_NEAR(d.max_overbreak.chainage, 5.0, 1e-9);
  EXPECT_NEAR(d.max_overbreak.angle, kPi / 6, 0.6 * kPi / 180);
}

TEST(ProfileDeviation, AClusterOfStrayCellsBehindAHoleIsLeftOutNotInterpolated) {
  // A wall on the design line with a hole three facets wide and 0.4 m
  // long; behind it, 0.85 m outside the wall, a stray sheet (issue 38: the
  // D heading's cells 0.85 m behind its wall, whose interpolated neighbours
  // added 0.07 m3 of overbreak). Its cells agree with each other, so the
  // one-cell rule keeps them; as a piece they meet the wall only across the
  // jump and are far smaller than the smallest break the round counts.
  const Alignment al = north_tunnel();
  const double hole_from = 2 * kPi * 200 / kFacets - kPi / 2;
  const double hole_to = 2 * kPi * 203 / kFacets - kPi / 2;
  const auto in_hole = [&](double t, double c) {
    return t > hole_from && t < hole_to && c > 4.8 && c < 5.2;
  };
  Mesh m;
  add_tube(
      m, al, {0, 0}, steps(0, 12, 0.1), [](double, double) { return 3.0; },
      [&](double t, double c) { return !in_hole(t, c); });
  add_tube(
      m, al, {0, 0}, steps(4.6, 5.4, 0.1), [](double, double) { return 3.85; },
      [&](double t, double) { return t > hole_from - 0.05 && t < hole_to + 0.05; });
  DeviationOptions o = one_ray_per_facet(3.0, 2, 10, 0.1);
  const ProfileDeviation d = profile_deviation(m.input(), al, circle_profile(3.0), o);
  ASSERT_EQ(d.status, DeviationStatus::ok) << d.message;
  // Sections 4.9, 5.0 and 5.1 by the hole's 3 facets.
  EXPECT_EQ(d.cells_off_lining, 9u) << d.message;
  EXPECT_LT(d.max_overbreak_m, 1e-3) << d.max_overbreak.chainage << " " << d.max_overbreak.s;
  EXPECT_LT(d.overbreak_volume_m3, 1e-6);
  // Left out, they are not interpolated from (a hole of a wall stays one).
  EXPECT_EQ(d.interpolated_overbreak_m3, 0.0);
}

TEST(ProfileDeviation, ASheetBelowTheInvertSeenThroughAHoleIsLeftOutAndCounted) {
  // The lower right wall (rays 36 to 44 degrees below horizontal: the
  // outline's normal there points less than 45 degrees down, so these are
  // wall rays) has a hole 0.5 m long; behind it a sheet of mesh at 5.5 m
  // from the centre, where those rays meet it 0.23-0.82 m below the
  // invert's lowest point (3 m below the centre): large enough that its
  // cells agree with each other.
  const Alignment al = north_tunnel();
  const auto in_hole = [](double t, double c) {
    return t > -44 * kPi / 180 && t < -36 * kPi / 180 && c > 5.0 && c < 5.5;
  };
  Mesh m;
  add_tube(
      m, al, {0, 0}, steps(0, 12, 0.1), [](double, double) { return 3.0; },
      [&](double t, double c) { return !in_hole(t, c); });
  add_tube(
      m, al, {0, 0}, steps(4.5, 6.0, 0.1), [](double, double) { return 5.5; },
      [](double t, double) { return t > -47 * kPi / 180 && t < -33 * kPi / 180; });
  DeviationOptions o = one_ray_per_facet(3.0, 2, 10, 0.25);
  o.rays_per_cell_side = 3;
  const ProfileDeviation d = profile_deviation(m.input(), al, circle_profile(3.0), o);
  ASSERT_EQ(d.status, DeviationStatus::ok) << d.message;
  EXPECT_GT(d.cells_below_invert, 10u) << d.message;
  EXPECT_LT(d.max_overbreak_m, 1e-3) << d.max_overbreak.chainage << " " << d.max_overbreak.s;
  EXPECT_LT(d.overbreak_volume_m3, 1e-6);
  EXPECT_NE(d.message.find("below the invert"), std::string::npos) << d.message;
}

TEST(ProfileDeviation, AFloorMetFarBelowTheDesignIsLeftOutAndARealFloorBreakIsCounted) {
  // Issue 38: the floor (rays 65 to 85 degrees below horizontal: the
  // invert's rays, whose outline normal points down within 45 degrees; the
  // tube's facets run from -90 degrees) has a hole 0.7 m long;
  // behind it, 1.8 m below the design, a sheet of mesh (a reconstruction's
  // stray background). Elsewhere on the floor a real break 0.4 m deep,
  // 1.2 m long: within the plausible 0.5 m, it counts. Both end between
  // the sections (every 0.25 m from 2), so no section straddles an edge.
  const Alignment al = north_tunnel();
  const double lo = -85 * kPi / 180, hi = -65 * kPi / 180;
  const auto in_hole = [&](double t, double c) { return t > lo && t < hi && c > 4.9 && c < 5.6; };
  const auto in_break = [&](double t, double c) { return t > lo && t < hi && c > 6.9 && c < 8.1; };
  Mesh m;
  add_tube(
      m, al, {0, 0}, steps(0, 12, 0.1),
      [&](double t, double c) { return in_break(t, c) ? 3.4 : 3.0; },
      [&](double t, double c) { return !in_hole(t, c); });
  add_tube(
      m, al, {0, 0}, steps(4.5, 6.0, 0.1), [](double, double) { return 4.8; },
      [&](double t, double) { return t > lo - 0.05 && t < hi + 0.05; });
  DeviationOptions o = one_ray_per_facet(3.0, 2, 10, 0.25);
  o.rays_per_cell_side = 3;
  const ProfileDeviation d = profile_deviation(m.input(), al, circle_profile(3.0), o);
  ASSERT_EQ(d.status, DeviationStatus::ok) << d.message;
  // The hole's 3 sections (5.0, 5.25, 5.5) by 40 facets are left out, said
  // with the bound.
  EXPECT_GE(d.cells_below_invert, 3 * 40u - 6) << d.message;
  EXPECT_NE(d.message.find("floor rays more than 0.50 m below the design"), std::string::npos)
      << d.message;
  EXPECT_EQ(d.max_invert_overbreak_m, 0.5);
  // The largest overbreak is the real break, 0.4 m but for the facets'
  // sagitta (3.4 m x (1 - cos 0.25 deg) = 3.2e-5 m, where the cell's rays
  // meet the chords), inside its stretch.
  EXPECT_NEAR(d.max_overbreak_m, 0.4, 1e-4) << d.max_overbreak.chainage << " " << d.max_overbreak.s;
  EXPECT_GT(d.max_overbreak.chainage, 6.9);
  EXPECT_LT(d.max_overbreak.chainage, 8.1);
  // Its volume: 1/2 (3.4^2 - 3^2) x 20 degrees x 1.2 m = 0.534 m3. The
  // trapezoid over the sections (7.0 to 8.0 in it, 6.75 and 8.25 not) gives
  // 1.25 m of chainage for its 1.2 (+4 %), and the columns at its sides
  // straddle its edges by a facet: 5 % either way.
  const double truth = 0.5 * (3.4 * 3.4 - 9.0) * (hi - lo) * 1.2;
  EXPECT_NEAR(d.overbreak_volume_m3, truth, 0.05 * truth);
}

TEST(ProfileDeviation, TheLiningsOffsetIsMeasuredOnTheLiningNotPulledByItsBreaks) {
  // The same lining, 3 mm inside the design with +-7 mm of noise, now with
  // underbreak 0.1 m deep over 1.5 rad of its 2 pi along the whole round
  // (24 % of the cells). The median of every cell would lie at the 34 %
  // point of the intact cells' noise (-10 to +4 mm): -5.2 mm. The offset
  // is the median of the cells within the noise threshold (1 cm) of that:
  // the intact ones, -3 mm, to the tolerance of the test above (0.3 mm).
  const Alignment al = north_tunnel();
  const auto in_break = [](double t, double) { return t > 0.5 && t < 2.0; };
  const std::vector<double> rows = steps(0, 12, 0.07);
  Mesh m;
  add_tube(
      m, al, {0, 0}, rows,
      [&](double t, double c) {
        return 3.0 - 0.003 + facet_noise(t, c, 0.007) - (in_break(t, c) ? 0.1 : 0.0);
      },
      kEverywhere);
  DeviationOptions o;
  o.chainage_from = 2;
  o.chainage_to = 10;
  o.depth_sigma_m = 0.005;
  const ProfileDeviation d = profile_deviation(m.input(), al, circle_profile(3.0), o);
  ASSERT_EQ(d.status, DeviationStatus::ok) << d.message;
  EXPECT_NEAR(d.lining_offset.median_m, -0.003, 3e-4);
  EXPECT_TRUE(d.lining_offset_removed);
}

TEST(ProfileDeviation, NoiseWithinTheStatedPrecisionIsNotCountedAndTheOffsetIsStated) {
  // A lining 3 mm inside the design line with +-7 mm of noise per facet (as
  // a reconstruction's surface: a bias and noise), and one pocket of
  // underbreak 0.1 m deep over 0.5 rad and 2 m of chainage. The facets'
  // rows are 0.07 m long so that no ray runs along the seam of two rows
  // (facets at different radii: the first hit there is the nearer one, a
  // bias of the test's mesh, which a reconstruction's connected mesh has not).
  const Alignment al = north_tunnel();
  // Its ends lie halfway between sections (every 0.25 m from 2), where the
  // trapezoidal rule over the sections puts a step.
  const auto in_pocket = [](double t, double c) {
    return t > 0.5 && t < 1.0 && c > 5.125 && c < 7.125;
  };
  const std::vector<double> rows = steps(0, 12, 0.07);
  // The pocket as the facets draw it: whole facets of 0.5 deg, whole rows.
  double pocket_rad = 0, pocket_m = 0;
  for (int i = 0; i < kFacets; ++i)
    if (in_pocket(-kPi / 2 + 2 * kPi * (i + 0.5) / kFacets, 6)) pocket_rad += 2 * kPi / kFacets;
  for (std::size_t j = 0; j + 1 < rows.size(); ++j)
    if (in_pocket(0.75, (rows[j] + rows[j + 1]) / 2)) pocket_m += rows[j + 1] - rows[j];
  Mesh m;
  add_tube(
      m, al, {0, 0}, rows,
      [&](double t, double c) {
        return 3.0 - 0.003 + facet_noise(t, c, 0.007) - (in_pocket(t, c) ? 0.1 : 0.0);
      },
      kEverywhere);
  DeviationOptions o;
  o.chainage_from = 2;
  o.chainage_to = 10;
  o.depth_sigma_m = 0.005;  // the stated precision: threshold 2 sigma = 1 cm
  const ProfileDeviation d = profile_deviation(m.input(), al, circle_profile(3.0), o);
  ASSERT_EQ(d.status, DeviationStatus::ok) << d.message;
  EXPECT_DOUBLE_EQ(d.noise_threshold_m, 0.01);
  // The offset: the median cell, -3 mm, within the noise's effect on a
  // median of ~12000 cells of +-7 mm uniform noise (standard error ~0.05
  // mm), the pocket's 2 % of the cells below it (~0.1 mm) and the facets'
  // sagitta (0.01 mm): 0.3 mm.
  EXPECT_NEAR(d.lining_offset.median_m, -0.003, 3e-4);
  EXPECT_TRUE(d.lining_offset_removed);
  EXPECT_NE(d.message.find("off the design as a whole"), std::string::npos) << d.message;
  // The pocket's volume (1/2 (3^2 - 2.9^2) x its angle x its length, about
  // 0.295 m3): the noise (+-7 mm, mean 0) over its 1.5 m^2 moves it by well
  // under 1 mm x 1.5 m^2 = 0.0015 m3; cells across its edges are counted
  // whole or not at all (half a cell of 0.05 m along 2 m each side, 0.1 m
  // deep: 0.005 m3 each, ~3 %): 0.012 m3.
  const double pocket = 0.5 * (9 - 2.9 * 2.9) * pocket_rad * pocket_m;
  EXPECT_NEAR(d.underbreak_volume_m3, pocket, 0.012);
  // Outside the pocket nothing is counted: the noise and the offset stay
  // within the threshold, so there is no overbreak at all.
  EXPECT_EQ(d.overbreak_volume_m3, 0);
  EXPECT_EQ(d.max_overbreak_m, 0);
  ASSERT_TRUE(d.underbreak_volume_sigma_m3);
  EXPECT_GT(*d.underbreak_volume_sigma_m3, 0);
  // Without a stated precision every deviation counts: the offset alone
  // makes 2 pi x 3 m x 3 mm x 8 m = 0.45 m3 of "underbreak" (issue 38).
  o.depth_sigma_m = 0;
  const ProfileDeviation plain = profile_deviation(m.input(), al, circle_profile(3.0), o);
  EXPECT_GT(plain.underbreak_volume_m3, pocket + 0.3);
  EXPECT_FALSE(plain.underbreak_volume_sigma_m3);
}

TEST(ProfileDeviation, SectionsThatMeetNothingAtTheEndsAreLeftOutAndSaid) {
  const Alignment al = north_tunnel();
  Mesh m;
  add_tube(
      m, al, {0, 0}, steps(4, 12, 0.1), [](double, double) { return 3.1; }, kEverywhere);
  const ProfileDeviation d =
      profile_deviation(m.input(), al, circle_profile(3.0), one_ray_per_facet(3.0, 2, 10, 0.5));
  EXPECT_EQ(d.status, DeviationStatus::ok) << d.message;
  ASSERT_EQ(d.sections_left_out.size(), 1u);
  EXPECT_DOUBLE_EQ(d.sections_left_out[0].chainage_from, 2.0);
  EXPECT_DOUBLE_EQ(d.sections_left_out[0].chainage_to, 3.5);
  EXPECT_EQ(d.sections_left_out[0].sections, 4u);
  ASSERT_FALSE(d.sections.empty());
  EXPECT_DOUBLE_EQ(d.sections.front().chainage, 4.0);
  EXPECT_DOUBLE_EQ(d.view.chainage.front(), 4.0);
  EXPECT_NE(d.message.find("4 cross-sections at chainage 2.00 to 3.50 left out"), std::string::npos)
      << d.message;
  // The overbreak over the sections kept: 6 m of a ring of 3.1 m.
  EXPECT_NEAR(d.overbreak_volume_m3, kPi * (faceted(3.1) * faceted(3.1) - 9) * 6, 1e-8);
}

// Issue 38: a hole of the 3D image inside the measured lining is filled
// from its measured neighbours when it is no wider than the stated limit,
// counted in the volume with its share and uncertainty said; a wider one
// stays unseen. The lining: a tube whose overbreak grows linearly along the
// chainage (radius 3.1 + 0.01 c m on a 3 m circle), each 0.1 m ring of
// facets at its middle's radius, the sections through those middles; the
// hole spans 0.9 m of outline (wider than the limit along it), so only the
// chainage brackets it. Linear interpolation along the chainage is exact on
// this lining: the truth is the whole tube's volume.
Mesh growing_tube_with_hole(const Alignment& al, double hole_from, double hole_to) {
  Mesh m;
  add_tube(
      m, al, {0, 0}, steps(-0.05, 12.05, 0.1), [](double, double c) { return 3.1 + 0.01 * c; },
      [&](double t, double c) { return !(t >= 0 && t < 0.3 && c > hole_from && c < hole_to); });
  return m;
}

double growing_tube_volume(double from, double to, double spacing) {
  // Trapezoidal over the sections, each a whole faceted ring (as
  // FullRingOfOverbreakIsPiTimesTheDifferenceOfSquares).
  double v = 0;
  const int n = static_cast<int>(std::lround((to - from) / spacing));
  for (int k = 0; k < n; ++k) {
    const double a = faceted(3.1 + 0.01 * (from + k * spacing));
    const double b = faceted(3.1 + 0.01 * (from + (k + 1) * spacing));
    v += 0.5 * kPi * ((a * a - 9) + (b * b - 9)) * spacing;
  }
  return v;
}

TEST(ProfileDeviation, AHoleWithinTheLimitIsInterpolatedAndAWiderOneStaysUnseen) {
  const Alignment al = north_tunnel();
  DeviationOptions o = one_ray_per_facet(3.0, 2, 8, 0.1);
  // The stated limit: the smallest break the round counts.
  ASSERT_EQ(o.max_interpolated_hole_m, 0.75);
  ASSERT_EQ(o.max_interpolated_hole_m, o.min_break_chainage_m);
  // Three sections (5.1-5.3) unseen over 0.9 m of outline: 0.3 m along the
  // chainage, within the limit.
  const ProfileDeviation d =
      profile_deviation(growing_tube_with_hole(al, 5.05, 5.35).input(), al, circle_profile(3.0), o);
  ASSERT_EQ(d.sections.size(), 61u);
  // Rounding of ~10^5 polar areas of metre-sized radii: far below 1e-8 m^3.
  EXPECT_NEAR(d.overbreak_volume_m3, growing_tube_volume(2, 8, 0.1), 1e-8);
  EXPECT_GT(d.interpolated_fraction, 0);
  EXPECT_NEAR(d.seen_fraction + d.interpolated_fraction, 1, 1e-12);
  // The hole's share: its cells' part of the volume, 3 of 61 sections over
  // a fraction of the outline, between 0 and 3 / 60 of the whole.
  EXPECT_GT(d.interpolated_overbreak_m3, 0);
  EXPECT_LT(d.interpolated_overbreak_m3, 3.0 / 60 * d.overbreak_volume_m3);
  EXPECT_NE(d.message.find("interpolated across holes"), std::string::npos) << d.message;
  // Its cells are drawn as interpolated, their deviation the lining's.
  const std::size_t cols = d.view.s.size();
  std::size_t interpolated = 0;
  for (std::size_t k = 0; k < d.view.state.size(); ++k)
    if (d.view.state[k] == 4) {
      ++interpolated;
      const double c = d.view.chainage[k / cols];
      EXPECT_NEAR(d.view.deviation_m[k], faceted(3.1 + 0.01 * c) - 3, 1e-6) << c;  // float
    }
  EXPECT_NEAR(static_cast<double>(interpolated) / static_cast<double>(d.view.state.size()),
              d.interpolated_fraction, 1e-12);

  // Nine sections (5.1-5.9, 0.9 m) unseen: wider than the limit both ways.
  const ProfileDeviation w =
      profile_deviation(growing_tube_with_hole(al, 5.05, 5.95).input(), al, circle_profile(3.0), o);
  EXPECT_EQ(w.interpolated_fraction, 0);
  EXPECT_LT(w.overbreak_volume_m3, growing_tube_volume(2, 8, 0.1) - 1e-3);
  for (std::size_t k = 0; k < w.view.state.size(); ++k) EXPECT_NE(w.view.state[k], 4);
  // Never interpolated when the limit is 0.
  o.max_interpolated_hole_m = 0;
  EXPECT_EQ(
      profile_deviation(growing_tube_with_hole(al, 5.05, 5.35).input(), al, circle_profile(3.0), o)
          .interpolated_fraction,
      0);
}

// cuts the round into more sections and casts more rays, and keeps the
// other options (tolerances, caps) of a default DeviationOptions.
TEST(DeviationOptionsOfPreset, FinerPresetsSampleMoreDenselyAndKeepTheRest) {
  const DeviationOptions fast = deviation_options(Preset::fast);
  const DeviationOptions standard = deviation_options(Preset::standard);
  const DeviationOptions precise = deviation_options(Preset::precise);
  EXPECT_GT(fast.section_spacing_m, standard.section_spacing_m);
  EXPECT_GT(standard.section_spacing_m, precise.section_spacing_m);
  EXPECT_GT(fast.ray_spacing_m, standard.ray_spacing_m);
  EXPECT_GT(standard.ray_spacing_m, precise.ray_spacing_m);
  const DeviationOptions plain;
  for (const DeviationOptions& o : {fast, standard, precise}) {
    EXPECT_EQ(o.underbreak_tolerance_m, plain.underbreak_tolerance_m);
    EXPECT_EQ(o.max_overbreak_m, plain.max_overbreak_m);
    EXPECT_EQ(o.min_seen_fraction, plain.min_seen_fraction);
  }
  // The standard preset is the documented default of the struct itself.
  EXPECT_EQ(standard.section_spacing_m, plain.section_spacing_m);
  EXPECT_EQ(standard.ray_spacing_m, plain.ray_spacing_m);
}

}  // namespace
}  // namespace rockface::tunnel

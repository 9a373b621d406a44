// The figures on faces drawn exactly: traces as the true lines where
// planes of known spacing cut a flat rectangular face.
#include <cmath>

#include <gtest/gtest.h>

#include "core/geometry/orientation.h"
#include "core/rockmass/rock_mass_figures.h"

namespace rockface::rockmass {
namespace {

// The face y = 0, x in [0, w], z in [0, h]; the planes n . p = d0 + k s.
struct Face {
  double w = 12, h = 6;
  std::vector<FaceTrace> traces;
  std::vector<Eigen::Vector3d> outline() const {
    return {{0, 0, 0}, {w, 0, 0}, {w, 0, h}, {0, 0, h}};
  }
  void add_set(const Eigen::Vector3d& n, double s, double d0, const std::string& tag) {
    // Where n_x x + n_z z = d cuts the rectangle: clip the line to it.
    const Eigen::Vector2d along(n.z(), -n.x());
    double lo = 1e9, hi = -1e9;
    for (const auto& c : outline()) {
      lo = std::min(lo, n.dot(c));
      hi = std::max(hi, n.dot(c));
    }
    int k = static_cast<int>(std::ceil((lo - d0) / s));
    for (double d = d0 + k * s; d < hi; d += s) {
      const Eigen::Vector2d base =
          d * Eigen::Vector2d(n.x(), n.z()) / (n.x() * n.x() + n.z() * n.z());
      double t0 = -1e9, t1 = 1e9;
      const double lo_b[2] = {0, 0}, hi_b[2] = {w, h};
      bool inside = true;
      for (int a = 0; a < 2; ++a) {
        if (std::abs(along[a]) < 1e-12) {
          if (base[a] < lo_b[a] || base[a] > hi_b[a]) inside = false;
          continue;
        }
        double u = (lo_b[a] - base[a]) / along[a], v = (hi_b[a] - base[a]) / along[a];
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
      }
      if (!inside || t1 - t0 < 1e-6) continue;
      FaceTrace t;
      t.label = tag + std::to_string(traces.size() + 1);
      for (double f : {0.0, 0.5, 1.0}) {
        const Eigen::Vector2d q = base + (t0 + f * (t1 - t0)) * along;
        t.points.push_back({q.x(), 0, q.y()});
      }
      t.length_m = t1 - t0;
      t.censored = true;  // every trace runs from edge to edge
      traces.push_back(t);
    }
  }
};

TEST(RockMassFigures, ThreeSetsOfKnownSpacingOnAFlatFace) {
  Face face;
  const double spacing[3] = {0.8, 1.0, 1.2};
  const double orient[3][2] = {{60, 200}, {75, 110}, {20, 350}};
  RockMassInput in;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d n = geometry::plane_normal_deg(orient[k][0], orient[k][1]);
    face.add_set(n, spacing[k], 0.013 * (k + 1), "S" + std::to_string(k + 1) + "-");
    in.sets.push_back({"S" + std::to_string(k + 1), n});
  }
  in.traces = face.traces;
  in.outline_points = face.outline();
  const RockMassFigures f = rock_mass_figures(in);
  EXPECT_NEAR(f.window.area_m2, 72, 1e-9);
  EXPECT_TRUE(f.assigned.random.empty()) << f.assigned.random.size() << " random";
  double jv = 0;
  for (int k = 0; k < 3; ++k) {
    const auto& s = f.spacings[k];
    ASSERT_TRUE(s.mean_m) << s.label;
    // Exact lines, straight traces: the only error is the arithmetic.
    EXPECT_NEAR(*s.mean_m, spacing[k], 1e-9) << s.label;
    EXPECT_NEAR(*s.cv, 0, 1e-6) << s.label;
    EXPECT_NE(s.distribution.find("regular"), std::string::npos);
    jv += 1 / spacing[k];
    // Every trace leaves the window: persistence only bounded.
    EXPECT_FALSE(f.persistence[k].persistence_m);
    EXPECT_TRUE(f.persistence[k].lower_bound_m);
  }
  ASSERT_TRUE(f.jv.jv);
  EXPECT_NEAR(*f.jv.jv, jv, 1e-9);
  EXPECT_EQ(f.sets, 3);
  EXPECT_FALSE(f.random_joints);
  EXPECT_EQ(*f.q.jn.rating, 9);
  EXPECT_EQ(f.measured_rmr.spacing_set, "S1");
  // Three sets cut parallelepipeds: Vb = S1 S2 S3 / |det(n1, n2, n3)|.
  ASSERT_TRUE(f.blocks.vb_from_spacing_m3);
  Eigen::Matrix3d n;
  for (int k = 0; k < 3; ++k) n.col(k) = in.sets[k].normal;
  EXPECT_NEAR(*f.blocks.vb_from_spacing_m3, 0.8 * 1.0 * 1.2 / std::abs(n.determinant()), 1e-9);
  ASSERT_EQ(f.scanlines.directions.size(), 3u);
  for (const auto& d : f.scanlines.directions) {
    ASSERT_TRUE(d.rqd_percent);
    EXPECT_GE(*d.rqd_percent, 0);
    EXPECT_LE(*d.rqd_percent, 100);
    // The frequency the sets' spacings give along the line is what the
    // line counts, up to the window's ends (a few crossings in hundreds).
    ASSERT_TRUE(d.frequency_from_sets_per_m);
    EXPECT_NEAR(d.frequency_per_m, *d.frequency_from_sets_per_m, 0.1 * *d.frequency_from_sets_per_m)
        << d.name;
    for (const auto& s : d.sets) {
      // Terzaghi's correction of the apparent spacing: a line of length L
      // holding L / a of the set's crossings counts one more or one fewer
      // at its ends, so the count is off by at most one per line: a
      // relative error of at most lines / crossings.
      if (s.corrected_m && s.crossings >= 10) {
        const double truth = spacing[s.label[1] - '1'];
        const double bound = static_cast<double>(d.lines) / (s.crossings - d.lines);
        EXPECT_NEAR(*s.corrected_m, truth, bound * truth) << d.name << " " << s.label;
      }
    }
  }
}

TEST(RockMassFigures, ScanlineRqdOfOneCloseVerticalSetAsByHand) {
  // Vertical joints striking north at 0.08 m (x = 0.05 + 0.08 k) on a face
  // 6 m wide: the horizontal lines are cut into 0.08 m pieces (RQD 0), the
  // vertical lines run along them uncut (RQD 100), the 45 deg lines see
  // 0.08 / cos 45 = 0.113 m pieces (RQD 100 but for the ends).
  Face face;
  face.w = 6;
  face.h = 6;
  face.add_set({1, 0, 0}, 0.08, 0.05, "V");
  RockMassInput in;
  in.sets.push_back({"S1", {1, 0, 0}});
  in.traces = face.traces;
  in.outline_points = face.outline();
  const RockMassFigures f = rock_mass_figures(in);
  const auto& horizontal = f.scanlines.directions[0];
  const auto& vertical = f.scanlines.directions[1];
  const auto& inclined = f.scanlines.directions[2];
  EXPECT_NEAR(*horizontal.rqd_percent, 0, 1e-9);
  EXPECT_NEAR(horizontal.frequency_per_m, 75.0 / 6.0, 1e-9);  // 75 traces on each 6 m line
  EXPECT_NEAR(*horizontal.priest_hudson_from_frequency, 100 * std::exp(-1.25) * (1.25 + 1), 1e-9);
  EXPECT_NEAR(*vertical.rqd_percent, 100, 1e-9);
  EXPECT_EQ(vertical.crossings, 0);
  EXPECT_GT(*inclined.rqd_percent, 95);  // only end pieces under 0.1 m can be lost
  // Terzaghi along the horizontal line: apparent 0.08 (cos delta 1).
  EXPECT_NEAR(*horizontal.sets[0].corrected_m, 0.08, 1e-9);
  EXPECT_TRUE(vertical.sets[0].in_blind_zone);
}

TEST(RockMassFigures, RandomTracesAddToJvAndJn) {
  Face face;
  face.add_set(geometry::plane_normal_deg(60, 200), 0.8, 0.01, "A");
  face.add_set(geometry::plane_normal_deg(75, 110), 1.0, 0.02, "B");
  RockMassInput in;
  in.sets = {{"S1", geometry::plane_normal_deg(60, 200)},
             {"S2", geometry::plane_normal_deg(75, 110)}};
  in.traces = face.traces;
  // Two traces running nowhere near either set's direction on the face.
  for (int i = 0; i < 2; ++i) {
    FaceTrace t;
    t.label = "R" + std::to_string(i);
    t.points = {{1.0 + i, 0, 1.0}, {1.3 + i, 0, 3.0}};
    in.traces.push_back(t);
  }
  in.outline_points = face.outline();
  const RockMassFigures f = rock_mass_figures(in);
  ASSERT_EQ(f.assigned.random.size(), 2u);
  EXPECT_NEAR(f.jv.from_random, 2 / (5 * std::sqrt(72.0)), 1e-12);
  EXPECT_EQ(*f.q.jn.rating, 6);  // two sets plus random
}

}  // namespace
}  // namespace rockface::rockmass

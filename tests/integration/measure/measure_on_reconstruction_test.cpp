// Measuring on the 3D image end to end: the synthetic face of the
// reconstruction tests (three facets, range pole, compass line) with joints
// drawn as dark traces is rendered, reconstructed with the standard preset
// and registered; traces are then picked on the left photograph where the
// renderer drew them, and traced semi-automatically between their ends.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/common/units.h"
#include "core/measure/least_cost_trace.h"
#include "core/measure/plane_measurement.h"
#include "tests/support/synthetic_truth.h"

namespace rm = rockface::measure;
namespace rp = rockface::photogrammetry;
namespace rg = rockface::geometry;
using rockface::deg_to_rad;
using rockface::rad_to_deg;

namespace {

struct JointTruth {
  const char* id;
  double dip, dipdir;
  Eigen::Vector3d point;
};

// J1 crosses all three facets (its trace bends at the folds: relief);
// J2 is steep and stays on the middle facet (a straight trace on a flat face).
const JointTruth kJoints[] = {{"J1", 25, 30, {0.0, 10.0, 2.0}}, {"J2", 80, 270, {0.3, 10.0, 2.0}}};

struct Fixture {
  rockface::camera::SyntheticScene scene;
  rockface::camera::SyntheticRender render;
  rp::ReconstructionResult rec;
  rm::PhotoView left;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture f;
    f.scene = rockface::testing::synthetic_face();
    for (const auto& j : kJoints)
      f.scene.joints.push_back({j.id, rg::plane_normal_deg(j.dip, j.dipdir), j.point});
    rockface::NoProgress progress;
    f.render = rockface::camera::render_scene(f.scene, progress);
    f.rec = rp::reconstruct(f.render.images[0], f.render.images[1], f.render.intrinsics,
                            f.render.intrinsics, rp::preset_standard(),
                            rockface::testing::pole_and_compass(f.scene, f.render, 0.0), progress);
    f.left = rm::left_view(f.rec.model_to_world, f.render.intrinsics);
    return f;
  }();
  return f;
}

// The true trace of a joint in the left image: its pieces on each facet,
// west to east, kept `margin` px inside the image and the facets' ends.
std::vector<std::vector<Eigen::Vector2d>> true_pieces(const Fixture& f, const std::string& joint) {
  std::vector<std::vector<Eigen::Vector2d>> pieces;
  for (const auto& t : f.render.traces) {
    if (t.joint != joint) continue;
    std::vector<Eigen::Vector2d> px;
    const std::size_t n = t.left_image.size(), cut = n / 20;  // 5 % off each end
    for (std::size_t i = cut; i + cut < n; ++i) {
      const auto& p = t.left_image[i];
      if (p.x() > 10 && p.y() > 10 && p.x() < f.render.intrinsics.width - 10 &&
          p.y() < f.render.intrinsics.height - 10)
        px.push_back(p);
    }
    if (px.size() < 2) continue;
    if (px.front().x() > px.back().x()) std::reverse(px.begin(), px.end());
    pieces.push_back(px);
  }
  std::sort(pieces.begin(), pieces.end(),
            [](const auto& a, const auto& b) { return a.front().x() < b.front().x(); });
  return pieces;
}

double distance_to(const std::vector<Eigen::Vector2d>& line, const Eigen::Vector2d& p) {
  double best = 1e9;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Eigen::Vector2d a = line[i - 1], b = line[i];
    const double t =
        std::clamp((p - a).dot(b - a) / std::max(1e-12, (b - a).squaredNorm()), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - p).norm());
  }
  return best;
}

rm::MeasureSettings settings_of(const rp::ReconstructionResult& rec) {
  rm::MeasureSettings s;
  s.point_sigma = rec.accuracy.sigma_z;
  // Neighbouring points share the dense-matching window (5 px at the dense
  // scale, one lattice step per pixel).
  s.correlation_length = rec.point_spacing * rp::preset_standard().sgbm_block_size;
  return s;
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

}  // namespace

TEST(MeasureOnReconstruction, TraceAcrossFacetsGivesTheJointWithinOneDegree) {
  const Fixture& f = fixture();
  const rm::MeshPicker picker(f.rec.mesh);
  std::vector<Eigen::Vector2d> taps;  // a geologist's taps: every 40th pixel of the drawn trace
  for (const auto& piece : true_pieces(f, "J1"))
    for (std::size_t i = 0; i < piece.size(); i += std::max<std::size_t>(1, piece.size() / 8))
      taps.push_back(piece[i]);
  ASSERT_GE(taps.size(), 12u);
  const auto t = rm::measure_trace(picker, f.left, "J1", taps, settings_of(f.rec), "traces[0]");
  ASSERT_TRUE(t.plane.known) << t.plane.problem;
  const double error = angle_deg(t.plane.fit.normal, f.scene.joints[0].normal);
  // Expected error: sigma_Z of the reconstruction (1.4 cm at 10 m) over the
  // trace's relief (0.4 m RMS across its line) and its ~80 independent
  // points (one per matching window): the fit's own sigma, 0.15 deg; the
  // registration adds its vertical and north errors (0.06 deg here,
  // integration/reconstruct) and the picks on a 2 px dark line a little
  // bias of the dense matching. Seen: 0.4 deg. The picks that cross the
  // steps between facets are dropped by the robust fit.
  std::printf(
      "J1 measured %.2f/%.1f, true 25/30, error %.3f deg, predicted sigma %.3f deg, "
      "sigma_Z %.4f m, %zu points\n",
      rad_to_deg(t.plane.orientation.dip), rad_to_deg(t.plane.orientation.dipdir), error,
      rad_to_deg(t.plane.sigma), f.rec.accuracy.sigma_z, t.points.size());
  EXPECT_LT(error, 1.0);
  EXPECT_LT(rad_to_deg(t.plane.sigma), 0.5);
  EXPECT_NEAR(rad_to_deg(t.plane.orientation.dip), 25, 1.0);
  EXPECT_NEAR(rad_to_deg(t.plane.orientation.dipdir), 30, 1.0 / std::sin(deg_to_rad(25)));
}

TEST(MeasureOnReconstruction, StraightTraceOnAFacetIsOrientationUnknown) {
  const Fixture& f = fixture();
  const rm::MeshPicker picker(f.rec.mesh);
  const auto pieces = true_pieces(f, "J2");
  ASSERT_EQ(pieces.size(), 1u);  // the middle facet only
  std::vector<Eigen::Vector2d> taps;
  for (std::size_t i = 0; i < pieces[0].size(); i += pieces[0].size() / 6)
    taps.push_back(pieces[0][i]);
  const auto t = rm::measure_trace(picker, f.left, "J2", taps, settings_of(f.rec), "traces[1]");
  EXPECT_FALSE(t.plane.known) << "fitted " << rad_to_deg(t.plane.orientation.dip) << "/"
                              << rad_to_deg(t.plane.orientation.dipdir);
  EXPECT_NE(t.plane.problem.find("orientation unknown"), std::string::npos);
}

TEST(MeasureOnReconstruction, SemiAutomaticTraceFindsTheRenderedTrace) {
  const Fixture& f = fixture();
  for (const auto& piece : true_pieces(f, "J1")) {
    rm::TraceRequest r;
    r.from = piece.front();
    r.to = piece.back();
    const auto path = rm::trace_between(f.render.images[0], &f.rec.mesh, r, "J1");
    double sum = 0;
    for (const auto& p : path.pixels) sum += distance_to(piece, p);
    const double mean = sum / static_cast<double>(path.pixels.size());
    // The path runs on whole pixels along a ~2 px dark line in sensor noise:
    // about half a pixel from its centre line.
    EXPECT_LT(mean, 2.0) << "piece from " << r.from.transpose();
    std::printf("semi-automatic trace of %.0f px: mean distance %.2f px\n", (r.to - r.from).norm(),
                mean);
  }
}

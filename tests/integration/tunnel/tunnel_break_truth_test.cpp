// Issue 38: over- and underbreak of a round against the truth of the
// rendered heading itself (its breaks as the scene defines them, integrated
// by camera/synthetic_tunnel's closed description, never by the measurement
// under test). Two headings: the project's sample (horseshoe, one overbreak
// on the right shoulder, one underbreak on the left wall) and a second one
// of another shape (a D: flat invert, vertical walls, a semicircular crown),
// another lens, texture and sensor noise, with two overbreaks and one
// underbreak. Each is replayed through the mock camera at the standard
// preset, placed by the typed chainage of its range pole and measured by
// `visit_profile` as `rockface profile` does.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "camera/synthetic_tunnel.h"
#include "core/common/progress.h"
#include "firmware-app/replay/field_replay.h"
#include "firmware-app/tunnel/rendered_tunnel.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "firmware-app/tunnel/visit_surface.h"
#include "storage/project/project_store.h"
#include "storage/scene/scene.h"
#include "tests/support/test_paths.h"
#include "tests/support/tunnel_drive_scene.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The second heading: the same alignment (straight and level, chainage c at
// northing 5211800 + c, the axis at 410 m), a D-shaped profile 5.0 m wide
// and 5.0 m high, the face at chainage 62 seen from chainage 53 through a
// wider lens (fx 600 on 1200 px), another rock texture and a noisier sensor.
// Along the outline (s from the invert's centre, counter-clockwise seen in
// the drive direction): right invert 0-2.5, right wall 2.5-5.0, crown arc
// 5.0-12.854, left wall 12.854-15.354, left invert 15.354-17.854.
json d_heading_scene() {
  json s = test::tunnel_drive_scene();
  s["name"] = "second heading: D profile, face at chainage 62";
  s["tunnel"]["profile"] = {
      {"format", "rockface-tunnel-profile/1"},
      {"name", "D 5.0 x 5.0 m (crown r 2.5)"},
      {"ray_centre", {0.0, 0.5}},
      {"segments",
       {{{"line", {{"from", {0.0, -1.5}}, {"to", {2.5, -1.5}}}}},
        {{"line", {{"from", {2.5, -1.5}}, {"to", {2.5, 1.0}}}}},
        {{"arc",
          {{"centre", {0.0, 1.0}}, {"radius", 2.5}, {"start_deg", 0.0}, {"end_deg", 180.0}}}},
        {{"line", {{"from", {-2.5, 1.0}}, {"to", {-2.5, -1.5}}}}},
        {{"line", {{"from", {-2.5, -1.5}}, {"to", {0.0, -1.5}}}}}}}};
  s["tunnel"]["placement"] = {{"chainage", 60.0}, {"offset", 1.2}, {"height", -0.95}};
  s["tunnel"]["render"] = {
      {"from_chainage", 45.0},
      {"face_chainage", 62.0},
      {"section_m", 0.2},
      {"facet_m", 0.1},
      {"face_relief_m", 0.3},
      {"breaks",
       {{{"chainage", {56.5, 58.5}}, {"s", {3.0, 4.8}}, {"depth_m", 0.30}},
        {{"chainage", {58.4, 60.8}}, {"s", {9.6, 11.6}}, {"depth_m", 0.18}},
        {{"chainage", {57.0, 59.2}}, {"s", {13.2, 14.9}}, {"depth_m", -0.10}}}}};
  const double e = 512340.0, n = 5211800.0;
  auto& cam = s["imaging"]["camera"];
  cam["fx"] = cam["fy"] = 600.0;
  s["imaging"]["stations"] =
      json::array({{{"position", {e - 0.7, n + 53.0, 410.1}}, {"look_at", {e, n + 62.0, 410.6}}},
                   {{"position", {e + 0.7, n + 53.0, 410.1}}, {"look_at", {e, n + 62.0, 410.6}}}});
  s["imaging"]["range_pole"] = {
      {"base", {e + 1.2, n + 60.0, 409.05}}, {"length", 2.0}, {"target_diameter", 0.25}};
  s["imaging"]["reference_line"] = {{"from", {e - 1.5, n + 62.0, 410.0}},
                                    {"to", {e + 1.5, n + 62.0, 410.0}}};
  s["imaging"]["effects"] = {
      {"distortion", true}, {"noise_sigma", 2.5}, {"blur_px", 0.7}, {"exposure", 0.9}};
  s["imaging"]["texture_seed"] = 29;
  return s;
}

struct Heading {
  fs::path scene_file, project;
  ReplayOutcome outcome;
};

Heading replay_heading(const fs::path& dir, const std::string& name, const json& scene) {
  Heading h;
  h.scene_file = dir / (name + ".scene.json");
  h.project = dir / (name + ".rockface");
  std::ofstream(h.scene_file) << scene.dump(2);
  NoProgress quiet;
  h.outcome = replay_field_workflow(
      {h.scene_file.string(), h.project.string(), Preset::standard, {}, {}, {}}, quiet);
  return h;
}

// Whether both photographs see a point (survey coordinates): in front of
// each station and inside its frame, by the scene's pinhole (a station looks
// from `position` at `look_at` without roll, image x horizontal to the
// right; docs: SCENE.md "imaging"). The lens distortion (k1 -0.05) moves the
// frame's edge by a few pixels and is left out.
bool both_photographs_see(const storage::Scene& scene, const Eigen::Vector3d& point) {
  const auto& cam = scene.imaging->camera;
  for (int k = 0; k < 2; ++k) {
    const auto& station = scene.imaging->stations[static_cast<std::size_t>(k)];
    const Eigen::Vector3d forward = (station.look_at - station.position).normalized();
    const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
    const Eigen::Vector3d down = forward.cross(right);
    const Eigen::Vector3d x = point - station.position;
    const double z = x.dot(forward);
    if (z <= 0) return false;
    const double col = cam.fx * x.dot(right) / z + cam.cx, row = cam.fy * x.dot(down) / z + cam.cy;
    if (col < 0 || row < 0 || col > cam.width - 1 || row > cam.height - 1) return false;
  }
  return true;
}

// The truth over the round the measurement chose and over what both
// photographs see of it (the scene's geometry, not the reconstruction):
// volumes integrated from the scene's breaks (2 cm of chainage by 2 cm of
// outline, each piece integrated every millimetre by camera/synthetic_tunnel
// and kept when both photographs see its centre), and the deepest over- and
// underbreak at the centre of their break (the breaks do not overlap, so
// each one's deepest point is its centre).
struct RoundTruth {
  double over_m3 = 0, under_m3 = 0;
  double whole_over_m3 = 0, whole_under_m3 = 0;  // seen or not
  double max_over_m = 0, max_under_m = 0;
  double over_chainage = 0, over_s = 0, under_chainage = 0, under_s = 0;
};

RoundTruth round_truth(const Heading& h, const VisitProfile& measured,
                       const tunnel::Alignment& alignment) {
  const storage::Scene scene = storage::load_scene(h.scene_file.string());
  const camera::RenderedTunnelSpec spec = rendered_tunnel_spec(*scene.tunnel->render);
  const tunnel::DesignProfile& profile = measured.tunnel.profile;
  RoundTruth t;
  const double lo = std::min(measured.round_from, measured.round_to);
  const double hi = std::max(measured.round_from, measured.round_to);
  const double dc = 0.02, ds = 0.02, perimeter = profile.perimeter();
  for (double c = lo + dc / 2; c < hi; c += dc) {
    const tunnel::TunnelFrame frame = alignment.frame_at(c);
    for (double s0 = 0; s0 < perimeter; s0 += ds) {
      const double s1 = std::min(perimeter, s0 + ds), s = (s0 + s1) / 2;
      const auto piece = camera::rendered_section_truth(spec, profile, c, s0, s1);
      t.whole_over_m3 += piece.overbreak_m2 * dc;
      t.whole_under_m3 += piece.underbreak_m2 * dc;
      if (piece.overbreak_m2 == 0 && piece.underbreak_m2 == 0) continue;
      const Eigen::Vector2d uv =
          profile.point_at_length(s) +
          camera::rendered_deviation(spec, c, s) * profile.outward_normal_at_length(s);
      if (!both_photographs_see(scene, alignment.to_survey(frame.to_local(uv.x(), uv.y()))))
        continue;
      t.over_m3 += piece.overbreak_m2 * dc;
      t.under_m3 += piece.underbreak_m2 * dc;
    }
  }
  for (const auto& b : spec.breaks) {
    const double c = (b.chainage_from + b.chainage_to) / 2, s = (b.s_from + b.s_to) / 2;
    if (b.depth_m > t.max_over_m) {
      t.max_over_m = b.depth_m;
      t.over_chainage = c;
      t.over_s = s;
    }
    if (-b.depth_m > t.max_under_m) {
      t.max_under_m = -b.depth_m;
      t.under_chainage = c;
      t.under_s = s;
    }
  }
  return t;
}

// How much of the lining both photographs see the 3D image holds (issue
// 38: the sample's covered ~30 %). The true lining is the scene's: the
// design outline displaced by the rendered breaks, sampled every 5 cm of
// chainage and outline from the rendered walls' far end to 0.25 m short of
// the face's bulge (nearer, a ray toward the lining may meet the face), and
// kept where both photographs see it. A sample is covered when the ray from
// the section's ray centre toward it meets the mesh within 5 cm of it (the
// 3D image's depth error at the walls is ~1 cm; a hole meets something
// farther or nothing).
struct LiningCoverage {
  int seen = 0, covered = 0;
  int seen_by_part[3] = {0, 0, 0}, covered_by_part[3] = {0, 0, 0};  // invert, walls, roof
  // The depth error of the covered samples along the ray (the mesh's hit
  // less the true lining's distance): sum and sum of squares, per part.
  double error_sum[3] = {0, 0, 0}, error_sq[3] = {0, 0, 0};
  double fraction() const { return seen ? static_cast<double>(covered) / seen : 0; }
};

LiningCoverage lining_coverage(const Heading& h) {
  storage::ProjectStore store = storage::ProjectStore::open(h.project);
  const storage::Scene scene = storage::load_scene(h.scene_file.string());
  const camera::RenderedTunnelSpec spec = rendered_tunnel_spec(*scene.tunnel->render);
  const auto tunnel = store.load_tunnel();
  const tunnel::Alignment alignment = tunnel->alignment(store.project().datum);
  const tunnel::DesignProfile& profile = tunnel->profile;
  const VisitSurface surface = visit_surface(store, h.outcome.visit_id);
  const tunnel::MeshRaycaster mesh(surface.vertices, surface.triangles);
  const double kStepM = 0.05, kCoveredWithinM = 0.05;
  const double from = spec.chainage_from, to = spec.face_chainage - spec.face_relief_m - 0.25;
  const double centre_v = profile.ray_centre().y();
  LiningCoverage out;
  for (double c = from + kStepM / 2; c < to; c += kStepM) {
    const tunnel::TunnelFrame frame = alignment.frame_at(c);
    const Eigen::Vector3d centre = frame.to_local(profile.ray_centre().x(), centre_v);
    for (double s = kStepM / 2; s < profile.perimeter(); s += kStepM) {
      const Eigen::Vector2d uv =
          profile.point_at_length(s) +
          camera::rendered_deviation(spec, c, s) * profile.outward_normal_at_length(s);
      const Eigen::Vector3d p = frame.to_local(uv.x(), uv.y());
      if (!both_photographs_see(scene, alignment.to_survey(p))) continue;
      const int part = uv.y() < profile.point_at_length(0).y() + 0.3 ? 0
                       : uv.y() < centre_v                           ? 1
                                                                     : 2;
      ++out.seen;
      ++out.seen_by_part[part];
      const double r = (p - centre).norm();
      const auto hit = mesh.first_hit(centre, (p - centre) / r, 0.0, r + 1.0);
      if (hit && std::abs(hit->t - r) < kCoveredWithinM) {
        ++out.covered;
        ++out.covered_by_part[part];
        out.error_sum[part] += hit->t - r;
        out.error_sq[part] += (hit->t - r) * (hit->t - r);
      }
    }
  }
  return out;
}

// Distance between two places on the developed view (chainage and arc
// length, both in metres of excavated surface), the arc length wrapping
// round the outline.
double developed_distance(double c1, double s1, double c2, double s2, double perimeter) {
  double ds = std::fmod(std::abs(s1 - s2), perimeter);
  ds = std::min(ds, perimeter - ds);
  return std::hypot(c1 - c2, ds);
}

// NOT YET MET (disabled, issue 38 left open): measured on 2026-11-29 at the
// standard preset with the disparity map's small holes filled, the sample
// heading's largest over- and underbreak are within 3 cm and 0.5 m (0.355 m
// at 109.98 / 5.97 for 0.35 at 110.1 / 6; 0.112 m at 109.98 / 15.75 for
// 0.12 at 110.2 / 15.7), but its volumes are not within 10 % (overbreak
// 0.58 for 0.76 m3: the 3D image covers 46 % of the lining the photographs
// both see, the coverage tests below; underbreak 0.143 for 0.129 m3, +11 %);
// on the D heading the largest overbreak is 0.255 m at 57.70 / 3.87 for 0.30
// at 57.5 / 3.9 (before the holes were filled a sheet 2.2 m below the left
// invert was counted), overbreak 0.37 for 0.49 m3, underbreak 0.33 for
// 0.09 m3, the largest underbreak 0.247 m at 59.39 / 6.26 for 0.10 at
// 58.1 / 14.05 (the terraces of dense matching on the grazing walls read as
// underbreak). Run with --gtest_also_run_disabled_tests to see the figures.
class TunnelBreakTruth : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("rockface-break-truth-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    sample_ = new Heading(replay_heading(dir_, "sample", test::tunnel_drive_scene()));
    d_heading_ = new Heading(replay_heading(dir_, "d-heading", d_heading_scene()));
  }
  static void TearDownTestSuite() {
    delete sample_;
    delete d_heading_;
    fs::remove_all(dir_);
  }

  // The figures of issue 38: both volumes within 10 % of the truth, the
  // largest over- and underbreak within 3 cm of their depth and 0.5 m of
  // their place.
  static void expect_the_truth(const Heading& h, const std::string& name) {
    storage::ProjectStore store = storage::ProjectStore::open(h.project);
    const VisitProfile m = visit_profile(store, h.outcome.visit_id, Preset::standard);
    const auto& d = m.deviation;
    // The cameras look along the heading: the sections see the walls and
    // the shoulders, not the whole outline (partly seen is what they say).
    ASSERT_NE(d.status, tunnel::DeviationStatus::no_walls_in_view) << name << ": " << d.message;
    const RoundTruth t = round_truth(h, m, m.tunnel.alignment(store.project().datum));
    const double perimeter = m.tunnel.profile.perimeter();
    std::cout << name << ": round " << m.round_from << " to " << m.round_to << "; overbreak "
              << d.overbreak_volume_m3 << " m3 (true " << t.over_m3 << "), underbreak "
              << d.underbreak_volume_m3 << " m3 (true " << t.under_m3 << "; over the whole outline "
              << t.whole_over_m3 << " / " << t.whole_under_m3 << "); largest overbreak "
              << d.max_overbreak_m << " m at " << d.max_overbreak.chainage << " / "
              << d.max_overbreak.s << " (true " << t.max_over_m << " at " << t.over_chainage
              << " / " << t.over_s << "), largest underbreak " << d.max_underbreak_m << " m at "
              << d.max_underbreak.chainage << " / " << d.max_underbreak.s << " (true "
              << t.max_under_m << " at " << t.under_chainage << " / " << t.under_s << ")\n"
              << "  " << d.message << "\n";
    // The truth is a real break in the round (else the test says nothing).
    ASSERT_GT(t.over_m3, 0.1) << name;
    ASSERT_GT(t.under_m3, 0.02) << name;
    // Volumes: 10 % is issue 38's requirement; the reconstruction's depth
    // error over a break (a few mm on 0.1-0.35 m deep bumps) and the
    // dense matching's smoothing of their flanks must stay within it.
    EXPECT_NEAR(d.overbreak_volume_m3, t.over_m3, 0.1 * t.over_m3) << name;
    EXPECT_NEAR(d.underbreak_volume_m3, t.under_m3, 0.1 * t.under_m3) << name;
    // The largest of each: 3 cm of depth (a cell's depth error, ~1 cm at the
    // walls' distance, plus the smoothing of a crest), 0.5 m of place (the
    // crest of a sin^2 bump is flat: within 1 cm of its depth over +-0.1 of
    // its width).
    EXPECT_NEAR(d.max_overbreak_m, t.max_over_m, 0.03) << name;
    EXPECT_LT(developed_distance(d.max_overbreak.chainage, d.max_overbreak.s, t.over_chainage,
                                 t.over_s, perimeter),
              0.5)
        << name;
    ASSERT_TRUE(d.has_underbreak) << name;
    EXPECT_NEAR(d.max_underbreak_m, t.max_under_m, 0.03) << name;
    EXPECT_LT(developed_distance(d.max_underbreak.chainage, d.max_underbreak.s, t.under_chainage,
                                 t.under_s, perimeter),
              0.5)
        << name;
  }

  static void expect_coverage(const Heading& h, const std::string& name) {
    const LiningCoverage c = lining_coverage(h);
    std::cout << name << ": the 3D image covers " << c.covered << " of " << c.seen
              << " samples of the lining both photographs see (" << 100 * c.fraction()
              << " %); invert " << c.covered_by_part[0] << "/" << c.seen_by_part[0] << ", walls "
              << c.covered_by_part[1] << "/" << c.seen_by_part[1] << ", roof "
              << c.covered_by_part[2] << "/" << c.seen_by_part[2] << "\n";
    const char* part_name[3] = {"invert", "walls", "roof"};
    for (int p = 0; p < 3; ++p)
      if (c.covered_by_part[p] > 0)
        std::cout << "  " << part_name[p] << ": depth error along the ray, mean "
                  << 1000 * c.error_sum[p] / c.covered_by_part[p] << " mm, rms "
                  << 1000 * std::sqrt(c.error_sq[p] / c.covered_by_part[p]) << " mm\n";
    ASSERT_GT(c.seen, 1000) << name;
    EXPECT_GT(c.fraction(), 0.9) << name;
  }

  static inline fs::path dir_;
  static inline Heading* sample_ = nullptr;
  static inline Heading* d_heading_ = nullptr;
};

// Issue 38: both photographs see every break, so the 3D image must hold the
// lining they see. 90 %: the range pole and its targets hide ~2 % of it,
// the rectified images' border (alpha 0) and the SGBM window's margin
// ~3-5 % at the frame's edge.
// NOT YET MET (disabled): on 2026-11-29 at standard the sample's image
// covers 46 % (35 % before small holes of the disparity map were filled:
// invert 46 %, walls 33 %, roof 54 %), the D heading's 26 % (17 %). What
// loses the rest, seen on the sample's disparity map: (1) semi-global
// matching follows a wall or invert seen at a grazing angle (0.5-0.8 px of
// disparity per px) as terraces, flat runs and 3-5 px steps (the penalty of
// one jump, P2 = 4 P1, is cheaper than the 1 px steps), and the lattice
// mesh cuts every step (max_jump_px 1.5): with P1 2 / P2 64 (and (2)'s
// padding) the sample covers 59 % and the D heading 40 %; (2) SGBM leaves the first min + num
// and the last -min columns of the rectified image unmatched, the near
// walls (padding the pair there gave +3 %, but it maps the stepped face's
// partly-seen right strip without a facet: FacetsOnReconstruction).
TEST_F(TunnelBreakTruth, DISABLED_TheSampleHeadingsImageCoversTheLiningBothPhotographsSee) {
  expect_coverage(*sample_, "sample heading");
}

TEST_F(TunnelBreakTruth, DISABLED_TheSecondHeadingsImageCoversTheLiningBothPhotographsSee) {
  expect_coverage(*d_heading_, "D heading");
}

TEST_F(TunnelBreakTruth, DISABLED_TheSampleHeadingsVolumesAndLargestBreaksMatchItsScene) {
  expect_the_truth(*sample_, "sample heading");
}

TEST_F(TunnelBreakTruth, DISABLED_ASecondHeadingOfAnotherShapeAndTextureMatchesItsScene) {
  expect_the_truth(*d_heading_, "D heading");
}

}  // namespace
}  // namespace rockface::app

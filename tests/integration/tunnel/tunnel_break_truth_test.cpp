// Issue 38: over- and underbreak of a round against the truth of the
// rendered heading itself (its breaks as the scene defines them, integrated
// by camera/synthetic_tunnel's closed description, never by the measurement
// under test). Two headings: the project's sample (horseshoe, one overbreak
// on the right shoulder, one underbreak on the left wall) and a second one
// of another shape (a D: flat invert, vertical walls, a semicircular crown),
// another lens, texture and sensor noise, with two overbreaks and one
// underbreak. Each is replayed through the mock camera at the standard
// preset, registered and placed by five monitoring targets of the tunnel's
// survey (imaging.control_targets: ground control) and measured by
// `visit_profile` as `rockface profile` does. A round's volumes need the
// 3D image placed to a few hundredths of a degree: a quarter of a degree
// moves them by tens of percent, and the compass line read from this 3D
// image turns it by 0.14-0.22 deg (docs/accuracy-cost.md, issue 38).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "camera/synthetic_tunnel.h"
#include "core/common/progress.h"
#include "core/common/units.h"
#include "firmware-app/render/synthetic_scene_from_scene.h"
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

// The tunnel surveyor's monitoring targets instead of the range pole and
// the compass line: five targets 0.15 m across on bolts 0.2 m off the
// design lining (clear of the rock where a break leaves it inside the
// design), on both walls and the crown, each given as (chainage, offset,
// height) on the straight, level alignment (chainage c at northing
// 5211800 + c, the axis at 410 m). Each is tapped at its centre's pixel in
// the left photograph (field_replay.h).
json with_monitoring_targets(json s, const std::vector<std::array<double, 3>>& places) {
  s["imaging"].erase("range_pole");
  s["imaging"].erase("reference_line");
  s["tunnel"].erase("placement");
  json targets = json::array();
  for (std::size_t k = 0; k < places.size(); ++k) {
    const auto& [c, u, v] = places[k];
    targets.push_back({{"id", "M" + std::to_string(k + 1)},
                       {"position", {512340.0 + u, 5211800.0 + c, 410.0 + v}},
                       {"diameter", 0.15}});
  }
  s["imaging"]["control_targets"] = targets;
  return s;
}

// The sample heading (horseshoe, walls at offset +-2.9 m at the axis's
// height, crown 4.0 m above it) photographed from chainage 104.
json sample_heading_scene() {
  return with_monitoring_targets(test::tunnel_drive_scene(), {{109.0, -2.7, 0.5},
                                                              {111.0, -2.7, -0.3},
                                                              {109.5, 2.7, 0.5},
                                                              {111.0, 2.7, -0.5},
                                                              {110.5, 0.0, 3.8}});
}

// The D heading (walls at +-2.5 m, crown 3.5 m above the axis)
// photographed from chainage 53.
json d_heading_with_targets() {
  return with_monitoring_targets(d_heading_scene(), {{57.0, -2.3, 0.0},
                                                     {60.0, -2.3, -0.8},
                                                     {56.0, 2.3, 0.0},
                                                     {59.5, 2.3, -0.8},
                                                     {58.5, 0.0, 3.3}});
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

// Whether the scene's own lining hides `point` (survey coordinates, on the
// lining) from a station: the ray from the station is marched (1 cm steps
// over its last 3 m, where a break's lip or an underbreak's bulge can stand
// in the way of a grazing ray; 5 cm before) and hidden when a sample lies
// beyond the true outline of its section (the design outline moved by the
// scene's deviation along its normal, met along the ray from the profile's
// ray centre). The last 3 cm, the point's own surface, are not tested.
bool lining_hides(const camera::RenderedTunnelSpec& spec, const tunnel::DesignProfile& profile,
                  const tunnel::Alignment& alignment, const Eigen::Vector3d& station,
                  const Eigen::Vector3d& point) {
  const Eigen::Vector3d ray = point - station;
  const double length = ray.norm();
  const Eigen::Vector2d centre = profile.ray_centre();
  for (double d = 0.5; d < length - 0.03; d += (length - d > 3.0 ? 0.05 : 0.01)) {
    const Eigen::Vector3d q = station + ray * (d / length);
    const tunnel::AlignmentPlace place = alignment.place_survey(q);
    if (place.chainage < spec.chainage_from || place.chainage > spec.face_chainage) continue;
    const Eigen::Vector2d uv(place.offset, place.height);
    const Eigen::Vector2d from_centre = uv - centre;
    const double r = from_centre.norm();
    if (r < 1e-6) continue;
    const tunnel::ProfileHit hit = profile.ray_hit(std::atan2(from_centre.y(), from_centre.x()));
    const double along = std::max(0.2, (from_centre / r).dot(hit.outward_normal));
    const double outline =
        hit.distance + camera::rendered_deviation(spec, place.chainage, hit.s) / along;
    if (r > outline + 0.002) return true;
  }
  return false;
}

// The truth over the round the measurement chose and over what both
// photographs see of it, in their frames and not hidden by the lining
// itself (the scene's geometry, not the reconstruction):
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
      const Eigen::Vector3d point = alignment.to_survey(frame.to_local(uv.x(), uv.y()));
      if (!both_photographs_see(scene, point) ||
          lining_hides(spec, profile, alignment, scene.imaging->stations[0].position, point) ||
          lining_hides(spec, profile, alignment, scene.imaging->stations[1].position, point))
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

// The developed view's cells against the scene's own deviation at their
// place (camera/synthetic_tunnel's closed description): how far the
// measured (and the interpolated) cells lie from the truth, and where the
// counted underbreak lies on lining the scene does not break inward: what
// a spurious underbreak is made of. Printed, for the figures in the docs.
void print_cells_against_truth(const Heading& h, const tunnel::ProfileDeviation& d,
                               const tunnel::DesignProfile& profile) {
  const storage::Scene scene = storage::load_scene(h.scene_file.string());
  const camera::RenderedTunnelSpec spec = rendered_tunnel_spec(*scene.tunnel->render);
  const auto& v = d.view;
  const std::size_t cols = v.s.size();
  {
    // The scene's volumes over the cells the round valued (measured or
    // interpolated), the trapezoid's weights along the chainage.
    const std::size_t rows = v.chainage.size();
    const double dc = rows > 1 ? v.chainage[1] - v.chainage[0] : 0.25;
    const double ds = cols > 1 ? v.s[1] - v.s[0] : 0.05;
    double over = 0, under = 0, over_measured = 0, under_measured = 0;
    for (std::size_t i = 0; i < rows; ++i) {
      const double w = (i == 0 || i + 1 == rows) ? 0.5 * dc : dc;
      for (std::size_t j = 0; j < cols; ++j) {
        const std::uint8_t st = v.state[i * cols + j];
        if (st != 0 && st != 4) continue;
        const auto piece = camera::rendered_section_truth(spec, profile, v.chainage[i],
                                                          v.s[j] - ds / 2, v.s[j] + ds / 2);
        over += piece.overbreak_m2 * w;
        under += piece.underbreak_m2 * w;
        if (st == 0) {
          over_measured += piece.overbreak_m2 * w;
          under_measured += piece.underbreak_m2 * w;
        }
      }
    }
    std::cout << "  the scene's volumes over the valued cells: overbreak " << over
              << " m3, underbreak " << under << " m3 (over the measured ones " << over_measured
              << " / " << under_measured << ")\n";
  }
  struct Tally {
    std::size_t cells = 0;
    double sum = 0, sq = 0;
  } measured, interpolated;
  struct Worst {
    double error = 0, c = 0, s = 0, value = 0, truth = 0;
    int state = 0;
  };
  std::vector<Worst> worst;
  for (std::size_t k = 0; k < v.state.size(); ++k) {
    if (v.state[k] != 0 && v.state[k] != 4) continue;
    const double c = v.chainage[k / cols], s = v.s[k % cols];
    const double truth = camera::rendered_deviation(spec, c, s), e = v.deviation_m[k] - truth;
    Tally& t = v.state[k] == 0 ? measured : interpolated;
    ++t.cells;
    t.sum += e;
    t.sq += e * e;
    worst.push_back({e, c, s, v.deviation_m[k], truth, v.state[k]});
  }
  for (const auto* t : {&measured, &interpolated})
    if (t->cells > 0)
      std::cout << "  " << (t == &measured ? "measured" : "interpolated") << " cells " << t->cells
                << ": error against the scene mean " << 1000 * t->sum / t->cells << " mm, rms "
                << 1000 * std::sqrt(t->sq / t->cells) << " mm\n";
  // Where the underbreak beyond the truth lies: per 0.5 m of chainage and
  // 1 m of outline, the measured and interpolated cells' underbreak less
  // the scene's (m3), the bins holding 5 litres or more.
  {
    const double cell_area = (v.chainage.size() > 1 ? v.chainage[1] - v.chainage[0] : 0.25) *
                             (cols > 1 ? v.s[1] - v.s[0] : 0.05);
    std::map<std::pair<int, int>, double> excess;
    for (const Worst& w : worst)
      excess[{static_cast<int>(std::floor(w.c / 0.5)), static_cast<int>(std::floor(w.s))}] +=
          (std::min(0.0, w.truth) - std::min(0.0, w.value)) * cell_area;
    std::cout << "  underbreak beyond the truth (chainage bin / s bin: m3):";
    for (const auto& [bin, m3] : excess)
      if (m3 > 0.005) std::cout << " " << 0.5 * bin.first << "/" << bin.second << ": " << m3 << ";";
    std::cout << "\n";
  }
  std::sort(worst.begin(), worst.end(),
            [](const Worst& a, const Worst& b) { return a.error < b.error; });
  std::cout << "  the cells most inside the truth (chainage / s: measured, truth, state):";
  for (std::size_t i = 0; i < std::min<std::size_t>(12, worst.size()); ++i)
    std::cout << " " << worst[i].c << "/" << worst[i].s << ": " << worst[i].value << ", "
              << worst[i].truth << ", " << worst[i].state << ";";
  std::cout << "\n";
  std::cout << "  the cells most outside the truth (chainage / s: measured, truth, state):";
  for (std::size_t i = 0; i < std::min<std::size_t>(12, worst.size()); ++i) {
    const Worst& w = worst[worst.size() - 1 - i];
    std::cout << " " << w.c << "/" << w.s << ": " << w.value << ", " << w.truth << ", " << w.state
              << ";";
  }
  std::cout << "\n";
}

// The measured cells' error against the scene, per band of depth and of the
// lining's orientation to the base, beside the depth precision the code
// predicted for each cell: how well the prediction follows the
// reconstruction's real spread. The bands are read from the scene itself:
// the design point of each cell seen from the left station (its depth along
// that station's optical axis) and the design outline's normal there against
// the stations' base (along it: the walls; across it: the roof's crown and
// the invert; between: the shoulders), since the matching's error differs
// most between those (lining_precision.h). Only cells on lining the scene leaves
// intact (no break within 0.3 m of the cell: a break's flank smoothed by the
// matching is not noise) and measured (not interpolated) enter.
struct PrecisionBand {
  std::vector<double> error, predicted;
};

struct PrecisionBands {
  static constexpr double kDepthEdges[4] = {5.0, 7.0, 9.0, 1e9};
  static constexpr double kAlongBaseEdges[3] = {0.3, 0.7, 1.01};
  PrecisionBand band[4][3];
  // The robust spread (1.4826 x the median absolute deviation about the
  // median) of a band's errors: the noise's sigma, not the few cells the
  // flank rule or a stray triangle put off.
  static double robust_sigma(std::vector<double> v) {
    if (v.empty()) return 0;
    auto median = [](std::vector<double> x) {
      std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2), x.end());
      return x[x.size() / 2];
    };
    const double m = median(v);
    for (double& x : v) x = std::abs(x - m);
    return 1.4826 * median(v);
  }
};

PrecisionBands precision_bands(const Heading& h, const VisitProfile& m,
                               const tunnel::Alignment& alignment) {
  const tunnel::ProfileDeviation& d = m.deviation;
  const tunnel::DesignProfile& profile = m.tunnel.profile;
  const storage::Scene scene = storage::load_scene(h.scene_file.string());
  const camera::RenderedTunnelSpec spec = rendered_tunnel_spec(*scene.tunnel->render);
  const auto& left = scene.imaging->stations[0];
  const Eigen::Vector3d axis = (left.look_at - left.position).normalized();
  const auto& v = d.view;
  const std::size_t cols = v.s.size();
  PrecisionBands out;
  const Eigen::Vector3d base_dir =
      (scene.imaging->stations[1].position - left.position).normalized();
  for (std::size_t k = 0; k < v.state.size(); ++k) {
    if (v.state[k] != 0) continue;
    const double c = v.chainage[k / cols], s = v.s[k % cols];
    bool intact = true;
    for (double dc : {-0.3, 0.0, 0.3})
      for (double ds : {-0.3, 0.0, 0.3})
        intact = intact && camera::rendered_deviation(spec, c + dc, s + ds) == 0;
    if (!intact) continue;
    const tunnel::TunnelFrame f = alignment.frame_at(c);
    const Eigen::Vector2d uv = profile.point_at_length(s), n2 = profile.outward_normal_at_length(s);
    const Eigen::Vector3d p = alignment.to_survey(f.to_local(uv.x(), uv.y()));
    const Eigen::Vector3d n = n2.x() * f.right + n2.y() * f.up;
    const Eigen::Vector3d ray = p - left.position;
    const double depth = ray.dot(axis), along_base = std::abs(n.dot(base_dir));
    int bz = 0, bc = 0;
    while (depth > PrecisionBands::kDepthEdges[bz]) ++bz;
    while (along_base > PrecisionBands::kAlongBaseEdges[bc]) ++bc;
    out.band[bz][bc].error.push_back(v.deviation_m[k] - camera::rendered_deviation(spec, c, s));
    out.band[bz][bc].predicted.push_back(m.cell_sigma_m.empty() ? 0.0 : m.cell_sigma_m[k]);
  }
  return out;
}

void print_precision_bands(const PrecisionBands& b) {
  const char* depth_name[4] = {"< 5 m", "5-7 m", "7-9 m", "> 9 m"};
  const char* kind_name[3] = {"roof crown / invert", "shoulders", "walls"};
  std::cout << "  measured cells on intact lining, error against the scene per band of depth "
               "(left station) and of the normal to the base (cells: robust sigma / predicted "
               "median, mm):\n";
  for (int z = 0; z < 4; ++z)
    for (int c = 0; c < 3; ++c) {
      const PrecisionBand& p = b.band[z][c];
      if (p.error.size() < 20) continue;
      std::vector<double> pred = p.predicted;
      std::nth_element(pred.begin(), pred.begin() + static_cast<std::ptrdiff_t>(pred.size() / 2),
                       pred.end());
      std::cout << "    " << depth_name[z] << ", " << kind_name[c] << ": " << p.error.size()
                << " cells, " << 1000 * PrecisionBands::robust_sigma(p.error) << " / "
                << 1000 * pred[pred.size() / 2] << "\n";
    }
}

// NOT YET MET (disabled, issue 38 left open): measured on 2026-11-29
// (fifth session) at the standard preset with the tunnel round's lining
// matched by the padded pair and the slanted passes (preset.h
// lining_along_the_drive) and holes up to 0.5 m interpolated: the sample's
// overbreak 0.792 m3 for 0.759 (+4 %, within 10 %), its largest over- and
// underbreak within 3 cm and 0.5 m (0.333 m at 110.01 / 5.97 for 0.35 at
// 110.1 / 6; 0.108 m at 110.25 / 15.80 for 0.12 at 110.2 / 15.7), but its
// underbreak 0.392 m3 for 0.129; the D heading's overbreak 0.556 for 0.490
// (+13 %), largest 0.287 m at 57.51 / 3.91 (0.30 at 57.5 / 3.9), underbreak
// 0.457 for 0.094, the largest 0.146 m at 59.45 / 6.31 where the scene has
// none (0.10 at 58.1 / 14.05). What the spurious underbreak is, read from
// the cells against the scene (print_cells_against_truth): the measured
// cells lie 18.2 mm rms from the truth on the sample and 14.2 mm on the D
// heading (the walls 22 / 13 mm along the ray), while the noise threshold is
// 2 sigma of the precision predicted at the face's depth (23.5 / 16.2 mm):
// the grazing walls' error is larger than the stated precision, so their
// noise passes the threshold and its flanks are counted; and on the D
// heading a cluster of cells 0.10-0.15 m inside a lining the scene leaves
// intact, chainage 58.7-60.4, s 2.9-7.3 (the right wall's top and the roof's
// shoulder, around the range pole at 60 / offset 1.2), not yet explained.
// Sixth session (2026-11-29): each cell's noise threshold now comes from its
// own predicted precision (lining_precision.h, checked against the cells'
// measured spread by the precision tests below), sigma 1.9-15 mm on the
// sample, 1.5-21 mm on the D heading (the face's single figure was 11.8 /
// 8.1 mm). The volumes do not come right with it: sample overbreak 0.812
// (+7 %), underbreak 0.408 for 0.129; D overbreak 0.565 (+15 %), underbreak
// 0.381 for 0.094, its largest still at 59.45 / 6.31. The spurious
// underbreak is not noise (the cells' robust spread is 2-24 mm) but
// systematic errors of 4-15 cm: on the sample at the near lip of the
// shoulder's overbreak (chainage 108-109.5, s 3-7: the cavity's near flank
// hidden from the cameras, the matching pulling its far flank toward the
// lip's depth, i.e. inside the lining); on the D heading in the right wall's
// top and shoulder 5-70 px right of the face's edge in the photographs (80-210
// px from the range pole's image, not the pole: its vertices are masked and
// no bad cell lies within 80 px of it). No threshold drawn from the
// precision can remove them; the matching there must.
// Seventh session (2026-11-29, helper tunnel38f): the robust patch rule
// (break_patches.h: a cell beyond the noise counts only inside a patch of
// its sign at least 3 sections by 5 rays, 0.74 x 0.25 m) and the round
// measured 0.4 m short of the face (visit_profile.cpp kFaceClearM, was
// 0.15) bring the D heading within every figure (overbreak 0.455 for 0.490,
// -7 %; underbreak 0.088 for 0.094, -6 %; largest underbreak 0.107 m at
// 57.99 / 14.44): its test is enabled. The sample's overbreak comes within
// 2 % (0.761 for 0.750) but its underbreak stays 0.307 m3 for 0.128: the
// cells beyond the truth lie over 1.5 m of chainage and 5 m of outline
// (chainage 108-109.5, s 2-7: the near right wall and shoulder, 4-5 m from
// the cameras at the right edge of the photographs, up to the overbreak's
// lip), a bias of 2-7 cm over metres, wider than any patch rule may drop
// without dropping real breaks. Tried and measured there without effect
// (docs/accuracy-cost.md, "Issue 38 (seventh session)"): pixels beside
// disparity jumps left out (radius 4 px: 0.390 m3; 12 px loses the D
// heading's reference line), pixels on disparity slopes over 0.9 px/px left
// out (0.366), four diagonal slanted passes added (0.404), a noise
// threshold from the cells' own local spread (0.405); without the slanted
// passes 0.289 (and the D heading's overbreak +69 %).
// Eighth session (2026-11-30, helper tunnel38g): the cause of the sample's
// bias is the registration's heading, not the matching. Checked against the
// renderer's truth (docs/accuracy-cost.md, "Issue 38 (eighth session)"):
// the relative pose is 0.016 deg off, the distortion models agree to 1e-13
// px, the true correspondences' vertical disparity is under 0.05 px, the
// matched disparity's median is 0.06 px off over the bad region (1 mm);
// but the model is turned 0.96 deg about the pole: the compass line's right
// end, read from its one nearest vertex, lies 20 px beside the range pole
// and was 59 mm too deep; the near right wall moved 2.5-3.5 cm inward, the
// left wall 3.2 cm outward. With each end read from the plane around it
// (surface_pick.h) the heading is 0.216 deg off and the sample's volumes
// read overbreak 0.663 m3 for 0.748 (-11 %), underbreak 0.142 for 0.128
// (+11 %; it was 0.307), largest overbreak 0.397 m at 109.27 / 5.02 (0.35
// at 110.1 / 6.0: 1.3 m off). Still disabled: a quarter of a degree of
// heading is what a 3 m compass line at 8 m read from this 3D image gives,
// and the volumes need less.
// Run with --gtest_also_run_disabled_tests to see the figures.
class TunnelBreakTruth : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("rockface-break-truth-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    sample_ = new Heading(replay_heading(dir_, "sample", sample_heading_scene()));
    d_heading_ = new Heading(replay_heading(dir_, "d-heading", d_heading_with_targets()));
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
              << "  " << d.message << "\n"
              << "  measured " << d.seen_fraction << ", interpolated " << d.interpolated_fraction
              << " of the cells; overbreak +- " << d.overbreak_volume_sigma_m3.value_or(-1)
              << " (interpolated " << d.interpolated_overbreak_m3 << "), underbreak +- "
              << d.underbreak_volume_sigma_m3.value_or(-1) << " (interpolated "
              << d.interpolated_underbreak_m3 << ")\n";
    print_cells_against_truth(h, d, m.tunnel.profile);
    if (m.cell_precision)
      std::cout << "  cell precision: " << m.cell_precision->model << ": "
                << 1000 * m.cell_precision->min_sigma_m << " to "
                << 1000 * m.cell_precision->max_sigma_m << " mm, median "
                << 1000 * m.cell_precision->median_sigma_m << " mm\n";
    print_precision_bands(precision_bands(h, m, m.tunnel.alignment(store.project().datum)));
    // Patches beyond the noise left out as noise are said, and only then.
    EXPECT_EQ(d.noise_patches > 0, d.message.find("beyond the noise left out") != std::string::npos)
        << name << ": " << d.noise_patches << " patches; " << d.message;
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

  // Issue 38: the noise threshold is only as good as the precision it is
  // drawn from. In every band of depth and incidence holding 100 measured
  // cells or more, the predicted sigma (the band's median) lies within a
  // factor 3 of the measured spread: the model takes the preset's disparity
  // precision (0.3 px) for every image, while the headings' sensor noise
  // (1.5 and 2.5 grey levels) and blur make the real one differ, and its
  // slant term is the spread of a uniform ramp over the window, not of the
  // matcher's own aggregation (docs/accuracy-cost.md, "Issue 38 (sixth
  // session)"). And at each depth where the walls' measured spread exceeds
  // the roof's crown and the invert's, their predicted sigma must too. The
  // face's single figure (the same for every cell) missed the sample's roof
  // and invert by a factor 5 and told no band from another on the D heading.
  static void expect_the_predicted_precision(const Heading& h, const std::string& name) {
    storage::ProjectStore store = storage::ProjectStore::open(h.project);
    const VisitProfile m = visit_profile(store, h.outcome.visit_id, Preset::standard);
    const PrecisionBands b = precision_bands(h, m, m.tunnel.alignment(store.project().datum));
    std::cout << name << ":\n";
    print_precision_bands(b);
    int bands = 0;
    auto predicted_of = [](const PrecisionBand& p) {
      std::vector<double> pred = p.predicted;
      std::nth_element(pred.begin(), pred.begin() + static_cast<std::ptrdiff_t>(pred.size() / 2),
                       pred.end());
      return pred[pred.size() / 2];
    };
    for (const auto& row : b.band) {
      for (const PrecisionBand& p : row) {
        if (p.error.size() < 100) continue;
        ++bands;
        const double predicted = predicted_of(p);
        const double measured = PrecisionBands::robust_sigma(p.error);
        EXPECT_LT(predicted, 3 * measured) << name << ": " << p.error.size() << " cells";
        EXPECT_GT(predicted, measured / 3) << name << ": " << p.error.size() << " cells";
      }
      // At the same depth the walls are less precise than the roof's crown
      // and the invert where the measured spread says so: the prediction
      // tells them apart (one figure for the image cannot).
      const PrecisionBand &across = row[0], &walls = row[2];
      if (across.error.size() >= 100 && walls.error.size() >= 100 &&
          PrecisionBands::robust_sigma(walls.error) > PrecisionBands::robust_sigma(across.error)) {
        EXPECT_GT(predicted_of(walls), predicted_of(across)) << name;
      }
    }
    EXPECT_GE(bands, 4) << name;  // the walls, the roof and the invert near and far
  }

  // Issue 38 (tunnel38g): the stored model's rotation into the project
  // frame against the truth. The model frame is the left camera's
  // (relative_orientation.h), so the true rotation is the left station's
  // camera-to-world rotation; what is left of their product is the
  // registration's error: about the vertical, its heading; about a
  // horizontal axis, its tilt. The sample heading's
  // near walls were measured 2.5-3.5 cm inside the lining and its left wall
  // 3.2 cm outside because the heading was 0.96 deg off: the compass line's
  // right end, read from its one nearest vertex, lies 20 px beside the range
  // pole and was 59 mm too deep (docs/accuracy-cost.md, "Issue 38 (eighth
  // session)").
  static void expect_the_true_heading(const Heading& h, const std::string& name) {
    storage::ProjectStore store = storage::ProjectStore::open(h.project);
    const photogrammetry::Similarity s =
        storage::similarity_of(store.load_model(h.outcome.model_id).registration);
    const SyntheticSceneInput synthetic =
        synthetic_scene_from_scene(storage::load_scene(h.scene_file.string()));
    const photogrammetry::CameraPose left =
        camera::station_pose(synthetic.scene.stations[0], "imaging.stations[0]");
    const Eigen::AngleAxisd error(s.R * left.R);
    const Eigen::Vector3d w = error.angle() * error.axis();  // world axes: east, north, up
    const double heading_deg = rad_to_deg(w.z()), tilt_deg = rad_to_deg(w.head<2>().norm());
    std::cout << name << ": registration's heading error " << heading_deg << " deg, tilt "
              << tilt_deg << " deg; " << h.outcome.registration << "\n";
    // Every monitoring target measured on itself in both photographs.
    EXPECT_NE(h.outcome.registration.find("(5 of 5 measured on their targets"), std::string::npos)
        << name << ": " << h.outcome.registration;
    // What the five monitoring targets allow (tenth session: they replaced
    // the pole and the compass line here, which turned these models 0.216
    // and 0.143 deg, docs/accuracy-cost.md "Issue 38 (tenth session)"):
    // each centre located to a tenth of a pixel at 5-7 m is
    // Z^2 x 0.1 px / (f B) = 3-4 mm of depth (fx 800 / 600, base 1.4 m), along
    // the view, i.e. along the drive; over targets +-2.3-2.7 m across, the
    // least-squares heading is good to ~3.5 mm / sqrt(4 x 2.5^2 m^2) = 0.04
    // deg, and the tilt alike (the crown target 3.3-3.8 m above the walls').
    // 0.1 deg: 2.5 sigma (measured: sample -0.019, D -0.027 deg; tilt 0.008
    // and 0.025 deg).
    EXPECT_LT(std::abs(heading_deg), 0.1) << name;
    EXPECT_LT(tilt_deg, 0.1) << name;
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

// A goal beyond issue 38's points, kept as the measure of what is left:
// issue 38 asks that every cross-section both photographs see be measured
// and those left out be said (the round starts where both see the lining,
// and says its partly seen sections, its sections left out and why: the
// volume tests below and ProfileDeviation.SectionsThatMeetNothingAtTheEnds
// AreLeftOutAndSaid), and its volumes within 10 % are met with what the 3D
// image holds (holes up to 0.75 m interpolated). This asks more: that the
// 3D image hold 90 % of the lining cells both photographs see.
// Both photographs see every break, so the 3D image should hold the
// lining they see. 90 %: the range pole and its targets hide ~2 % of it,
// the rectified images' border (alpha 0) and the SGBM window's margin
// ~3-5 % at the frame's edge.
// NOT YET MET (disabled): on 2026-11-29 (fifth session) at standard, with
// the tunnel round's lining matched by the padded pair and the slanted
// passes (preset.h lining_along_the_drive), the sample's image covers
// 74.2 % (invert 80 %, walls 72 %, roof 72 %; 46 % before), the D
// heading's 65.2 % (invert 66 %, walls 60 %, roof 67 %; 26 % before). What
// loses the rest (stop 55's prototype, docs/accuracy-cost.md): the
// selection among the passes' candidates, the D heading's near walls
// beyond the first pass's 256-disparity window, the far walls' 0.5 px for
// 5 cm; and a sample covered needs its depth within 5 cm, which the walls'
// 13-22 mm rms error mostly meets.
TEST_F(TunnelBreakTruth, DISABLED_TheSampleHeadingsImageCoversTheLiningBothPhotographsSee) {
  expect_coverage(*sample_, "sample heading");
}

TEST_F(TunnelBreakTruth, DISABLED_TheSecondHeadingsImageCoversTheLiningBothPhotographsSee) {
  expect_coverage(*d_heading_, "D heading");
}

TEST_F(TunnelBreakTruth, EachCellsPredictedPrecisionFollowsTheSampleHeadingsMeasuredSpread) {
  expect_the_predicted_precision(*sample_, "sample heading");
}

TEST_F(TunnelBreakTruth, EachCellsPredictedPrecisionFollowsTheSecondHeadingsMeasuredSpread) {
  expect_the_predicted_precision(*d_heading_, "D heading");
}

TEST_F(TunnelBreakTruth, TheSampleHeadingsModelIsRegisteredWithItsTrueHeading) {
  expect_the_true_heading(*sample_, "sample heading");
}

TEST_F(TunnelBreakTruth, TheSecondHeadingsModelIsRegisteredWithItsTrueHeading) {
  expect_the_true_heading(*d_heading_, "D heading");
}

// Tenth session: registered by five monitoring targets (heading error
// -0.019 deg, was 0.216) and holes filled up to 0.75 m, every figure was
// met here (overbreak 0.686 m3 for 0.748, -8.3 %; underbreak 0.116 for
// 0.128, -9.3 %) but the underbreak's margin was 0.7 % of its truth, and
// the test stayed disabled. Eleventh session (2026-11-30): a patch no
// deeper than the lining around it is rough is left out as noise
// (break_significance.h), a break's flanks are followed down to the design
// (break_flanks.h), a band at the round's ends shorter than the patch rule
// does not count (break_patches.h), and the lining's offset is the median
// of the cells within the noise (its breaks no longer pull it): overbreak
// 0.693 for 0.748 (-7.4 %), underbreak 0.118 for 0.128 (-7.7 %), largest
// 0.353 m at 110.02 / 5.92 and 0.108 m at 110.02 / 15.65. Run as another
// machine would run it, with OpenCV's SSE4 code paths instead of AVX2
// (OPENCV_CPU_DISABLE=AVX2,FMA3,AVX,FP16,POPCNT), every figure moved by 1 %
// or less (-8.4 %, -7.3 %); before these rules the second heading's
// underbreak moved from +6.6 % to +14.5 % so (docs/accuracy-cost.md,
// "Issue 38 (eleventh session)"). Enabled. What the remaining -7 % is:
// the breaks' crests read 8-10 % shallow (0.108 for 0.12 here, 0.092 for
// 0.10 on the D heading), the dense matching's smoothing of a bump.
TEST_F(TunnelBreakTruth, TheSampleHeadingsVolumesAndLargestBreaksMatchItsScene) {
  expect_the_truth(*sample_, "sample heading");
}

// Issue 38's figures on the second heading (enabled in the seventh
// session: see the comment above the fixture). NOT MET again since the
// eighth session (2026-11-30, helper tunnel38g, disabled): the compass
// line's ends are read from the plane around each pick (surface_pick.h), not
// from one vertex; the D heading's registration then turns 0.143 deg off the
// truth instead of -0.110, and its underbreak reads 0.127 m3 for 0.094
// (+36 %), its largest overbreak 0.322 m at 56.04 / 5.26 (0.30 at 57.5 /
// 3.9); overbreak 0.528 for 0.490 (+7.6 %). Its test passed with the
// single vertex because of that -0.11 deg: the volumes move by tens of
// percent for a quarter of a degree of heading, which is what the compass
// line can give (docs/accuracy-cost.md, "Issue 38 (eighth session)").
// Ninth session: the largest breaks from the crest's robust depth and stray
// pieces of cells left out. Both headings' largest over- and underbreak
// now meet 3 cm and 0.5 m; the volumes (sample / D, against the truth
// here): overbreak -11 % / +7.6 %, underbreak +11 % / +36 %. With the
// compass reading turned by the measured heading error (a diagnostic, not
// the product) the D heading meets every figure (overbreak 0.475 for
// 0.490, underbreak 0.0933 for 0.0935) and the sample reads overbreak
// 0.636 for 0.748 (0.690 over the cells it valued: a part of its pocket
// is hidden behind its own lip) and underbreak 0.114 for 0.128.
// Tenth session (2026-11-30): both headings registered and placed by five
// monitoring targets of the tunnel's survey (ground control, each target
// measured in both photographs: control_targets.h) instead of the pole and
// the compass line. Heading error -0.027 deg (was 0.143), and every figure
// is met: overbreak 0.498 m3 for 0.477 (+4 %; 0.500, +4.8 %, with holes
// filled up to 0.75 m), underbreak 0.0996 for 0.0935 (+7 %), largest overbreak 0.284 m at 57.38
// / 3.91 (0.30 at 57.5 / 3.9), largest underbreak 0.093 m at 58.11 / 14.09 (0.10 at 58.1 / 14.05).
// Enabled again. Eleventh session: that +7 % was the true underbreak read
// 8 % short plus 0.02 m3 of noise patches on the far walls and the crease
// by the face, which OpenCV's SSE4 code paths made +14.5 %: with the rules
// above (the sample's test), overbreak 0.476 for 0.477 (-0.2 %; SSE4
// -2.3 %), underbreak 0.0871 for 0.0935 (-6.9 %; SSE4 -8.0 %).
TEST_F(TunnelBreakTruth, ASecondHeadingOfAnotherShapeAndTextureMatchesItsScene) {
  expect_the_truth(*d_heading_, "D heading");
}

}  // namespace
}  // namespace rockface::app

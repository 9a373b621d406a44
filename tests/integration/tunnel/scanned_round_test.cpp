// Issue 43: a contractor's laser scan of a whole round (walls, roof, invert
// and the face) in survey coordinates, imported into a project with the
// tunnel and measured by `rockface profile`'s workflow (visit_profile):
// over- and underbreak against the truth of the surface the points were
// sampled from. The surface is the sample heading's scene (its alignment,
// design profile and break patches), displaced by camera/synthetic_tunnel's
// closed description of the breaks, never by the measurement under test;
// the points get a scanner's noise. Before issue 43's round meshing the
// cloud was meshed over its best plane (the round's walls fold over it) and
// an imported visit was not placed in the tunnel at all.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "camera/synthetic_tunnel.h"
#include "firmware-app/tunnel/rendered_tunnel.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "storage/project/project_store.h"
#include "storage/scene/scene.h"
#include "tests/support/cli_run.h"
#include "tests/support/tunnel_drive_scene.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr double kScannerNoiseM = 0.003;  // 1 sigma per axis: a phase scanner at 5-10 m
constexpr double kSpacingM = 0.025;       // points on a jittered 2.5 cm grid

struct ScannedRound {
  fs::path dir, project, cloud, scene_file;
  camera::RenderedTunnelSpec spec;
  storage::RecordId visit = 0;
  std::string import_out;
};

// The scan: the round's walls from 2 m behind the rendered walls' start to
// the face, every kSpacingM of chainage and outline (jittered by a quarter
// spacing), displaced by the scene's breaks along the outline's normal; the
// face a plane at its chainage, sampled inside the design outline; each
// point moved by the scanner's noise; written in survey coordinates with
// 0.1 mm, as a scanner's XYZ export.
ScannedRound scan_round() {
  ScannedRound r;
  r.dir = fs::temp_directory_path() / ("rockface-scanned-round-" + std::to_string(::getpid()));
  fs::remove_all(r.dir);
  fs::create_directories(r.dir);
  r.scene_file = r.dir / "heading.scene.json";
  const json scene_json = test::tunnel_drive_scene();
  std::ofstream(r.scene_file) << scene_json.dump(2);
  const storage::Scene scene = storage::load_scene(r.scene_file.string());
  r.spec = rendered_tunnel_spec(*scene.tunnel->render);
  const tunnel::DesignProfile& profile = scene.tunnel->record.profile;
  const tunnel::Alignment alignment = scene.tunnel->record.alignment(Eigen::Vector3d::Zero());

  std::mt19937 rng(43);
  std::uniform_real_distribution<double> jitter(-0.25 * kSpacingM, 0.25 * kSpacingM);
  std::normal_distribution<double> noise(0.0, kScannerNoiseM);
  r.cloud = r.dir / "round.xyz";
  std::FILE* out = std::fopen(r.cloud.c_str(), "w");
  const auto write = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = p + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    std::fprintf(out, "%.4f %.4f %.4f\n", q.x(), q.y(), q.z());
  };
  const double perimeter = profile.perimeter();
  const double face = r.spec.face_chainage;
  for (double c0 = r.spec.chainage_from + 2.0; c0 < face; c0 += kSpacingM)
    for (double s0 = 0; s0 < perimeter; s0 += kSpacingM) {
      const double c = std::min(face, c0 + jitter(rng)),
                   s = std::fmod(s0 + jitter(rng) + perimeter, perimeter);
      const Eigen::Vector2d uv =
          profile.point_at_length(s) +
          camera::rendered_deviation(r.spec, c, s) * profile.outward_normal_at_length(s);
      write(alignment.frame_at(c).to_local(uv.x(), uv.y()));
    }
  const tunnel::TunnelFrame at_face = alignment.frame_at(face);
  for (double u = -4; u <= 4; u += kSpacingM)
    for (double v = -4; v <= 5; v += kSpacingM) {
      const Eigen::Vector2d p(u + jitter(rng), v + jitter(rng));
      const Eigen::Vector2d d = p - profile.ray_centre();
      if (d.norm() > 0.97 * profile.radius_toward(std::atan2(d.y(), d.x()))) continue;
      write(at_face.to_local(p.x(), p.y()));
    }
  std::fclose(out);

  r.project = r.dir / "round.rockface";
  {
    storage::ProjectInfo info;
    info.name = "scanned round";
    storage::ProjectStore::create(r.project, info);
  }
  const auto t =
      test::run_rockface("tunnel " + r.project.string() + " --alignment " +
                         scene_json["tunnel"]["alignment"].get<std::string>() + " --profile " +
                         scene_json["tunnel"]["profile"].get<std::string>());
  EXPECT_EQ(t.exit_code, 0) << t.err;
  const auto i = test::run_rockface("import " + r.project.string() + " " + r.cloud.string());
  EXPECT_EQ(i.exit_code, 0) << i.err;
  r.import_out = i.out;
  storage::ProjectStore store = storage::ProjectStore::open(r.project);
  const auto visits = store.list_visits();
  if (!visits.empty()) r.visit = visits.back().id;
  return r;
}

TEST(ScannedRound, OverAndUnderbreakOfAScannedRoundMatchTheSurfaceItWasSampledFrom) {
  const ScannedRound r = scan_round();
  ASSERT_NE(r.visit, 0);
  EXPECT_NE(r.import_out.find("developed view"), std::string::npos) << r.import_out;
  storage::ProjectStore store = storage::ProjectStore::open(r.project);
  const VisitProfile m = visit_profile(store, r.visit, Preset::standard);
  const auto& d = m.deviation;
  ASSERT_NE(d.status, tunnel::DeviationStatus::no_walls_in_view) << d.message;

  // The truth over the round the measurement chose, the whole outline (the
  // scanner saw all of it): camera/synthetic_tunnel integrates the breaks
  // every millimetre of outline, here every 2 cm of chainage.
  const tunnel::DesignProfile& profile = m.tunnel.profile;
  const double lo = std::min(m.round_from, m.round_to), hi = std::max(m.round_from, m.round_to);
  double over = 0, under = 0;
  const double dc = 0.02;
  for (double c = lo + dc / 2; c < hi; c += dc) {
    const auto section = camera::rendered_section_truth(r.spec, profile, c);
    over += section.overbreak_m2 * dc;
    under += section.underbreak_m2 * dc;
  }
  double max_over = 0, max_under = 0;
  for (const auto& b : r.spec.breaks) {
    max_over = std::max(max_over, b.depth_m);
    max_under = std::max(max_under, -b.depth_m);
  }
  std::cout << r.import_out << "round " << m.round_from << " to " << m.round_to << "; overbreak "
            << d.overbreak_volume_m3 << " m3 (true " << over << "), underbreak "
            << d.underbreak_volume_m3 << " m3 (true " << under << "); largest overbreak "
            << d.max_overbreak_m << " m (true " << max_over << "), underbreak "
            << d.max_underbreak_m << " m (true " << max_under << "); seen " << d.seen_fraction
            << "\n  " << d.message << "\n";
  ASSERT_GT(over, 0.1);
  ASSERT_GT(under, 0.02);
  // The scan sees the whole outline: every cell but the seam's and the
  // face's corner is measured.
  EXPECT_GT(d.seen_fraction, 0.95);
  // The import measured the scan's scatter as its depth precision (3 mm
  // normal noise; 10 % for the cells' plane fits on a 2.5 cm grid).
  EXPECT_NE(r.import_out.find("scatter normal to the surface: 2."), std::string::npos)
      << r.import_out;
  // Volumes within 3 %: the noise averages to well under 0.1 mm over a
  // cell's points; what is lost are the breaks' edges shallower than the
  // threshold (2 sigma, 6 mm, flanks down to 3 mm: the last centimetres of
  // a sin^2 flank, under 1 % of a 0.12-0.35 m bump's volume), and the cells
  // at the invert's seam and the face's corners. Measured: 0.2 %.
  EXPECT_NEAR(d.overbreak_volume_m3, over, 0.03 * over);
  EXPECT_NEAR(d.underbreak_volume_m3, under, 0.03 * under);
  // The deepest of each within 8 mm. The round's largest is a cell's
  // depth capped by its second deepest neighbour (profile_deviation.cpp,
  // crest_depth), no longer the noisiest cell's: the sections lie 0.25 m
  // apart, so the crest can fall 0.125 m from the nearest one, where a
  // sin^2 bump 3 m long is 1.7 % shallower (6 mm of 0.35 m; here 0.107 m:
  // 4.4 mm); the neighbours along the outline 5 cm away cap it by under
  // 1 mm, and a cell's median of 9 rays through 3 mm of noise scatters
  // ~1.5 mm. Measured: 5.1 mm (overbreak) and 4.7 mm (underbreak); 1 mm
  // and 0.8 mm with the largest single cell, whose noise lifted it.
  EXPECT_NEAR(d.max_overbreak_m, max_over, 0.008);
  EXPECT_NEAR(d.max_underbreak_m, max_under, 0.008);
  fs::remove_all(r.dir);
}

}  // namespace
}  // namespace rockface::app

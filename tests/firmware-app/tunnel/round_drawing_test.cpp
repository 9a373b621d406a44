// The round drawn for the office (issue 43's DXF export, `rockface export
// --what profile`): a heading driven toward descending chainage has its
// measured outlines drawn on the side of the tunnel the rock was broken on,
// read back by an independent reader (Debian's python3-ezdxf). Its sections
// are measured in the heading's own direction (round_start.h); drawn in the
// tunnel's ascending frame instead, the developed view's arc length (which
// runs from the invert to the right of the drive) lands mirrored.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "camera/synthetic_tunnel.h"
#include "firmware-app/export/visit_export.h"
#include "storage/project/project_store.h"
#include "tests/support/dxf_reading.h"
#include "tests/support/rendered_tunnel_project.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;

// The project: a straight tunnel due north from the datum (chainage 0 at
// the datum, 200 m), a circular design of 3 m radius, the tunnel's drive
// ascending. The south heading advances toward descending chainage: its
// first visit's face at 124, its second's at 120, and the second round
// broke 0.3 m beyond the design on the EAST wall (the break is laid in the
// ascending frame, where right is east: from the invert's middle the circle
// runs counter-clockwise in (right, up), so a quarter of it, s = pi R / 2,
// is due east, three quarters due west).
const Eigen::Vector3d kDatum(2600000, 1200000, 500);
constexpr double kRadius = 3.0;

camera::RenderedTunnelSpec round_spec(double walls_from, double face) {
  camera::RenderedTunnelSpec spec;
  spec.chainage_from = walls_from;
  spec.face_chainage = face;
  return spec;
}

camera::RenderedBreak east_wall_break() {
  camera::RenderedBreak b;
  b.chainage_from = 121.0;
  b.chainage_to = 123.5;
  const double east = 0.5 * M_PI * kRadius;
  b.s_from = east - 1.0;
  b.s_to = east + 1.0;
  b.depth_m = 0.3;
  return b;
}

// The south heading's visits, each placed at its face by a typed chainage.
test::RenderedTunnelVisit south_visit(const char* label, camera::RenderedTunnelSpec spec,
                                      const char* started_at) {
  return {label, "South portal", spec, started_at, "typed"};
}

void make_project(const fs::path& file, std::vector<test::RenderedTunnelVisit>& visits) {
  test::make_rendered_tunnel_project(file, {"south heading", "drive", kDatum, kRadius}, visits);
}

TEST(RoundDrawing, ADescendingHeadingsBreakIsDrawnOnTheWallItIsOn) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-round-drawing-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<test::RenderedTunnelVisit> visits{
      south_visit("S1", round_spec(128, 124), "2026-03-02T14:00:00Z"),
      south_visit("S2", round_spec(126, 120), "2026-03-03T14:00:00Z")};
  visits[1].spec.breaks.push_back(east_wall_break());
  const camera::RenderedTunnelSpec& broken = visits[1].spec;
  make_project(dir / "p.rockface", visits);
  {
    storage::ProjectStore store = storage::ProjectStore::open(dir / "p.rockface");
    ExportRequest request;
    request.visit = visits[1].id;
    request.out_dir = dir / "out";
    request.what = {"profile"};
    request.preset = Preset::fast;
    export_visit(store, request);
  }
  const test::DxfReading dxf =
      test::read_dxf(dir / "out" / ("visit-" + std::to_string(visits[1].id) + ".dxf"));
  ASSERT_EQ(dxf.exit_code, 0) << dxf.output;

  // The truth by construction: at chainage c the east wall (due east of the
  // axis, at its height) lies rendered_deviation(c, s_east) beyond the 3 m
  // circle, the west wall on it. The rendered walls are planar facets of
  // 0.25 m of chainage by 0.1 m of outline: across them the bump's sin^2
  // (0.3 m over 2.5 m x 2 m) sags at most 0.3 x 2 (pi / 2.5)^2 x 0.25^2 / 8
  // + 0.3 x 2 (pi / 2)^2 x 0.1^2 / 8 = 9.3 mm below its curve, and the
  // developed view's column nearest due east is a few millimetres of arc off
  // it at the bump's flat top: 2 cm holds that, and a mirrored drawing is
  // 0.3 m off on both walls.
  constexpr double kSagM = 0.02;
  const double s_east = 0.5 * M_PI * kRadius, s_west = 1.5 * M_PI * kRadius;
  // Each section's measured points, from every run it was drawn in (a run
  // breaks where the 3D image did not see the wall), keyed by millimetre
  // of chainage.
  std::map<long, std::vector<Eigen::Vector2d>> sections;
  for (const auto& e : dxf.drawing.at("entities")) {
    if (e.at("layer") != "PROFILE_MEASURED") continue;
    for (const auto& p : e.at("points"))
      sections[std::lround((p.at(1).get<double>() - kDatum.y()) * 1000)].emplace_back(
          p.at(0).get<double>() - kDatum.x(), p.at(2).get<double>() - kDatum.z());
  }
  int checked = 0;
  for (const auto& [mm, points] : sections) {
    const double chainage = mm / 1000.0;
    const double depth = camera::rendered_deviation(broken, chainage, s_east);
    if (depth < 0.2) continue;  // the bump's core: sections well inside the break
    // The measured points nearest due east and due west of the axis, by
    // the angle about it in the section (x east, z up).
    double best_east = std::numeric_limits<double>::max(), best_west = best_east;
    double radius_east = 0, radius_west = 0;
    for (const Eigen::Vector2d& p : points) {
      const double angle = std::atan2(p.y(), p.x());  // 0 east, pi west
      const double off_east = std::abs(angle), off_west = M_PI - std::abs(angle);
      if (off_east < best_east) best_east = off_east, radius_east = p.norm();
      if (off_west < best_west) best_west = off_west, radius_west = p.norm();
    }
    // Both walls seen at this section (within 2 degrees of their points).
    ASSERT_LT(best_east, 2 * M_PI / 180) << "no measured point east at chainage " << chainage;
    ASSERT_LT(best_west, 2 * M_PI / 180) << "no measured point west at chainage " << chainage;
    EXPECT_NEAR(radius_east - kRadius, depth, kSagM)
        << "east wall at chainage " << chainage << " (the break is there)";
    EXPECT_NEAR(radius_west - kRadius, camera::rendered_deviation(broken, chainage, s_west), kSagM)
        << "west wall at chainage " << chainage << " (no break there)";
    ++checked;
  }
  EXPECT_GE(checked, 2) << "sections through the break's core";
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace rockface::app

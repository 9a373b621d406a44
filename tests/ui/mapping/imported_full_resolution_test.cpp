// Issue 43, "full resolution for measuring, decimated for the display": on
// the tablet, a scanner's cloud imported as a visit is drawn from a display
// copy cut down to the view's triangle budget (ui/view3d/display_mesh.h),
// while a trace tapped on the Mapping screen, an area outlined there and
// Find traces' facets are measured on the stored surface at full
// resolution. The scan: a stepped
// face (tests/support/stepped_face.h: strips 0.75 m wide alternately on two
// joint sets, meeting in ridges 68 degrees apart) with 2 mm of ranging
// noise, at UTM coordinates, imported by the program's own import. The
// display budget is 2,000 triangles (a cell of about 0.2 m): a coarse
// triangle near a ridge cuts the corner by centimetres, where the stored
// surface lies within the scanner's noise of the true face.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <random>

#include <gtest/gtest.h>

#include "core/geometry/orientation.h"
#include "firmware-app/import/import_surface.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"
#include "tests/support/stepped_face.h"
#include "tests/support/temp_folders.h"
#include "ui/app/app_state.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;

constexpr double kRangeNoiseM = 0.002;
constexpr double kSpacingM = 0.015;
const Eigen::Vector3d kUtm(276771, 5151636, 2385);
constexpr double kHalfWidth = 4.5, kZFrom = -2.0, kZTo = 2.5;
constexpr std::size_t kDisplayTriangles = 2000;

std::vector<test::Facet> stepped_strips() {
  return test::stepped_face(test::SteppedTruth{}, 40, 30, 0.0, 2, kHalfWidth, kZFrom, kZTo).facets;
}

// The true face's point at (x, z) and its distance from a point (both in the
// file's local frame, before the UTM offset): the nearest of the strips'
// planes over the strip under the point and its two neighbours (a point
// near a ridge may be nearest the other strip's plane).
Eigen::Vector3d on_face(const std::vector<test::Facet>& strips, double x, double z) {
  const auto s =
      std::find_if(strips.begin(), strips.end(), [&](const test::Facet& f) { return x < f.x_to; });
  const Eigen::Vector3d& n = s->plane.normal;
  return {x, (s->plane.offset - n.x() * x - n.z() * z) / n.y(), z};
}
double off_face(const std::vector<test::Facet>& strips, const Eigen::Vector3d& p) {
  double best = std::numeric_limits<double>::max();
  for (std::size_t k = 0; k < strips.size(); ++k) {
    if (p.x() < strips[k].x_from - 0.2 || p.x() > strips[k].x_to + 0.2) continue;
    best = std::min(best, std::abs(strips[k].plane.normal.dot(p) - strips[k].plane.offset));
  }
  return best;
}

// The scan, from a scanner at the local origin, as a binary PLY.
void write_scan(const std::vector<test::Facet>& strips, const fs::path& file) {
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> jitter(-0.3 * kSpacingM, 0.3 * kSpacingM);
  std::normal_distribution<double> noise(0, kRangeNoiseM);
  std::vector<double> xyz;
  for (double z0 = kZFrom + kSpacingM / 2; z0 < kZTo; z0 += kSpacingM)
    for (double x0 = -kHalfWidth + kSpacingM / 2; x0 < kHalfWidth; x0 += kSpacingM) {
      const double x = std::clamp(x0 + jitter(rng), -kHalfWidth, kHalfWidth - 1e-9);
      const Eigen::Vector3d p = on_face(strips, x, z0 + jitter(rng));
      const Eigen::Vector3d q = p + noise(rng) * p.normalized() + kUtm;
      xyz.insert(xyz.end(), {q.x(), q.y(), q.z()});
    }
  std::ofstream out(file, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << xyz.size() / 3
      << "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  out.write(reinterpret_cast<const char*>(xyz.data()),
            static_cast<std::streamsize>(xyz.size() * sizeof(double)));
}

// Find traces' runner as the program has it, noting the surface it was
// handed (the size of its mesh) and the facets' triangles it returned.
class NotingProposals final : public ui::ProposalRunner {
 public:
  explicit NotingProposals(ui::ProposalRunner& real) : real_(real) {}
  measure::ProposalResult propose(const ui::ProposalInput& input, Progress& progress,
                                  const Batch& batch) override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      triangles_ = input.mesh ? input.mesh->triangles.size() : 0;
    }
    return real_.propose(input, progress, batch);
  }
  std::size_t triangles() {
    std::lock_guard<std::mutex> lock(mutex_);
    return triangles_;
  }

 private:
  ui::ProposalRunner& real_;
  std::mutex mutex_;
  std::size_t triangles_ = 0;
};

TEST(ImportedFullResolution, TracesAreasAndFindTracesMeasureTheStoredSurfaceNotTheDisplayCopy) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-imported-full-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  test::remove_when_passed(dir);
  const std::vector<test::Facet> strips = stepped_strips();
  write_scan(strips, dir / "scan.ply");
  const fs::path project = dir / "scan.rockface";
  app::ImportResult imported;
  std::size_t stored_triangles = 0;
  {
    storage::ProjectInfo info;
    info.name = "stepped scan";
    storage::ProjectStore store = storage::ProjectStore::create(project, info);
    app::ImportRequest request;
    request.file = dir / "scan.ply";
    request.view_from = kUtm;  // the scanner
    imported = app::import_surface(store, request);
    stored_triangles = store.load_model(imported.model).mesh.faces.size();
  }
  ASSERT_EQ(imported.registration_kind, "scanner");
  // The project's frame from the file's local one (the strips').
  const Eigen::Vector3d to_project = kUtm - imported.project_datum;

  app::FieldRunners runners{""};
  ui::FieldServices services = runners.services();
  services.sync = nullptr;
  services.camera = nullptr;
  NotingProposals noting(runners.proposals);
  services.proposals = &noting;
  ui::UiOptions options;
  options.project = project;
  options.max_display_triangles = kDisplayTriangles;
  ui::HeadlessSession s(options, services, 1280, 800);
  s.settle();
  ui::AppState& app = s.state();
  ASSERT_TRUE(app.model_view.has_model());
  ASSERT_LE(app.model_view.display_mesh().triangle_count(), kDisplayTriangles);
  ASSERT_GT(stored_triangles, 100 * kDisplayTriangles) << "the display copy is a coarse one";
  s.tap("Mapping");
  s.settle();

  // A trace tapped across the strips, each tap 5 cm from a ridge on
  // alternate sides (where a coarse triangle spanning the ridge lies
  // centimetres inside the face) and at heights that make it no straight
  // line.
  std::vector<Eigen::Vector3d> aimed;
  for (std::size_t k = 3; k + 3 < strips.size(); ++k) {
    const double x = k % 2 ? strips[k].x_to - 0.05 : strips[k].x_from + 0.05;
    aimed.push_back(on_face(strips, x, -0.8 + 0.25 * static_cast<double>(k)) + to_project);
  }
  for (const Eigen::Vector3d& p : aimed) {
    const auto at = app.model_view.to_screen(p);
    ASSERT_TRUE(at);
    s.tap(at->x, at->y);
  }
  ASSERT_EQ(app.mapping.marker.taps().size(), aimed.size()) << app.mapping.marker.problem();
  s.tap("Save trace");
  s.settle();
  std::vector<storage::Measurement> traces;
  {
    storage::ProjectStore store = storage::ProjectStore::open(project);
    for (const auto& m : store.list_measurements(imported.visit))
      if (m.kind == storage::Measurement::Kind::trace) traces.push_back(m);
  }
  ASSERT_EQ(traces.size(), 1u);
  ASSERT_GE(traces[0].points.size(), aimed.size());
  // Every point of the trace on the scanned face: the stored surface's
  // vertices lie within the ranging noise of it (2 mm along the line of
  // sight; 4 sigma, 8 mm, is the most a few of 180 k points reach) and its
  // triangles, 1.5 cm across, never span a ridge 5 cm away; the display
  // copy's triangles near a ridge lie centimetres off it.
  constexpr double kOnTheScanM = 4 * kRangeNoiseM;
  double worst = 0;
  for (const Eigen::Vector3d& p : traces[0].points)
    worst = std::max(worst, off_face(strips, p - to_project));
  std::printf("trace of %zu points: at most %.2f mm off the scanned face\n",
              traces[0].points.size(), worst * 1000);
  EXPECT_LT(worst, kOnTheScanM) << "the trace's points lie off the scanned face";

  // An area outlined on one strip (corners 10 cm inside its edges): stored
  // with the strip's true plane. Its plane is fitted to the stored surface's
  // few thousand points inside the outline (1.25 mm of noise normal to the
  // face over 0.55 x 2 m: a thousandth of a degree or so); 0.01 degrees
  // holds that with room, and a neighbouring strip's plane is 68 degrees
  // away.
  const test::Facet& strip = strips[6];
  s.tap("Outline the face");
  for (const auto& [x, z] :
       {std::pair{strip.x_from + 0.1, -1.0}, std::pair{strip.x_to - 0.1, -1.0},
        std::pair{strip.x_to - 0.1, 1.0}, std::pair{strip.x_from + 0.1, 1.0}}) {
    const auto at = app.model_view.to_screen(on_face(strips, x, z) + to_project);
    ASSERT_TRUE(at);
    s.tap(at->x, at->y);
  }
  ASSERT_EQ(app.mapping.outline.corners().size(), 4u) << app.mapping.outline.problem();
  s.tap("Save outline");
  s.settle();
  std::vector<storage::Measurement> areas;
  {
    storage::ProjectStore store = storage::ProjectStore::open(project);
    for (const auto& m : store.list_measurements(imported.visit))
      if (m.kind == storage::Measurement::Kind::area) areas.push_back(m);
  }
  ASSERT_EQ(areas.size(), 1u) << "one flat piece";
  ASSERT_TRUE(areas[0].dip_deg && areas[0].dipdir_deg) << areas[0].note;
  const geometry::PlaneOrientation want = geometry::plane_orientation(strip.plane.normal);
  std::printf("area %s: %.4f / %.4f (strip %.4f / %.4f)\n", areas[0].label.c_str(),
              *areas[0].dip_deg, *areas[0].dipdir_deg, want.dip * 180 / M_PI,
              want.dipdir * 180 / M_PI);
  constexpr double kAreaDeg = 0.01;
  EXPECT_NEAR(*areas[0].dip_deg, want.dip * 180 / M_PI, kAreaDeg);
  EXPECT_NEAR(*areas[0].dipdir_deg, want.dipdir * 180 / M_PI, kAreaDeg);

  // Find traces: the facets are sought on the stored surface.
  s.tap("Find traces");
  s.settle();
  EXPECT_EQ(noting.triangles(), stored_triangles)
      << "Find traces was handed a surface of " << noting.triangles() << " triangles";
}

}  // namespace

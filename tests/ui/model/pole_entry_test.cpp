// Issue 43 on the tablet: a scanner's cloud imported in its own frame has no
// photograph for the range pole to be found in; on the Model screen the
// geologist taps the pole's lower and upper target on the 3D image, and the
// visit is scaled and levelled by them (ui/model/pole_entry.h), headless with
// the program's own runners. The cloud is sampled from the rendered sample
// face with its pole (tests/support/rendered_pole_cloud.h) and carried into
// a local frame by a known similarity; the truth is the scene's target
// centres, compared through Eigen's Umeyama fit of the file's points onto
// the stored ones (not the code under test).
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "storage/project/model_registration.h"
#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/support/rendered_pole_cloud.h"
#include "tests/support/synthetic_face.h"
#include "tests/support/temp_folders.h"
#include "tests/ui/field_tablet.h"
#include "ui/app/app_state.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using namespace rockface::ui;

constexpr double kNoise = 0.002;  // the scanner's scatter per coordinate, m

// The sample face scanned square to its best plane through the pole (the
// plane of its facets' corners, fitted here): the pole's targets then lie
// over their own shadow on the face and the cloud's 2.5D mesh keeps them.
camera::SyntheticScene scanned_square_to_the_face() {
  camera::SyntheticScene scene = rockface::testing::synthetic_face(1200, 800);
  std::vector<Eigen::Vector3d> corners;
  for (const auto& p : scene.patches)
    corners.insert(corners.end(), p.polygon.begin(), p.polygon.end());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& c : corners) mean += c;
  mean /= static_cast<double>(corners.size());
  Eigen::MatrixXd A(corners.size(), 3);
  for (std::size_t i = 0; i < corners.size(); ++i)
    A.row(static_cast<Eigen::Index>(i)) = (corners[i] - mean).transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinV);
  Eigen::Vector3d n = svd.matrixV().col(2);
  if (n.y() > 0) n = -n;  // toward the stations, south of the face
  const Eigen::Vector3d middle = scene.range_pole->base + Eigen::Vector3d(0, 0, 1);
  scene.stations[0] = {middle + 7 * n, middle - n};
  scene.stations[1] = {middle + 7 * n + Eigen::Vector3d(0.6, 0, 0), middle - n};
  return scene;
}

// Before issue 43's fourth round the upper tap landed 9 cm off its target,
// the lower 2 cm: ImGui floors the pointer to whole pixels (the tap's ray
// went up to a pixel up and left of the target), and a ray a third of a
// pixel off the upper plate's centre met a curtain triangle from the plate
// to the rock 3 m behind it, kept by the 2.5D meshing's edge test (a lone
// rock point amid the plate's points took its spacing from the plate).
TEST(PoleEntry, TheTargetsTappedOnAnImportedCloudScaleAndLevelTheVisit) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-pole-entry-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  test::remove_when_passed(dir);
  rockface::testing::LocalFrame frame;
  frame.scale = 0.37;
  frame.R = (Eigen::AngleAxisd(130 * M_PI / 180, Eigen::Vector3d::UnitZ()) *
             Eigen::AngleAxisd(25 * M_PI / 180, Eigen::Vector3d(1, 1, 0).normalized()))
                .toRotationMatrix();
  frame.t = Eigen::Vector3d(12.3, -4.5, 101.0);
  const auto cloud =
      rockface::testing::rendered_pole_cloud(scanned_square_to_the_face(), 1, kNoise, frame);
  const fs::path file = dir / "scan-local.xyz";
  std::vector<Eigen::Vector3d> written;
  {
    std::FILE* f = std::fopen(file.c_str(), "w");
    for (std::size_t k = 0; k < cloud.points.size(); ++k) {
      char text[120];
      std::snprintf(text, sizeof text, "%.7f %.7f %.7f", cloud.points[k].x(), cloud.points[k].y(),
                    cloud.points[k].z());
      Eigen::Vector3d back;
      std::sscanf(text, "%lf %lf %lf", &back.x(), &back.y(), &back.z());
      written.push_back(back);
      std::fprintf(f, "%s %d %d %d\n", text, cloud.colours[k][0], cloud.colours[k][1],
                   cloud.colours[k][2]);
    }
    std::fclose(f);
  }
  const fs::path project = dir / "scan.rockface";
  const test::CliRun imported =
      test::run_rockface("import " + project.string() + " " + file.string() + " --frame local");
  ASSERT_EQ(imported.exit_code, 0) << imported.err;

  test::FieldTablet tablet(project);
  HeadlessSession& s = tablet.session;
  AppState& app = s.state();
  ASSERT_TRUE(app.session && app.session->visit());
  s.tap("Model");
  s.settle();
  ASSERT_TRUE(app.model_view.has_model());
  EXPECT_EQ(app.model_view.model()->registration.kind, "none");
  s.tap("Scale from the range pole");
  s.frame();
  ASSERT_TRUE(app.model.pole.open);
  // Each target tapped where the view draws its true centre (the file's
  // frame is the stored one while nothing registered the visit).
  double world_per_screen_px = 0;
  for (const Eigen::Vector3d& target : cloud.targets) {
    const auto at = app.model_view.to_screen(target);
    ASSERT_TRUE(at);
    // The view's scale at the target: a step across the line of sight.
    const Eigen::Vector3d across = app.model_view.ray_at(*at).direction.unitOrthogonal();
    const double step = 0.01 * frame.scale;
    const auto beside = app.model_view.to_screen(target + step * across);
    ASSERT_TRUE(beside);
    world_per_screen_px =
        std::max(world_per_screen_px, step / std::hypot(beside->x - at->x, beside->y - at->y));
    s.tap(at->x, at->y);
  }
  ASSERT_EQ(app.model.pole.targets.size(), 2u);
  s.tap("Scale by the pole");
  s.settle();
  EXPECT_FALSE(app.model.pole.open) << "the entry closes once the visit is scaled";

  auto store = storage::ProjectStore::open(project);
  const storage::Model m = store.load_model(store.list_models().back().id);
  EXPECT_EQ(m.registration.kind, "range_pole");
  EXPECT_TRUE(storage::read_model_registration(m.registration).is_scaled());
  ASSERT_EQ(m.mesh.vertices.size(), written.size());
  const auto n = static_cast<Eigen::Index>(written.size());
  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    src.col(i) = written[static_cast<std::size_t>(i)];
    dst.col(i) = m.mesh.vertices[static_cast<std::size_t>(i)];
  }
  const Eigen::Matrix4d M = Eigen::umeyama(src, dst, true);
  auto stored = [&](const Eigen::Vector3d& p) {
    return Eigen::Vector3d((M * p.homogeneous()).head<3>());
  };
  const Eigen::Vector3d lower = stored(cloud.targets[0]), upper = stored(cloud.targets[1]);
  // A tap lands within half a screen pixel of where it was aimed, and the
  // ray from it meets the 3D image on the plate's noisy points (up to 3
  // sigmas of the scanner's scatter off the plate): each target within that
  // of its true centre, in the site's metres; the upper one's stored place
  // carries its own error and the lower's (twice the bound).
  const double tolerance = (0.5 * world_per_screen_px) / frame.scale + 3 * kNoise;
  std::printf(
      "pole tapped: lower target stored at %.4f %.4f %.4f, upper at %.4f %.4f %.4f "
      "(tolerance %.4f m, %.4f m a screen pixel)\n",
      lower.x(), lower.y(), lower.z(), upper.x(), upper.y(), upper.z(), tolerance,
      world_per_screen_px / frame.scale);
  EXPECT_LT(lower.norm(), tolerance);
  EXPECT_LT((upper - Eigen::Vector3d(0, 0, 2.0)).norm(), 2 * tolerance);
}

}  // namespace

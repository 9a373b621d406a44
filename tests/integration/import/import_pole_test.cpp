// Issue 43: a cloud in a local frame (a drone model in its software's units,
// a scanner's own frame) is scaled and levelled by the range pole standing at
// the face, and turned to north by a compass line, as a photographed visit
// is. The test's face and pole are made in the site's frame (x East, y North,
// z Up), with 2 mm of scanner noise, then moved, turned and scaled into a
// local frame by a known similarity; the pole's targets and the compass
// line's ends are picked as the cloud's own (noisy) points, as CloudCompare's
// point picking gives them. The truth is the applied similarity: the stored
// 3D image must be the site's frame with the lower target at the origin.
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "storage/project/model_registration.h"
#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/support/rendered_pole_cloud.h"
#include "tests/support/synthetic_face.h"
#include "tests/support/temp_folders.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::run_rockface;

constexpr double kNoise = 0.002;     // the scanner's scatter per coordinate, m
constexpr double kPoleLength = 2.0;  // m between the targets' centres

struct LocalCloud {
  fs::path dir, file;
  std::vector<Eigen::Vector3d> site;         // noise-free, the site's frame, in the file's order
  std::vector<Eigen::Vector3d> file_points;  // as written (noisy, local frame)
  std::size_t lower = 0, upper = 0, line_from = 0, line_to = 0;  // indices of the picks
};

std::string triple(const Eigen::Vector3d& p) {
  char text[120];
  std::snprintf(text, sizeof text, "%.7f,%.7f,%.7f", p.x(), p.y(), p.z());
  return text;
}

// A face 3 x 2.5 m facing south, 10 cm of relief, every 2 cm; the pole 15 cm
// in front of it, its targets 0.5 and 2.5 m up, a few points on each.
LocalCloud write_local_cloud(const std::string& name) {
  LocalCloud c;
  c.dir = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(c.dir);
  fs::create_directories(c.dir);
  rockface::test::remove_when_passed(c.dir);
  const int columns = 151, rows = 126;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const double a = 0.02 * i, b = 0.02 * j;
      c.site.emplace_back(a, 0.1 * std::sin(2 * a) * std::cos(3 * b), b);
    }
  c.line_from = 90 * columns + 10;  // a line across the face 1.8 m up, 2.6 m long
  c.line_to = 90 * columns + 140;
  for (const double height : {0.5, 0.5 + kPoleLength}) {
    // Each target a 3 x 3 patch of points 1 cm apart facing south; its
    // centre is the middle one.
    for (int dz = -1; dz <= 1; ++dz)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dz == 0) (height < 1 ? c.lower : c.upper) = c.site.size();
        c.site.emplace_back(1.51 + 0.01 * dx, -0.15, height + 0.01 * dz);
      }
  }
  // The local frame: local = k Q site + t (k: the drone software's units).
  const double k = 0.37;
  const Eigen::Matrix3d Q =
      (Eigen::AngleAxisd(130 * M_PI / 180, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(25 * M_PI / 180, Eigen::Vector3d(1, 1, 0).normalized()))
          .toRotationMatrix();
  const Eigen::Vector3d t(12.3, -4.5, 101.0);
  std::mt19937 random(43);
  std::normal_distribution<double> noise(0.0, kNoise);
  c.file = c.dir / "face-local.xyz";
  std::FILE* f = std::fopen(c.file.c_str(), "w");
  for (const auto& p : c.site) {
    const Eigen::Vector3d scanned =
        p + Eigen::Vector3d(noise(random), noise(random), noise(random));
    Eigen::Vector3d local = k * (Q * scanned) + t;
    char text[100];
    std::snprintf(text, sizeof text, "%.7f %.7f %.7f", local.x(), local.y(), local.z());
    std::sscanf(text, "%lf %lf %lf", &local.x(), &local.y(), &local.z());
    std::fprintf(f, "%s\n", text);
    c.file_points.push_back(local);  // the numbers as written: what a pick reads
  }
  std::fclose(f);
  return c;
}

// The similarity stored = s R (site - lower target) + t, fitted by Eigen's
// Umeyama over every point (not the code under test).
struct Fit {
  double scale = 0, tilt_deg = 0, heading_deg = 0;
};

Fit fit_stored_to_site(const std::vector<Eigen::Vector3d>& stored, const LocalCloud& c) {
  const auto n = static_cast<Eigen::Index>(c.site.size());
  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    src.col(i) = c.site[static_cast<std::size_t>(i)] - c.site[c.lower];
    dst.col(i) = stored[static_cast<std::size_t>(i)];
  }
  const Eigen::Matrix4d M = Eigen::umeyama(src, dst, true);
  Fit fit;
  fit.scale = M.block<3, 1>(0, 0).norm();
  const Eigen::Matrix3d R = M.topLeftCorner<3, 3>() / fit.scale;
  fit.tilt_deg = std::acos(std::clamp((R * Eigen::Vector3d::UnitZ()).z(), -1.0, 1.0)) * 180 / M_PI;
  const Eigen::Vector3d east = R * Eigen::Vector3d::UnitX();
  fit.heading_deg = std::atan2(east.y(), east.x()) * 180 / M_PI;
  return fit;
}

// Each target and each end of the line is a point picked with the scanner's
// noise (kNoise per coordinate): a length between two picks is off by about
// sqrt(2) kNoise, so 3 sigma of the pole's scale is 3 sqrt(2) kNoise / L
// (0.42 %), of its vertical the same in radians (0.24 deg), and of the
// compass line's bearing 3 sqrt(2) kNoise / 2.6 m (0.19 deg) plus what the
// tilt carries into it.
const double kScaleTolerance = 3 * std::sqrt(2.0) * kNoise / kPoleLength;
const double kTiltToleranceDeg = kScaleTolerance * 180 / M_PI;
const double kHeadingToleranceDeg =
    3 * std::sqrt(2.0) * kNoise / 2.6 * 180 / M_PI + kTiltToleranceDeg;

TEST(ImportRangePole, ALocalCloudIsScaledLevelledAndTurnedToNorthByThePoleAndACompassLine) {
  const LocalCloud c = write_local_cloud("import-pole");
  // The compass bearing of the line as the geologist measured it on site
  // (noise-free site points).
  const Eigen::Vector3d line = c.site[c.line_to] - c.site[c.line_from];
  const double azimuth = std::atan2(line.x(), line.y()) * 180 / M_PI;
  const fs::path project = c.dir / "pole.rockface";
  const auto r = run_rockface(
      "import " + project.string() + " " + c.file.string() + " --frame local --pole " +
      triple(c.file_points[c.lower]) + "," + triple(c.file_points[c.upper]) + " --range-pole " +
      std::to_string(kPoleLength) + " --azimuth " + std::to_string(azimuth) + " --reference-line " +
      triple(c.file_points[c.line_from]) + "," + triple(c.file_points[c.line_to]));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("scaled and levelled by the range pole"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("north by the compass line"), std::string::npos) << r.out;
  auto store = rockface::storage::ProjectStore::open(project);
  const auto model = store.load_model(store.list_models().back().id);
  ASSERT_EQ(model.mesh.vertices.size(), c.site.size());
  const auto reg = rockface::storage::read_model_registration(model.registration);
  EXPECT_EQ(reg.kind, "range_pole_compass");
  EXPECT_TRUE(reg.has_pole);
  EXPECT_EQ(reg.pole_targets.size(), 2u);
  EXPECT_TRUE(reg.oriented());
  EXPECT_TRUE(reg.is_scaled());
  // The lower target's pick is the origin, as a photographed pole's.
  EXPECT_LT(model.mesh.vertices[c.lower].norm(), 1e-9);
  const Fit fit = fit_stored_to_site(model.mesh.vertices, c);
  std::printf(
      "measured: scale %.6f (tolerance %.6f), tilt %.4f deg (%.4f), heading %.4f deg (%.4f)\n",
      fit.scale, kScaleTolerance, fit.tilt_deg, kTiltToleranceDeg, fit.heading_deg,
      kHeadingToleranceDeg);
  EXPECT_NEAR(fit.scale, 1.0, kScaleTolerance);
  EXPECT_LT(fit.tilt_deg, kTiltToleranceDeg);
  EXPECT_NEAR(fit.heading_deg, 0.0, kHeadingToleranceDeg);
}

TEST(ImportRangePole, WithoutACompassLineThePoleScalesAndLevelsAndNorthIsNotClaimed) {
  const LocalCloud c = write_local_cloud("import-pole-level");
  const fs::path project = c.dir / "level.rockface";
  // The length the geologist typed for the project's photographs is taken
  // when the import gives none: a first import without it is refused.
  const std::string pole = " --frame local --pole " + triple(c.file_points[c.lower]) + "," +
                           triple(c.file_points[c.upper]);
  const auto refused = run_rockface("import " + project.string() + " " + c.file.string() + pole);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--range-pole"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(project));  // nothing stored, no project left behind
  const auto r = run_rockface("import " + project.string() + " " + c.file.string() + pole +
                              " --range-pole " + std::to_string(kPoleLength));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("no north"), std::string::npos) << r.out;
  auto store = rockface::storage::ProjectStore::open(project);
  const auto model = store.load_model(store.list_models().back().id);
  const auto reg = rockface::storage::read_model_registration(model.registration);
  EXPECT_EQ(reg.kind, "range_pole");
  EXPECT_FALSE(reg.oriented());
  ASSERT_EQ(model.mesh.vertices.size(), c.site.size());
  const Fit fit = fit_stored_to_site(model.mesh.vertices, c);
  std::printf(
      "measured: scale %.6f (tolerance %.6f), tilt %.4f deg (%.4f), heading %.4f deg (%.4f)\n",
      fit.scale, kScaleTolerance, fit.tilt_deg, kTiltToleranceDeg, fit.heading_deg,
      kHeadingToleranceDeg);
  EXPECT_NEAR(fit.scale, 1.0, kScaleTolerance);
  EXPECT_LT(fit.tilt_deg, kTiltToleranceDeg);
}

TEST(ImportRangePole, ThePoleAndGroundControlAreNotTakenTogether) {
  const LocalCloud c = write_local_cloud("import-pole-gcp");
  const fs::path project = c.dir / "both.rockface";
  const auto r =
      run_rockface("import " + project.string() + " " + c.file.string() +
                   " --frame local --range-pole 2 --gcp " + c.file.string() + " --pole " +
                   triple(c.file_points[c.lower]) + "," + triple(c.file_points[c.upper]));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("not both"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(project));
}

TEST(ImportRangePole, PoleAutoOnACloudWithoutColoursIsRefusedWithNothingStored) {
  const LocalCloud c = write_local_cloud("import-pole-auto-grey");
  const fs::path project = c.dir / "grey.rockface";
  const auto r = run_rockface("import " + project.string() + " " + c.file.string() +
                              " --frame local --pole auto --range-pole 2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--pole auto"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no colours"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(project));  // nothing stored, no project left behind
}

// The local frame of the `--pole auto` clouds: 0.37 of the site's size,
// turned 130 deg about z and tilted 25 deg.
rockface::testing::LocalFrame pole_auto_frame() {
  rockface::testing::LocalFrame frame;
  frame.scale = 0.37;
  frame.R = (Eigen::AngleAxisd(130 * M_PI / 180, Eigen::Vector3d::UnitZ()) *
             Eigen::AngleAxisd(25 * M_PI / 180, Eigen::Vector3d(1, 1, 0).normalized()))
                .toRotationMatrix();
  frame.t = Eigen::Vector3d(12.3, -4.5, 101.0);
  return frame;
}

fs::path pole_auto_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  rockface::test::remove_when_passed(dir);
  return dir;
}

// A point as a file holds it (7 decimals) and as the file's reader reads
// it back.
std::string written_point(const Eigen::Vector3d& p, std::vector<Eigen::Vector3d>& written) {
  char text[120];
  std::snprintf(text, sizeof text, "%.7f %.7f %.7f", p.x(), p.y(), p.z());
  Eigen::Vector3d back;
  std::sscanf(text, "%lf %lf %lf", &back.x(), &back.y(), &back.z());
  written.push_back(back);
  return text;
}

// The scene's two target centres where the import stored them: the file's
// points fitted onto the stored ones by Eigen's Umeyama (not the code under
// test), the stored model registered by the range pole.
std::array<Eigen::Vector3d, 2> stored_targets(const fs::path& project,
                                              const std::vector<Eigen::Vector3d>& written,
                                              const rockface::testing::RenderedPoleCloud& cloud) {
  auto store = rockface::storage::ProjectStore::open(project);
  const auto model = store.load_model(store.list_models().back().id);
  EXPECT_EQ(model.mesh.vertices.size(), written.size());
  const auto reg = rockface::storage::read_model_registration(model.registration);
  EXPECT_EQ(reg.kind, "range_pole");
  EXPECT_TRUE(reg.is_scaled());
  const auto n = static_cast<Eigen::Index>(std::min(written.size(), model.mesh.vertices.size()));
  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    src.col(i) = written[static_cast<std::size_t>(i)];
    dst.col(i) = model.mesh.vertices[static_cast<std::size_t>(i)];
  }
  const Eigen::Matrix4d M = Eigen::umeyama(src, dst, true);
  auto stored = [&](const Eigen::Vector3d& p) {
    return Eigen::Vector3d((M * p.homogeneous()).head<3>());
  };
  return {stored(cloud.targets[0]), stored(cloud.targets[1])};
}

// The finder's bound (cloud_range_pole_test.cpp): each centre within half
// the picture's pixel, 1.5 sampling footprints, of the truth; in the stored
// frame, metres of the site: 0.75 footprints / the frame's scale. The upper
// target's stored place carries its own error and the lower's (the pole's
// similarity takes the lower to the origin and its scale from both): twice
// the bound.
void expect_pole_found(const std::array<Eigen::Vector3d, 2>& at,
                       const rockface::testing::RenderedPoleCloud& cloud, double frame_scale) {
  const double tolerance = 0.75 * cloud.spacing / frame_scale;
  std::printf(
      "pole auto: lower target stored at %.4f %.4f %.4f, upper at %.4f %.4f %.4f "
      "(tolerance %.4f m)\n",
      at[0].x(), at[0].y(), at[0].z(), at[1].x(), at[1].y(), at[1].z(), tolerance);
  EXPECT_LT(at[0].norm(), tolerance);  // the lower target at the origin
  EXPECT_LT((at[1] - Eigen::Vector3d(0, 0, kPoleLength)).norm(), 2 * tolerance);
}

// `--pole auto`: the targets found in the colours of a cloud sampled from
// the rendered sample face (tests/support/rendered_pole_cloud.h: 2 mm of
// scanner noise, a local frame at 0.37 of the site's size, turned and
// tilted). The truth is the scene's target centres carried into the file's
// frame.
TEST(ImportRangePole, WithPoleAutoTheTargetsAreFoundInTheCloudsColours) {
  const rockface::testing::LocalFrame frame = pole_auto_frame();
  const auto cloud = rockface::testing::rendered_pole_cloud(
      rockface::testing::synthetic_face(1200, 800), 1, kNoise, frame);
  const fs::path dir = pole_auto_folder("import-pole-auto");
  const fs::path file = dir / "face-local.xyz";
  std::vector<Eigen::Vector3d> written;
  {
    std::FILE* f = std::fopen(file.c_str(), "w");
    for (std::size_t k = 0; k < cloud.points.size(); ++k)
      std::fprintf(f, "%s %d %d %d\n", written_point(cloud.points[k], written).c_str(),
                   cloud.colours[k][0], cloud.colours[k][1], cloud.colours[k][2]);
    std::fclose(f);
  }
  const fs::path project = dir / "auto.rockface";
  const auto r = run_rockface("import " + project.string() + " " + file.string() +
                              " --frame local --pole auto --range-pole 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("found in the cloud's colours"), std::string::npos) << r.out;
  expect_pole_found(stored_targets(project, written, cloud), cloud, frame.scale);
}

// A terrestrial scanner without a camera: the same rendered face's cloud
// whose only picture is the return intensity (the rendered grey, ITU-R
// BT.601 luma of its colour, in a scanner's units), written as "x y z
// intensity" (12-bit counts, 200 at black to 3900 at white) and as a PTX
// without colours (0.05 to 0.95, as Leica writes it). The import draws the
// intensity as grey (its own range black to white) and `--pole auto` finds
// the targets in it within the same bounds as in colours.
TEST(ImportRangePole, WithPoleAutoTheTargetsAreFoundInAScannersIntensity) {
  const rockface::testing::LocalFrame frame = pole_auto_frame();
  const rockface::camera::SyntheticScene scene = rockface::testing::synthetic_face(1200, 800);
  const auto cloud = rockface::testing::rendered_pole_cloud(scene, 1, kNoise, frame);
  const fs::path dir = pole_auto_folder("import-pole-intensity");
  auto grey = [&](std::size_t k) {
    const auto& c = cloud.colours[k];
    return (0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]) / 255.0;
  };
  std::vector<Eigen::Vector3d> written;
  const fs::path text = dir / "scan-intensity.xyz";
  {
    std::FILE* f = std::fopen(text.c_str(), "w");
    for (std::size_t k = 0; k < cloud.points.size(); ++k)
      std::fprintf(f, "%s %ld\n", written_point(cloud.points[k], written).c_str(),
                   std::lround(200 + 3700 * grey(k)));
    std::fclose(f);
  }
  // PTX: one scan of all the points (a row of them), the scanner where the
  // left station stood, registered already (the identity).
  const fs::path ptx = dir / "scan-intensity.ptx";
  {
    std::FILE* f = std::fopen(ptx.c_str(), "w");
    const Eigen::Vector3d scanner = frame.apply(scene.stations[0].position);
    std::fprintf(f, "%zu\n1\n%.7f %.7f %.7f\n1 0 0\n0 1 0\n0 0 1\n", cloud.points.size(),
                 scanner.x(), scanner.y(), scanner.z());
    std::fprintf(f, "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
    std::vector<Eigen::Vector3d> same;  // the same numbers as the text file's
    for (std::size_t k = 0; k < cloud.points.size(); ++k)
      std::fprintf(f, "%s %.4f\n", written_point(cloud.points[k], same).c_str(),
                   0.05 + 0.9 * grey(k));
    std::fclose(f);
  }
  for (const fs::path& file : {text, ptx}) {
    SCOPED_TRACE(file.filename().string());
    const fs::path project = dir / (file.extension().string().substr(1) + ".rockface");
    const auto r = run_rockface("import " + project.string() + " " + file.string() +
                                " --frame local --pole auto --range-pole 2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("its intensity drawn as grey"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("found in the cloud's colours"), std::string::npos) << r.out;
    expect_pole_found(stored_targets(project, written, cloud), cloud, frame.scale);
  }
}

}  // namespace

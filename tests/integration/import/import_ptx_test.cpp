// Issue 43: a PTX scan registered by a non-identity matrix, written here as
// the format says (the matrix for row vectors, its translation last; the
// header's scanner position), imported by `rockface import`: the points
// where the matrix puts them, and the virtual view the geologist maps on
// looking from the side the scanner stood on, not from a side guessed from
// the wall's bearing.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::run_rockface;

struct WrittenPtx {
  fs::path dir, file;
  Eigen::Vector3d scanner;      // survey coordinates
  Eigen::Matrix3d R;            // scanner frame -> survey axes
  Eigen::Vector3d first_point;  // survey coordinates, the first with a return
  std::size_t with_return = 0;
  double wall_easting = 0;  // the wall's plane, x = this
};

// A wall facing west (its normal's bearing 270 degrees), a 4 x 3 m grid every
// 2.5 cm with a 2 cm relief, 4 m east of the scanner; the scanner turned 30
// degrees about the vertical. The points are written in the scanner's frame
// (6 decimals: exact to 1e-6 m), every 97th with no return (0 0 0).
WrittenPtx write_ptx() {
  WrittenPtx w;
  w.dir = fs::temp_directory_path() / ("import-ptx-" + std::to_string(::getpid()));
  fs::remove_all(w.dir);
  fs::create_directories(w.dir);
  w.file = w.dir / "wall.ptx";
  w.scanner = {276771.5, 5151636.25, 2385.0};
  w.R = Eigen::AngleAxisd(30 * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  w.wall_easting = w.scanner.x() + 4.0;
  const int columns = 161, rows = 121;
  std::FILE* f = std::fopen(w.file.c_str(), "w");
  std::fprintf(f, "%d\n%d\n%.4f %.4f %.4f\n", columns, rows, w.scanner.x(), w.scanner.y(),
               w.scanner.z());
  for (int k = 0; k < 3; ++k)
    std::fprintf(f, "%.12f %.12f %.12f\n", w.R(0, k), w.R(1, k), w.R(2, k));
  // p_survey = p_scanner * M: M's top-left block is R transposed.
  for (int i = 0; i < 3; ++i)
    std::fprintf(f, "%.12f %.12f %.12f 0\n", w.R(0, i), w.R(1, i), w.R(2, i));
  std::fprintf(f, "%.4f %.4f %.4f 1\n", w.scanner.x(), w.scanner.y(), w.scanner.z());
  int n = 0;
  for (int c = 0; c < columns; ++c)
    for (int r = 0; r < rows; ++r, ++n) {
      if (n % 97 == 5) {
        std::fprintf(f, "0 0 0 0.5\n");
        continue;
      }
      const double north = -2.0 + 0.025 * c, up = -1.5 + 0.025 * r;
      const Eigen::Vector3d world(w.wall_easting + 0.02 * std::sin(3 * north) * std::cos(2 * up),
                                  w.scanner.y() + north, w.scanner.z() + up);
      Eigen::Vector3d local = w.R.transpose() * (world - w.scanner);
      // As written: 6 decimals, so the truth is of the written numbers.
      char text[100];
      std::snprintf(text, sizeof text, "%.6f %.6f %.6f", local.x(), local.y(), local.z());
      std::sscanf(text, "%lf %lf %lf", &local.x(), &local.y(), &local.z());
      std::fprintf(f, "%s 0.5\n", text);
      if (w.with_return++ == 0) w.first_point = w.R * local + w.scanner;
    }
  std::fclose(f);
  return w;
}

TEST(ImportPtx, PointsWhereTheMatrixPutsThemSeenFromTheScannersSide) {
  const WrittenPtx w = write_ptx();
  const fs::path project = w.dir / "wall.rockface";
  const auto r = run_rockface("import " + project.string() + " " + w.file.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("from the side the scanner stood on"), std::string::npos) << r.out;
  auto store = rockface::storage::ProjectStore::open(project);
  const Eigen::Vector3d datum = store.project().datum;
  const auto models = store.list_models();
  ASSERT_EQ(models.size(), 1u);
  const rockface::storage::Model model = store.load_model(models[0].id);
  ASSERT_EQ(model.mesh.vertices.size(), w.with_return);
  // 0.1 mm: the round trip of survey coordinates; the written
  // numbers are exact to 1e-6 m and the matrix to 1e-12.
  EXPECT_LT((model.mesh.vertices[0] + datum - w.first_point).norm(), 1e-4);
  // Every point on the wall (its relief 2 cm) where the matrix puts it.
  for (const auto& v : model.mesh.vertices)
    ASSERT_NEAR(v.x() + datum.x(), w.wall_easting, 0.0201) << "a point off the wall";
  // The view's camera stands on the scanner's side (west) of the wall; the
  // wall's bearing alone (its normal 90 or 270 degrees) would put it east.
  ASSERT_TRUE(model.camera_to_mesh.has_value());
  const Eigen::Vector3d camera = model.camera_to_mesh->t + datum;
  EXPECT_LT(camera.x(), w.wall_easting - 1.0) << "camera at E " << camera.x();
  fs::remove_all(w.dir);
}

}  // namespace

// Issue 43: a cloud in a local frame gets its scale, level and north from
// ground control picked on it, as a photographed visit does (`replay --gcp`).
// The test's face is written in survey coordinates, then moved, turned and
// scaled into a local frame by a known similarity; five of its points are
// picked on the import's virtual view (their pixels read from a first
// import) with their survey coordinates; the second import with --gcp must
// put every point back where the test wrote it.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::run_rockface;

TEST(ImportGroundControl, ALocalCloudIsPutBackWhereTheSurveySaysByPointsPickedOnItsView) {
  const fs::path dir = fs::temp_directory_path() / ("import-gcp-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // The face: 3 x 2.5 m facing south with 10 cm of relief, every 2 cm.
  const Eigen::Vector3d origin(600000.0, 5200000.0, 450.0);
  const int columns = 151, rows = 126;
  std::vector<Eigen::Vector3d> world;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const double a = 0.02 * i, b = 0.02 * j;
      world.push_back(origin + Eigen::Vector3d(a, 0.1 * std::sin(2 * a) * std::cos(3 * b), b));
    }
  // The local frame: world = scale * R * local + T.
  const double scale = 1.25;
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(35 * M_PI / 180, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(8 * M_PI / 180, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const Eigen::Vector3d T = origin + Eigen::Vector3d(1.0, -3.0, 0.5);
  const fs::path cloud = dir / "face-local.xyz";
  {
    std::FILE* f = std::fopen(cloud.c_str(), "w");
    for (auto& p : world) {
      Eigen::Vector3d local = R.transpose() * (p - T) / scale;
      char text[100];
      std::snprintf(text, sizeof text, "%.7f %.7f %.7f", local.x(), local.y(), local.z());
      std::sscanf(text, "%lf %lf %lf", &local.x(), &local.y(), &local.z());
      std::fprintf(f, "%s\n", text);
      p = scale * (R * local) + T;  // the truth of the numbers as written
    }
    std::fclose(f);
  }
  // A first import, to read where the points fall on the view.
  const fs::path first = dir / "first.rockface";
  const auto r1 =
      run_rockface("import " + first.string() + " " + cloud.string() + " --frame local");
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  int width = 0, height = 0;
  const auto at = r1.out.find("virtual view ");
  ASSERT_NE(at, std::string::npos) << r1.out;
  ASSERT_EQ(std::sscanf(r1.out.c_str() + at, "virtual view %d x %d", &width, &height), 2);
  std::vector<std::array<float, 2>> texcoords;
  {
    auto store = rockface::storage::ProjectStore::open(first);
    texcoords = store.load_model(store.list_models().back().id).mesh.texcoords;
  }
  ASSERT_EQ(texcoords.size(), world.size());
  const fs::path gcp = dir / "gcp.csv";
  {
    std::ofstream out(gcp);
    out << "id,u,v,X,Y,Z\n";
    const int picks[] = {10 * columns + 10, 10 * columns + 140, 115 * columns + 10,
                         115 * columns + 140, 60 * columns + 75};
    for (int k : picks) {
      const auto i = static_cast<std::size_t>(k);
      char line[200];
      std::snprintf(line, sizeof line, "GCP%d,%.6f,%.6f,%.4f,%.4f,%.4f\n", k,
                    texcoords[i][0] * static_cast<float>(width),
                    texcoords[i][1] * static_cast<float>(height), world[i].x(), world[i].y(),
                    world[i].z());
      out << line;
    }
  }
  const fs::path project = dir / "registered.rockface";
  const auto r2 = run_rockface("import " + project.string() + " " + cloud.string() +
                               " --frame local --gcp " + gcp.string());
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  EXPECT_NE(r2.out.find("registered by 5 ground control points"), std::string::npos) << r2.out;
  auto store = rockface::storage::ProjectStore::open(project);
  const Eigen::Vector3d datum = store.project().datum;
  const auto model = store.load_model(store.list_models().back().id);
  EXPECT_EQ(model.registration.kind, "ground_control");
  ASSERT_EQ(model.mesh.vertices.size(), world.size());
  double worst = 0;
  for (std::size_t i = 0; i < world.size(); ++i)
    worst = std::max(worst, (model.mesh.vertices[i] + datum - world[i]).norm());
  // 1 mm: the picks' survey coordinates are written to 0.1 mm and their
  // pixels to 1e-6 px (a few micrometres on the face); noise-free, the
  // similarity puts the far corners within a few tenths of a millimetre.
  EXPECT_LT(worst, 1e-3);
  fs::remove_all(dir);
}

}  // namespace

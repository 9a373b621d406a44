// The tablet's further pairs of a visit (issue 45): a visit's first pair
// replayed with its pole and compass, then a second pair taken 1.2 m to the
// East (rendered by the mock camera as the tablet's camera would give it)
// stored in the same visit and reconstructed by the tablet's runner
// (StoreReconstructionRunner): it is tied to the first pair's 3D image, in
// its frame, and lies on the scene's true surface where its camera stood.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/progress.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_folders.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;

// The demo scene without its picks (the blocks from the true traces) and
// its joints 0.5 m lower, as replay_pairs_test.cpp takes it (on that
// texture the further pairs' registration was tried and measured), its
// stations moved `dx` metres East.
nlohmann::json demo_moved(double dx) {
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face-demo.scene.json");
  nlohmann::json scene = nlohmann::json::parse(in);
  scene.erase("picks");
  for (auto& j : scene["joints"]) j["point"][2] = j["point"][2].get<double>() - 0.5;
  for (auto& st : scene["imaging"]["stations"]) {
    st["position"][0] = st["position"][0].get<double>() + dx;
    st["look_at"][0] = st["look_at"][0].get<double>() + dx;
  }
  return scene;
}

Eigen::Vector3d point(const nlohmann::json& p) {
  return {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
}

// Median distance of the mesh's vertices (project frame + datum) to the
// nearest plane of the scene's true surface patches.
double median_distance_to_truth(const storage::Mesh& mesh, const Eigen::Vector3d& datum,
                                const nlohmann::json& scene) {
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> planes;  // point, normal
  for (const auto& patch : scene["surface"]["patches"]) {
    const auto& poly = patch["polygon"];
    const Eigen::Vector3d a = point(poly[0]), b = point(poly[1]), c = point(poly[2]);
    planes.emplace_back(a, (b - a).cross(c - a).normalized());
  }
  std::vector<double> d;
  for (std::size_t i = 0; i < mesh.vertices.size(); i += 7) {
    const Eigen::Vector3d p = mesh.vertices[i] + datum;
    double best = 1e9;
    for (const auto& [q, n] : planes) best = std::min(best, std::abs(n.dot(p - q)));
    d.push_back(best);
  }
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  return d[d.size() / 2];
}

TEST(FacePairRunner, ASecondPairOnTheTabletIsTiedToTheFirstPairsFace) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-face-pair-runner-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  test::remove_when_passed(dir);

  const nlohmann::json first = demo_moved(0), second = demo_moved(1.2);
  std::ofstream(dir / "first.scene.json") << first.dump(2);
  std::ofstream(dir / "second.scene.json") << second.dump(2);
  const fs::path project = dir / "site.rockface";
  const test::CliRun replay =
      test::run_rockface("replay " + (dir / "first.scene.json").string() + " --project " +
                         project.string() + " --preset fast");
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  const test::CliRun render = test::run_rockface("render " + (dir / "second.scene.json").string() +
                                                 " --out " + (dir / "second").string());
  ASSERT_EQ(render.exit_code, 0) << render.err;

  storage::RecordId capture_id = 0, visit_id = 0;
  {
    storage::ProjectStore store = storage::ProjectStore::open(project);
    const auto captures = store.list_captures();
    ASSERT_EQ(captures.size(), 1u);
    visit_id = captures[0].visit_id;
    // As the Capture screen stores a pair: the camera's JPEGs, the
    // project's calibration of that camera, the pole's length typed once.
    storage::Capture capture;
    capture.visit_id = visit_id;
    capture.calibration_id = captures[0].calibration_id;
    capture.label = "tablet pair";
    auto jpeg = [&](const char* name) {
      std::vector<unsigned char> bytes;
      EXPECT_TRUE(cv::imencode(".jpg", cv::imread((dir / "second" / name).string()), bytes,
                               {cv::IMWRITE_JPEG_QUALITY, 95}));
      return bytes;
    };
    capture.left.bytes = jpeg("left.png");
    capture.right.bytes = jpeg("right.png");
    capture.settings["range_pole_m"] = "2";
    capture.settings["preset"] = "fast";
    capture_id = store.save_capture(capture);
  }

  NoProgress progress;
  app::StoreReconstructionRunner runner;
  const storage::RecordId model_id =
      runner.reconstruct(project, capture_id, Preset::fast, progress);

  storage::ProjectStore store = storage::ProjectStore::open(project);
  const auto first_models = store.list_models(store.list_captures(visit_id).front().id);
  ASSERT_EQ(first_models.size(), 1u);
  const storage::Model face = store.load_model(first_models[0].id);
  const storage::Model model = store.load_model(model_id);
  EXPECT_EQ(model.registration.kind, "face_images");
  const nlohmann::json report = nlohmann::json::parse(model.registration.parameters_json);
  ASSERT_EQ(report["images"].size(), 2u);
  EXPECT_GE(report["images"][1]["tie_points"].get<int>(), 20);

  // On the true surface as well as the first pair's own 3D image is: the
  // first's median distance (its depth noise and its pole's scale error)
  // plus the further pair's registration onto it (surface rms ~1.5 cm at
  // the fast preset, replay_pairs_test.cpp): within 1.5 cm of the first's.
  const Eigen::Vector3d datum = store.project().datum;
  const double first_d = median_distance_to_truth(face.mesh, datum, first);
  const double second_d = median_distance_to_truth(model.mesh, datum, second);
  std::printf("median distance to the true surface: first pair %.4f m, second %.4f m\n", first_d,
              second_d);
  EXPECT_LT(second_d, first_d + 0.015);

  // Its camera where the station stood relative to the first pair's: the
  // same budget as the replay's further pairs (registration ~0.1 deg over
  // 10 m and 1-2 cm of surface fit: 0.3-1.3 cm seen there), under 6 cm.
  ASSERT_TRUE(face.camera_to_mesh);
  ASSERT_TRUE(model.camera_to_mesh);
  const Eigen::Vector3d moved = point(second["imaging"]["stations"][0]["position"]) -
                                point(first["imaging"]["stations"][0]["position"]);
  const double off = ((model.camera_to_mesh->t - face.camera_to_mesh->t) - moved).norm();
  std::printf("second pair's camera %.3f m from its station\n", off);
  EXPECT_LT(off, 0.06);
}

}  // namespace

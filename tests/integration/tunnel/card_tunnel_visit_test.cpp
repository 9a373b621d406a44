// Issue 42: a round photographed in the tunnel and brought home on a card
// becomes a scaled, north-oriented, placed visit with its over- and
// underbreak, with no scene file anywhere: `replay` of the card's folder
// (the pair as DSC_0001.JPG / DSC_0002.JPG, camera.json, visit.json with
// the pole and the compass line), `tunnel` from the alignment and profile
// files, `place` by the pole's typed chainage, then `profile`.
//
// The photographs are rendered once by `rockface render` from the
// tunnel-drive sample; the truth is the scene's geometry (the face between
// chainage 111.6 and 112.0, one overbreak 0.35 m deep) and the renderer's
// record (truth.json), not anything the route computes.
#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "storage/project/project_store.h"
#include "tests/support/card_folder.h"
#include "tests/support/cli_run.h"
#include "tests/support/dxf_reading.h"
#include "tests/support/tunnel_drive_scene.h"

namespace rockface {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CliRun;
using test::run_rockface;

double shoelace(const std::vector<std::array<double, 2>>& p) {
  double twice = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return std::abs(twice) / 2;
}

// The area a rockface-tunnel-profile/1 file encloses, from its segments
// (lines "from"/"to", arcs "centre"/"radius"/"start_deg"/"end_deg")
// walked in 0.5 mm steps: written here from the file's format, so that the
// export is checked against the file, not against rockface's own profile.
double profile_file_area(const std::string& file) {
  const json profile = json::parse(std::ifstream(file));
  std::vector<std::array<double, 2>> p;
  for (const auto& s : profile.at("segments")) {
    if (s.contains("line")) {
      const auto& a = s["line"]["from"];
      p.push_back({a[0].get<double>(), a[1].get<double>()});
    } else {
      const auto& arc = s.at("arc");
      const double cx = arc["centre"][0], cy = arc["centre"][1], r = arc["radius"];
      const double a0 = arc["start_deg"].get<double>() * M_PI / 180;
      const double a1 = arc["end_deg"].get<double>() * M_PI / 180;
      const int n = std::max(1, static_cast<int>(std::abs(a1 - a0) * r / 0.0005));
      for (int k = 0; k < n; ++k) {
        const double a = a0 + (a1 - a0) * k / n;
        p.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
      }
    }
  }
  return shoelace(p);
}

TEST(CardTunnelVisit, PhotographsPoleAndCompassGiveAPlacedRoundWithItsOverbreak) {
  const fs::path root =
      fs::temp_directory_path() / ("rockface-card-tunnel-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const std::string samples = std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/";
  const json truth = test::render_sample("tunnel-drive.scene.json", root);
  ASSERT_FALSE(HasFailure());

  const fs::path card = root / "DCIM";
  test::write_card(root / "render", card, "DSC_0417.JPG", "DSC_0418.JPG");
  ASSERT_FALSE(HasFailure());
  const json& line = truth.at("reference_line");
  std::ofstream(card / "visit.json") << json{
      {"format", "rockface-visit/1"},
      {"range_pole_m", truth.at("range_pole").at("length")},
      {"compass",
       {{"reference_line_px", line.at("left")}, {"azimuth_deg", line.at("azimuth_deg")}}},
      {"preset", "fast"}}.dump(2);

  const fs::path project = root / "drive.rockface";
  CliRun r = run_rockface("replay " + card.string() + " --project " + project.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("north: compass"), std::string::npos) << r.out;

  // The tunnel from its files; a second one is refused, naming the first.
  const std::string files = " --alignment " + samples + "tunnel-drive.alignment.csv --profile " +
                            samples + "tunnel-drive.profile.json";
  r = run_rockface("tunnel " + project.string() + files + " --name \"Main drive\"");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_rockface("tunnel " + project.string() + files);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("already has the tunnel Main drive"), std::string::npos) << r.err;

  // Where the geologist stood the pole, typed (the scene's tunnel.placement).
  r = run_rockface("place " + project.string() +
                   " --visit 1 --chainage 110.6 --offset 1.3 --height -1.05");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  {
    storage::ProjectStore store = storage::ProjectStore::open(project);
    const auto placement = store.load_visit_placement(1);
    ASSERT_TRUE(placement);
    EXPECT_EQ(placement->method, storage::VisitPlacement::Method::chainage_compass);
    // The face bulges from chainage 111.6 (its centre) to 112.0 (where it
    // meets the walls); the median of the rays along the axis lies between,
    // with the reconstruction's depth error (~3 cm at 8 m, fast preset).
    EXPECT_GT(placement->chainage, 111.6);
    EXPECT_LT(placement->chainage, 112.0);
    // The face's centre lies on the axis (the stations look along it); a
    // north off by a degree would move it 0.15 m at 8.5 m.
    EXPECT_LT(std::abs(placement->offset_m), 0.2);
  }

  const fs::path figures = root / "profile.json";
  r = run_rockface("profile " + project.string() + " --visit 1 --out " +
                   (root / "profile.png").string() + " --json " + figures.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(std::ifstream(figures));
  EXPECT_EQ(j.at("placement").at("method"), "chainage_compass");
  // The compass line's heading error is not in the volumes' uncertainty,
  // and the message says so (issue 38).
  EXPECT_NE(j.at("message").get<std::string>().find("placed by its chainage and compass line"),
            std::string::npos)
      << j.at("message");
  ASSERT_TRUE(j.at("overbreak_volume_m3").is_number()) << j.dump();
  // The rendered overbreak: 0.35 m deep over 3.0 m of chainage and 2.8 m of
  // outline, a smooth bump; where the cameras see it from the round's
  // end, its volume is well above 0.1 m3 (the scene route's test asserts
  // the same bound, tunnel_round_test.cpp).
  EXPECT_GT(j.at("overbreak_volume_m3").get<double>(), 0.1);

  // Issue 43: the round exported for the office, read back by ezdxf: the
  // design outline and the measured one at every cross-section of the round.
  const fs::path exported = root / "export";
  r = run_rockface("export " + project.string() + " --visit 1 --what profile --out " +
                   exported.string());
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const test::DxfReading dxf = test::read_dxf(exported / "visit-1.dxf");
  ASSERT_EQ(dxf.exit_code, 0) << dxf.output;
  // The design's area from the profile file itself, not from rockface.
  const double design_area = profile_file_area(samples + "tunnel-drive.profile.json");
  const double from = j.at("round").at("from_chainage").get<double>();
  const double to = j.at("round").at("to_chainage").get<double>();
  int design = 0, measured = 0;
  for (const auto& e : dxf.drawing.at("entities")) {
    const std::string layer = e.at("layer");
    ASSERT_EQ(e.at("kind"), "polyline3d") << layer;
    // The alignment runs due north from (512340, 5211800) at elevation 410
    // (tunnel-drive.alignment.csv): the section at chainage c is the plane
    // y = 5211800 + c, with u = x - 512340 (right, looking north) and
    // v = z - 410. Written to 16 digits: 1e-6 m is rounding.
    const auto& points = e.at("points");
    const double chainage = points.at(0).at(1).get<double>() - 5211800;
    // The profile's JSON gives the round's ends to 1 mm: half of it either way.
    EXPECT_GE(chainage, from - 5e-4) << layer;
    EXPECT_LE(chainage, to + 5e-4) << layer;
    std::vector<std::array<double, 2>> uv;
    for (const auto& p : points) {
      EXPECT_NEAR(p.at(1).get<double>() - 5211800, chainage, 1e-6) << layer;
      uv.push_back({p.at(0).get<double>() - 512340, p.at(2).get<double>() - 410});
    }
    if (layer == "PROFILE_DESIGN") {
      ++design;
      EXPECT_TRUE(e.at("closed").get<bool>());
      // Chords every 2 cm on arcs of 3 m radius or more lose
      // perimeter x c^2 / (12 r) = 20 x 4e-4 / 36 = 2e-4 m2.
      EXPECT_NEAR(shoelace(uv), design_area, 1e-3) << "at chainage " << chainage;
    } else {
      EXPECT_EQ(layer, "PROFILE_MEASURED");
      ++measured;
    }
  }
  EXPECT_EQ(design, static_cast<int>(j.at("sections").size()));
  EXPECT_GT(measured, 0);
  // The over- and underbreak per section as CSV: a row per section.
  std::ifstream csv(exported / "visit-1-profile.csv");
  int rows = -1;  // the header
  for (std::string line; std::getline(csv, line);) rows += !line.empty();
  EXPECT_EQ(rows, design);
  fs::remove_all(root);
}

// The round's photographs with ground control instead of the pole and
// compass, as the visit file's control points (gcp.csv): five of the
// tunnel survey's monitoring targets (circular targets 0.15 m across by the
// walls and the crown, rendered into the photographs) tapped a few pixels
// off their centres, and five natural points on the face whose survey
// coordinates and pixels the renderer records (ends of joint traces,
// truth.json). The targets are measured on their targets in both
// photographs, the natural points read from the 3D image. The visit is in
// survey coordinates (the new project's datum at their centroid), and once
// the project has its tunnel it is placed by them (issue 42: a `--gcp` model
// was recorded as "control points" and could never be placed so).
TEST(CardTunnelVisit, MonitoringTargetsPlaceTheVisitInSurveyCoordinates) {
  const fs::path root =
      fs::temp_directory_path() / ("rockface-card-gcp-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const std::string samples = std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/";
  // The targets as the truth test places them (tunnel_break_truth_test.cpp):
  // (chainage, offset, height) on the straight, level alignment, chainage c
  // at northing 5211800 + c, the axis at 410 m, 0.2 m off the walls and the
  // crown.
  const std::vector<std::array<double, 3>> places = {{109.0, -2.7, 0.5},
                                                     {111.0, -2.7, -0.3},
                                                     {109.5, 2.7, 0.5},
                                                     {111.0, 2.7, -0.5},
                                                     {110.5, 0.0, 3.8}};
  json scene = test::tunnel_drive_scene();
  json targets = json::array();
  for (std::size_t k = 0; k < places.size(); ++k)
    targets.push_back(
        {{"id", "M" + std::to_string(k + 1)},
         {"position", {512340.0 + places[k][1], 5211800.0 + places[k][0], 410.0 + places[k][2]}},
         {"diameter", 0.15}});
  scene["imaging"]["control_targets"] = targets;
  std::ofstream(root / "drive.scene.json") << scene.dump(2);
  {
    const CliRun rendered = run_rockface("render " + (root / "drive.scene.json").string() +
                                         " --out " + (root / "render").string());
    ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
  }
  const json truth = json::parse(std::ifstream(root / "render" / "truth.json"));

  const fs::path card = root / "DCIM";
  test::write_card(root / "render", card, "DSC_0101.JPG", "DSC_0102.JPG");
  ASSERT_FALSE(HasFailure());
  std::ofstream gcp(card / "gcp.csv");
  gcp << "id,u,v,X,Y,Z\n";
  // Each target's centre projected into the left photograph by OpenCV's
  // camera model from the renderer's record (its pose, intrinsics and
  // distortion; not rockface's projection), and tapped 2 px right of and
  // 1 px above it, as a finger lands inside a disk about 20 px across.
  {
    const json& in = truth.at("intrinsics");
    const cv::Matx33d k(in.at("fx").get<double>(), 0, in.at("cx").get<double>(), 0,
                        in.at("fy").get<double>(), in.at("cy").get<double>(), 0, 0, 1);
    const std::vector<double> distortion = in.at("distortion").get<std::vector<double>>();
    const json& left = truth.at("cameras")[0];
    cv::Matx33d rotation;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        rotation(i, j) = left.at("rotation_world_to_camera")[i][j].get<double>();
    const cv::Vec3d station(left.at("position")[0].get<double>(),
                            left.at("position")[1].get<double>(),
                            left.at("position")[2].get<double>());
    cv::Vec3d rvec;
    cv::Rodrigues(rotation, rvec);
    for (const auto& target : targets) {
      const cv::Vec3d w(target.at("position")[0].get<double>(),
                        target.at("position")[1].get<double>(),
                        target.at("position")[2].get<double>());
      // Relative to the camera's centre: survey coordinates of 5 million
      // metres would cost the projection its millimetres.
      const std::vector<cv::Point3d> object{cv::Point3d(w - station)};
      std::vector<cv::Point2d> image;
      cv::projectPoints(object, rvec, cv::Vec3d(0, 0, 0), k, distortion, image);
      gcp << target.at("id").get<std::string>() << "," << std::setprecision(10) << image[0].x + 2
          << "," << image[0].y - 1 << "," << std::setprecision(12) << w[0] << "," << w[1] << ","
          << w[2] << "\n";
    }
  }
  // Each face trace's first end, and the last trace's other end: points on
  // rock spread over the face (5 m across, 5 m high).
  int n = 0;
  json last;
  for (const auto& t : truth.at("traces")) {
    if (t.at("patch").get<std::string>().rfind("FACE", 0) != 0) continue;
    const auto& px = t.at("left_image").front();
    const auto& w = t.at("world")[0];
    gcp << "P" << ++n << "," << px[0].get<double>() << "," << px[1].get<double>() << ","
        << std::setprecision(12) << w[0].get<double>() << "," << w[1].get<double>() << ","
        << w[2].get<double>() << "\n";
    last = t;
  }
  ASSERT_GE(n, 4);
  gcp << "P" << ++n << "," << last.at("left_image").back()[0].get<double>() << ","
      << last.at("left_image").back()[1].get<double>() << "," << std::setprecision(12)
      << last.at("world")[1][0].get<double>() << "," << last.at("world")[1][1].get<double>() << ","
      << last.at("world")[1][2].get<double>() << "\n";
  gcp.close();
  std::ofstream(card / "visit.json") << json{
      {"format", "rockface-visit/1"},
      {"control_points", "gcp.csv"},
      {"preset", "fast"}}.dump(2);

  const fs::path project = root / "drive.rockface";
  CliRun r = run_rockface("replay " + card.string() + " --project " + project.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("scale: control points"), std::string::npos) << r.out;
  // The five monitoring targets measured on their targets; the natural
  // points on the rock read from the 3D image, not from the range pole's
  // targets standing in front of the face (control_targets.h; a trace's end
  // beside a pole target was once taken for it, and the camera placed
  // 0.85 m off).
  EXPECT_NE(r.out.find("(5 of " + std::to_string(n + 5) + " measured on their targets"),
            std::string::npos)
      << r.out;
  {
    storage::ProjectStore store = storage::ProjectStore::open(project);
    const auto models = store.list_models();
    ASSERT_EQ(models.size(), 1u);
    EXPECT_EQ(models[0].registration_kind, "ground_control");
    // The datum near the work: the face is 8 m from the cameras.
    const Eigen::Vector3d datum = store.project().datum;
    const json& left = truth.at("cameras")[0];
    const Eigen::Vector3d station(left.at("position")[0].get<double>(),
                                  left.at("position")[1].get<double>(),
                                  left.at("position")[2].get<double>());
    EXPECT_LT((datum - station).norm(), 12.0);
    // The left camera's centre in survey coordinates against the renderer's
    // station. The natural points are read from the fast preset's 3D image
    // to 1-3 cm (two lattice steps at 8 m), the targets to millimetres; 14
    // points spread 5 m across and 6 m deep place the camera 8 m in front
    // to about rms / sqrt(14) times the lever (8 / 2.5): 1-2 cm (1.4 cm
    // here); 0.05 m.
    const storage::Model m = store.load_model(models[0].id);
    ASSERT_TRUE(m.camera_to_mesh);
    EXPECT_LT((datum + m.camera_to_mesh->t - station).norm(), 0.05)
        << (datum + m.camera_to_mesh->t).transpose();
  }
  const std::string files = " --alignment " + samples + "tunnel-drive.alignment.csv --profile " +
                            samples + "tunnel-drive.profile.json";
  r = run_rockface("tunnel " + project.string() + files);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path figures = root / "profile.json";
  r = run_rockface("profile " + project.string() + " --visit 1 --out " +
                   (root / "profile.png").string() + " --json " + figures.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(std::ifstream(figures));
  EXPECT_EQ(j.at("placement").at("method"), "ground_control") << j.at("placement").dump();
  EXPECT_EQ(j.at("message").get<std::string>().find("compass line"), std::string::npos)
      << j.at("message");
  // As by the pole: the face between its centre and its rim (111.6, 112.0).
  EXPECT_GT(j.at("placement").at("face_chainage").get<double>(), 111.6);
  EXPECT_LT(j.at("placement").at("face_chainage").get<double>(), 112.0);
  fs::remove_all(root);
}

}  // namespace
}  // namespace rockface

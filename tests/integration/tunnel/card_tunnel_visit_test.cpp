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
#include <opencv2/imgcodecs.hpp>

#include "storage/project/project_store.h"
#include "tests/support/card_folder.h"
#include "tests/support/cli_run.h"
#include "tests/support/dxf_reading.h"

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

// The round's photographs with monitoring targets instead of the pole and
// compass: five points on the face whose survey coordinates and pixels
// the renderer records (ends of joint traces, truth.json), given as the
// visit file's control points. The visit is in survey coordinates (the new
// project's datum at their centroid), and once the project has its tunnel
// it is placed by them (issue 42: a `--gcp` model was recorded as "control
// points" and could never be placed so).
TEST(CardTunnelVisit, MonitoringTargetsPlaceTheVisitInSurveyCoordinates) {
  const fs::path root =
      fs::temp_directory_path() / ("rockface-card-gcp-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const std::string samples = std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/";
  const json truth = test::render_sample("tunnel-drive.scene.json", root);
  ASSERT_FALSE(HasFailure());

  const fs::path card = root / "DCIM";
  test::write_card(root / "render", card, "DSC_0101.JPG", "DSC_0102.JPG");
  ASSERT_FALSE(HasFailure());
  // Each face trace's first end, and the last trace's other end: points on
  // rock spread over the face (5 m across, 5 m high).
  std::ofstream gcp(card / "gcp.csv");
  gcp << "id,u,v,X,Y,Z\n";
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
  // Natural points on the rock, none on a target: each read from the 3D
  // image, not from the range pole's targets standing in front of the face
  // (control_targets.h; a trace's end beside a pole target was once taken
  // for it, and the camera placed 0.85 m off).
  EXPECT_NE(r.out.find("(0 of " + std::to_string(n) + " measured on their targets"),
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
    // station: the targets are picked to two lattice steps (about 1 cm at
    // 8 m, fast preset) over a face 5 m across, so the camera 8 m in front
    // is placed to a few centimetres; 0.1 m.
    const storage::Model m = store.load_model(models[0].id);
    ASSERT_TRUE(m.camera_to_mesh);
    EXPECT_LT((datum + m.camera_to_mesh->t - station).norm(), 0.1)
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
  // As by the pole: the face between its centre and its rim (111.6, 112.0).
  EXPECT_GT(j.at("placement").at("face_chainage").get<double>(), 111.6);
  EXPECT_LT(j.at("placement").at("face_chainage").get<double>(), 112.0);
  fs::remove_all(root);
}

}  // namespace
}  // namespace rockface

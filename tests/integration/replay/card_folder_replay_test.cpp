// Issue 42: photographs brought home on a camera's card become a scaled,
// north-oriented visit with no scene file anywhere: two JPEGs named as a
// camera names them (DSC_0001.JPG, DSC_0002.JPG), the camera's calibration
// (camera.json) and the visit file the geologist filled in on site
// (visit.json: the range pole's length and the compass line), or the same
// given as options of `rockface replay FOLDER`.
//
// The photographs are rendered once by `rockface render` (the mock camera)
// and the scene is then left behind; the truth the visit is checked against
// is the renderer's own record (truth.json: the stations, the reference
// line's pixels and bearing), not anything the replay computes.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/units.h"
#include "storage/project/model_registration.h"
#include "storage/project/project_store.h"
#include "tests/support/card_folder.h"
#include "tests/support/cli_run.h"
#include "tests/support/station_truth.h"
#include "tests/support/temp_folders.h"

namespace rockface {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CliRun;
using test::run_rockface;

// The demo face rendered once for every test of this file.
class CardFolder : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("rockface-card-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    truth_ = test::render_sample("tunnel-face-demo.scene.json", root_);
  }
  static void TearDownTestSuite() {
    if (!::testing::UnitTest::GetInstance()->failed_test_count()) fs::remove_all(root_);
  }

  // A card's folder: the pair as the camera's JPEGs, its calibration and,
  // when given, the visit file.
  static fs::path card(const std::string& name, const std::optional<json>& visit) {
    const fs::path dir = root_ / name;
    test::write_card(root_ / "render", dir, "DSC_0001.JPG", "DSC_0002.JPG");
    if (visit) std::ofstream(dir / "visit.json") << visit->dump(2);
    return dir;
  }

  // The compass line as the geologist gives it: its two pixels in the left
  // photograph and its bearing (truth.json's, the renderer's).
  static json compass(double azimuth_offset_deg = 0) {
    const json& line = truth_.at("reference_line");
    return {{"reference_line_px", line.at("left")},
            {"azimuth_deg",
             std::fmod(line.at("azimuth_deg").get<double>() + azimuth_offset_deg, 360.0)}};
  }

  static json truth_station(int k) { return truth_.at("cameras").at(k); }

  // The left camera's optical axis in the project frame, as a compass
  // bearing (the model's camera map, stored with it).
  static double stored_view_azimuth_deg(const fs::path& project) {
    auto store = storage::ProjectStore::open(project);
    // The newest model: orienting a visit stores its turned models anew.
    const storage::Model m = store.load_model(store.list_models().back().id);
    EXPECT_TRUE(m.camera_to_mesh.has_value());
    const Eigen::Vector3d axis = m.camera_to_mesh->R * Eigen::Vector3d::UnitZ();
    double a = rad_to_deg(std::atan2(axis.x(), axis.y()));
    return a < 0 ? a + 360 : a;
  }

  static storage::ModelRegistration stored_registration(const fs::path& project) {
    auto store = storage::ProjectStore::open(project);
    return storage::read_model_registration(
        store.load_model(store.list_models().back().id).registration);
  }

  static inline fs::path root_;
  static inline json truth_;
};

double bearing_apart(double a, double b) {
  return std::abs(std::remainder(a - b, 360.0));
}

TEST_F(CardFolder, VisitFileGivesAScaledNorthOrientedVisit) {
  const fs::path dir = card("with-visit-file", json{{"format", "rockface-visit/1"},
                                                    {"range_pole_m", 2.0},
                                                    {"compass", compass()},
                                                    {"preset", "fast"},
                                                    {"note", "heading 3, round 112"}});
  const fs::path project = root_ / "with-visit-file.rockface";
  const CliRun r = run_rockface("replay " + dir.string() + " --project " + project.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("scale: range pole, vertical: range pole, north: compass"),
            std::string::npos)
      << r.out;

  const storage::ModelRegistration reg = stored_registration(project);
  EXPECT_EQ(reg.kind, "range_pole_compass");
  EXPECT_TRUE(reg.oriented());
  ASSERT_TRUE(reg.pole_length_m);
  EXPECT_EQ(*reg.pole_length_m, 2.0);
  // The scale against the stations' true distance (1.8 m): the pole's two
  // targets, 2 m apart at 9.5 m, are located to a few millimetres each in
  // 1500 px photographs (JPEG, blur 0.5 px), so the scale is good to about
  // 0.3 %; 1 % also covers the ellipse-centre bias of the printed targets.
  ASSERT_TRUE(reg.base_m);
  EXPECT_NEAR(*reg.base_m, test::true_base_m(truth_station(0), truth_station(1)),
              0.01 * test::true_base_m(truth_station(0), truth_station(1)));
  // North: the left camera looks at 5.2 deg; the compass line (4 m long at
  // 9.8 m, its ends given to a fraction of a pixel) fixes north to about
  // 0.1 deg, and the levelling by the pole adds less; 0.5 deg is the
  // tolerance a geologist's compass reading itself has.
  EXPECT_NEAR(bearing_apart(stored_view_azimuth_deg(project),
                            test::true_view_bearing_deg(truth_station(0))),
              0, 0.5);
  // The preset and the note came from the file.
  auto store = storage::ProjectStore::open(project);
  EXPECT_EQ(store.list_models().at(0).preset, "fast");
  EXPECT_EQ(store.list_visits().at(0).note, "heading 3, round 112");
}

// The bearing typed is what turns the visit: the same photographs with a
// line read 30 deg further round give a model turned by those 30 deg (the
// images, and so the reconstruction, are the same; the rotation about the
// vertical is the only difference, to rounding).
TEST_F(CardFolder, OptionsOverrideTheVisitFileAndTheBearingTurnsTheModel) {
  const fs::path dir = card("options", json{{"format", "rockface-visit/1"}, {"range_pole_m", 2.0}});
  const json line = compass(30).at("reference_line_px");
  const std::string pixels = std::to_string(line[0][0].get<double>()) + "," +
                             std::to_string(line[0][1].get<double>()) + "," +
                             std::to_string(line[1][0].get<double>()) + "," +
                             std::to_string(line[1][1].get<double>());
  const fs::path project = root_ / "options.rockface";
  const CliRun r = run_rockface("replay " + dir.string() + " --project " + project.string() +
                                " --preset fast --reference-line " + pixels + " --azimuth " +
                                std::to_string(compass(30).at("azimuth_deg").get<double>()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(stored_registration(project).oriented());
  // 0.5 deg as above, the truth being 30 deg round from the camera's.
  EXPECT_NEAR(bearing_apart(stored_view_azimuth_deg(project),
                            test::true_view_bearing_deg(truth_station(0)) + 30),
              0, 0.5);
}

// Without a compass line the pole scales and levels the visit and nothing
// claims a north: the model is recorded as "range_pole", and a tunnel
// placement by chainage is refused rather than made at the camera's heading
// (core/tunnel/visit_placement_test.cpp holds that refusal).
TEST_F(CardFolder, PoleWithoutCompassClaimsNoNorth) {
  const fs::path dir =
      card("no-compass", json{{"format", "rockface-visit/1"}, {"range_pole_m", 2.0}});
  const fs::path project = root_ / "no-compass.rockface";
  const CliRun r =
      run_rockface("replay " + dir.string() + " --project " + project.string() + " --preset fast");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("north: none"), std::string::npos) << r.out;
  const storage::ModelRegistration reg = stored_registration(project);
  EXPECT_EQ(reg.kind, "range_pole");
  EXPECT_FALSE(reg.oriented());
  EXPECT_TRUE(reg.is_scaled());
  auto store = storage::ProjectStore::open(project);
  EXPECT_EQ(store.list_models().at(0).registration_kind, "range_pole");
}

// The compass line read on site but left out of the visit file: given
// after the fact (`rockface orient`, what the tablet's compass entry calls),
// it turns the stored visit as the reconstruction would have.
TEST_F(CardFolder, ACompassLineGivenAfterwardsOrientsTheStoredVisit) {
  const fs::path dir =
      card("orient-later", json{{"format", "rockface-visit/1"}, {"range_pole_m", 2.0}});
  const fs::path project = root_ / "orient-later.rockface";
  CliRun r =
      run_rockface("replay " + dir.string() + " --project " + project.string() + " --preset fast");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_FALSE(stored_registration(project).oriented());
  const json line = compass();
  const std::string pixels = std::to_string(line["reference_line_px"][0][0].get<double>()) + "," +
                             std::to_string(line["reference_line_px"][0][1].get<double>()) + "," +
                             std::to_string(line["reference_line_px"][1][0].get<double>()) + "," +
                             std::to_string(line["reference_line_px"][1][1].get<double>());
  r = run_rockface("orient " + project.string() + " --visit 1 --reference-line " + pixels +
                   " --azimuth " + std::to_string(line["azimuth_deg"].get<double>()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("north from the compass line"), std::string::npos) << r.out;
  const storage::ModelRegistration reg = stored_registration(project);
  EXPECT_EQ(reg.kind, "range_pole_compass");
  EXPECT_TRUE(reg.oriented());
  // 0.5 deg as for the line given with the photographs.
  EXPECT_NEAR(bearing_apart(stored_view_azimuth_deg(project),
                            test::true_view_bearing_deg(truth_station(0))),
              0, 0.5);
  // A pixel off the 3D image (the sky above the face) is said, by pixel.
  r = run_rockface("orient " + project.string() +
                   " --visit 1 --reference-line 2,2,40,3 --azimuth 90");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no 3D image at pixel"), std::string::npos) << r.err;
}

// A card brought to a project that already knows the camera: no
// camera.json beside the photographs, the calibration is the library's one
// that fits them (here by image size: these JPEGs carry no EXIF); a
// project with none that fits refuses, saying what to calibrate, and
// stores nothing.
TEST_F(CardFolder, WithoutCameraJsonThePhotographsTakeTheLibrarysCalibration) {
  const fs::path first =
      card("library-first",
           json{{"format", "rockface-visit/1"}, {"range_pole_m", 2.0}, {"preset", "fast"}});
  const fs::path project = root_ / "library.rockface";
  CliRun r = run_rockface("replay " + first.string() + " --project " + project.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path second =
      card("library-second",
           json{{"format", "rockface-visit/1"}, {"range_pole_m", 2.0}, {"preset", "fast"}});
  fs::remove(second / "camera.json");
  r = run_rockface("replay " + second.string() + " --project " + project.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  {
    auto store = storage::ProjectStore::open(project);
    const auto captures = store.list_captures();
    ASSERT_EQ(captures.size(), 2u);
    EXPECT_EQ(captures[1].calibration_id, captures[0].calibration_id);
    EXPECT_EQ(store.list_calibrations().size(), 1u);
  }
  // A project whose only calibration is of another image size.
  const fs::path other = root_ / "other-size.rockface";
  {
    auto store = storage::ProjectStore::create(other, {});
    storage::Calibration c;
    c.intrinsics.width = 6016;
    c.intrinsics.height = 4016;
    c.intrinsics.fx = c.intrinsics.fy = 5000;
    c.intrinsics.cx = 3008;
    c.intrinsics.cy = 2008;
    c.method = "chessboard:9x6:0.025";
    store.save_calibration(c);
  }
  const auto bytes = fs::file_size(other);
  r = run_rockface("replay " + second.string() + " --project " + other.string());
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("no calibration of an unknown camera, 1500 x 1000 px"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("calibrated at 6016 x 4016 px"), std::string::npos) << r.err;
  EXPECT_EQ(fs::file_size(other), bytes);
  EXPECT_EQ(storage::ProjectStore::open(other).list_visits().size(), 0u);
}

TEST_F(CardFolder, BadFieldDataIsRefusedByNameBeforeAnythingIsStored) {
  json visit{{"format", "rockface-visit/1"}, {"range_pole_m", 2.0}, {"compass", compass()}};
  visit["compass"]["azimuth_deg"] = 400;
  const fs::path dir = card("bad-azimuth", visit);
  const fs::path project = root_ / "bad.rockface";
  CliRun r = run_rockface("replay " + dir.string() + " --project " + project.string());
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("visit.json: compass.azimuth_deg"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(project));

  // A misspelt field is said, never ignored.
  visit = json{{"format", "rockface-visit/1"}, {"range_pole_length", 2.0}};
  const fs::path misspelt = card("misspelt", visit);
  r = run_rockface("replay " + misspelt.string() + " --project " + project.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("visit.json: range_pole_length"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(project));

  // A scene brings its own pole and compass line: the options are refused.
  r = run_rockface("replay " + std::string(ROCKFACE_SOURCE_DIR) +
                   "/tools/samples/tunnel-face-demo.scene.json --project " + project.string() +
                   " --range-pole 2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("for a folder of photographs"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(project));
}

}  // namespace
}  // namespace rockface

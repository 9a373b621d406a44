// Issue 42: the virtual D750 serving two photographs of a face, carried as
// a geologist carries them to a scaled, north-oriented 3D image, its blocks
// and the report. The renderer only makes what the camera's card holds (a
// face seen from two stations with its range pole, and chessboard views
// through the same lens), as a real face and a real board would; no scene
// file is in the user's route:
//   1. `rockface calibrate --pattern ... --project P` on the board's views
//      (JPEGs with a D750's EXIF): the body's calibration in the library;
//   2. the tablet (the program's own runners, the DSLR found on USB): the
//      Capture screen connects, shoots left and right, stores the pair and
//      reconstructs it at the standard preset scaled by the pole; on the
//      Model screen the compass line is tapped on the photograph and its
//      bearing typed;
//   3. `rockface measure P --add-to-visit N` with taps where the face's
//      joint traces run, into the tablet's visit; the Blocks screen's Run
//      analysis; `rockface report` of that one visit, which carries the
//      camera, the scale, north and the blocks.
// Checked against the scene's truth (the renderer's record and the scene's
// joints), never against what the route computes. The tablet runs in this
// process (as capture_screen_camera_fault_test.cpp), not as `rockface ui
// --script`: the card takes the right photograph between the two shots,
// and the compass line's ends are tapped where the photograph is drawn.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "camera/exif.h"
#include "core/common/units.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/model_registration.h"
#include "storage/project/project_store.h"
#include "tests/camera/vcamera/virtual_d750.h"
#include "tests/core/photogrammetry/camera/board_views.h"
#include "tests/support/cli_run.h"
#include "tests/support/plane_angle.h"
#include "tests/support/station_truth.h"
#include "tests/support/temp_folders.h"
#include "tests/support/truth_picks.h"
#include "ui/app/app_state.h"
#include "ui/platform/headless_session.h"

namespace rockface {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CliRun;
using test::run_rockface;

// The demo face (tools/samples/tunnel-face-demo.scene.json) photographed
// at 1200 x 800 px instead of 1500 x 1000: the same lens and field of view
// (focal length and principal point scaled by 0.8, the distortion, in
// normalised coordinates, unchanged), a quicker reconstruction.
constexpr double kShrink = 0.8;

json small_demo_scene() {
  json scene = test::demo_scene();
  json& c = scene.at("imaging").at("camera");
  c["width"] = 1200;
  c["height"] = 800;
  c["fx"] = c.at("fx").get<double>() * kShrink;
  c["fy"] = c.at("fy").get<double>() * kShrink;
  c["cx"] = 599.5;
  c["cy"] = 399.5;
  return scene;
}

// What a D750 writes of itself in each photograph (the fields rockface
// reads). The focal setting only names the calibration the photographs
// take (the views' and the pair's the same): the lens is the render's.
std::vector<uint8_t> as_d750_jpeg(const cv::Mat& image) {
  std::vector<uint8_t> jpeg;
  cv::imencode(".jpg", image, jpeg, {cv::IMWRITE_JPEG_QUALITY, 95});
  camera::ExifInfo e;
  e.make = "NIKON CORPORATION";
  e.model = "NIKON D750";
  e.focal_length_mm = 50;
  e.f_number = 8;
  e.exposure_time_s = 1.0 / 125;
  e.iso = 200;
  e.width = image.cols;
  e.height = image.rows;
  return camera::with_exif(jpeg, e);
}

void write_bytes(const fs::path& file, const std::vector<uint8_t>& bytes) {
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

// Chessboard views through the render's lens (the scene's intrinsics and
// distortion): the board 1 to 1.1 m away, tilted, and moved into each
// corner (its corner points 76 % of the way from the centre to the
// photograph's corners, its white margin still inside the frame) and to
// each side, so that the distortion is measured where the photographs of
// the face use it (calibrate warns below 70 %).
std::vector<std::string> board_views(const json& lens, const fs::path& dir) {
  test::BoardCamera cam;
  cam.size = cv::Size(lens.at("width").get<int>(), lens.at("height").get<int>());
  cam.K = cv::Matx33d(lens.at("fx").get<double>(), 0, lens.at("cx").get<double>(), 0,
                      lens.at("fy").get<double>(), lens.at("cy").get<double>(), 0, 0, 1);
  for (int i = 0; i < 5; ++i) cam.dist[i] = lens.at("distortion")[i].get<double>();
  struct Pose {
    double ax, ay, az, distance, x, y;
  };
  const std::vector<Pose> poses{
      {0.0, 0.0, 0.0, 1.0, 0, 0},
      {0.35, 0.0, 0.05, 1.0, 0, 0},
      {0.0, -0.35, -0.05, 1.0, 0, 0},
      {-0.2, 0.25, 0.1, 1.0, 0, 0},
      {0.05, 0.05, 0.0, 1.1, -0.15, -0.085},
      {-0.05, 0.05, 0.0, 1.1, 0.15, -0.085},
      {0.05, -0.05, 0.0, 1.1, -0.15, 0.085},
      {-0.05, -0.05, 0.0, 1.1, 0.15, 0.085},
      {0.0, 0.2, 0.0, 1.0, -0.13, 0},
      {0.0, -0.2, 0.0, 1.0, 0.13, 0},
  };
  std::vector<std::string> files;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const Pose& p = poses[k];
    cv::Matx33d R;
    cv::Vec3d t;
    test::board_pose(9, 6, 0.035, p.ax, p.ay, p.az, p.distance, cv::Vec3d(p.x, p.y, 0), R, t);
    const cv::Mat view = test::render_board_view(cam, 9, 6, 0.035, R, t);
    files.push_back((dir / ("DSC_" + std::to_string(9001 + k) + ".JPG")).string());
    write_bytes(files.back(), as_d750_jpeg(view));
  }
  return files;
}

std::vector<uint8_t> png_as_d750_jpeg(const fs::path& png) {
  return as_d750_jpeg(cv::imread(png.string(), cv::IMREAD_COLOR));
}

// The geologist's taps: eight along each true trace on the face (its pixels
// in the left photograph, from the renderer's record), named by its joint.
// A joint seen on one facet only has a straight trace, which gives no
// plane: its trace carries the compass reading the geologist took of it
// (the sample's own, tools/samples/tunnel-face-demo.scene.json). The two
// walls either side of the fold outlined as free faces, as the sample's
// areas (measure_demo_picks_test.cpp), scaled to the smaller photograph.
json geologist_picks(const std::vector<test::TruthTrace>& traces) {
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face-demo.scene.json");
  const json sample = json::parse(in);
  std::map<std::string, json> readings;
  for (const json& t : sample.at("picks").at("traces"))
    if (t.contains("compass")) readings[t.at("joint").get<std::string>()] = t.at("compass");
  std::map<std::string, std::set<std::string>> facets;
  for (const auto& t : traces) facets[t.joint].insert(t.patch);
  json picks = json::array();
  for (const auto& t : traces) {
    json pick = {{"id", "T" + std::to_string(picks.size() + 1)},
                 {"joint", t.joint},
                 {"photo", "left"},
                 {"pixels", test::taps_along(t, 8)}};
    if (facets[t.joint].size() == 1 && readings.count(t.joint)) pick["compass"] = readings[t.joint];
    picks.push_back(pick);
  }
  json areas = json::array();
  const std::vector<std::vector<std::array<double, 2>>> walls{
      {{150, 60}, {150, 940}, {749.2, 940}, {746.0, 60}},
      {{746.0, 60}, {749.2, 940}, {1350, 940}, {1350, 60}}};
  for (std::size_t k = 0; k < walls.size(); ++k) {
    json polygon = json::array();
    for (const auto& c : walls[k]) polygon.push_back({c[0] * kShrink, c[1] * kShrink});
    areas.push_back({{"id", k == 0 ? "FW" : "FE"},
                     {"photo", "left"},
                     {"polygon", polygon},
                     {"rock_side", "lower"}});
  }
  return {{"format", "rockface-picks/1"}, {"traces", picks}, {"areas", areas}};
}

std::string pdf_text(const fs::path& pdf) {
  const fs::path txt = fs::path(pdf).replace_extension(".txt");
  if (std::system(("pdftotext -layout " + pdf.string() + " " + txt.string()).c_str()) != 0)
    return "";
  std::ifstream in(txt);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(VirtualD750PairToReport, APairShotOnTheTabletGivesAScaledOrientedVisitItsBlocksAndReport) {
  // The photographs the camera will serve, made before the camera is set up.
  const fs::path root =
      fs::temp_directory_path() / ("rockface-vcam-pair-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "views");
  test::remove_when_passed(root);
  const json scene = small_demo_scene();
  std::ofstream(root / "face.scene.json") << scene.dump(2);
  CliRun r = run_rockface("render " + (root / "face.scene.json").string() + " --out " +
                          (root / "render").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json truth = json::parse(std::ifstream(root / "render" / "truth.json"));
  const test::CardPair pair =
      test::same_size_jpegs(png_as_d750_jpeg(root / "render" / "left.png"),
                            png_as_d750_jpeg(root / "render" / "right.png"));

  const test::VirtualD750 d750 = test::set_up_virtual_d750(pair.left);
  if (d750.iolibs.empty()) {
    // CI builds it (tools/test.sh): there, its absence is a failure.
    if (const char* ci = std::getenv("CI"); ci && std::string(ci) == "true") FAIL() << d750.missing;
    GTEST_SKIP() << d750.missing;
  }
  // The tablet's spool in the camera's folder, not the shared one.
  ::setenv("TMPDIR", d750.folder.c_str(), 1);
  const fs::path project = root / "site.rockface";
  storage::RecordId visit = 0;
  {
    storage::ProjectInfo info;
    info.name = "virtual D750 face";
    auto store = storage::ProjectStore::create(project, info);
    visit = store.begin_visit("tablet");
  }

  // 1. The body's calibration from its views of the board.
  std::string views;
  for (const auto& v : board_views(scene.at("imaging").at("camera"), root / "views"))
    views += " " + v;
  r = run_rockface("calibrate --pattern chessboard:9x6:0.035" + views + " --out " +
                   (root / "d750.json").string() + " --project " + project.string());
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_EQ(r.out.find("no pattern found"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stored in " + project.string() + " as calibration 1 of NIKON D750"),
            std::string::npos)
      << r.out;

  // 2. The tablet: shoot, store and reconstruct, give north.
  const json& line = truth.at("reference_line");
  double taps_deg = 0;
  std::string bearing_typed;
  {
    app::FieldRunners runners("");  // the first DSLR libgphoto2 finds
    ui::FieldServices services = runners.services();
    services.sync = nullptr;
    ui::UiOptions options;
    options.project = project;
    options.max_display_triangles = 20000;
    ui::HeadlessSession s(options, services, 1280, 800);
    s.settle();
    ui::AppState& app = s.state();
    const auto capture_screen = static_cast<std::size_t>(ui::Screen::capture);
    s.tap("Capture");
    s.tap("Connect camera");
    s.settle();
    ASSERT_TRUE(app.capture.camera) << app.capture.connection;
    // The pole's length on its slider: the demo's pole, 2 m between its
    // targets, is the slider's first value (it takes no typed length); the
    // visit's preset the default.
    EXPECT_EQ(app.capture.range_pole_m, truth.at("range_pole").at("length").get<float>());
    EXPECT_EQ(app.capture.preset, Preset::standard);
    s.tap("Shoot left");
    s.settle();
    ASSERT_TRUE(app.capture.left) << app.statuses.line(capture_screen);
    // The geologist walks to the right station: the face as seen from there.
    test::put_on_card(d750, pair.right);
    s.tap("Shoot right");
    s.settle();
    ASSERT_TRUE(app.capture.right) << app.statuses.line(capture_screen);
    EXPECT_EQ(app.capture.left->image.data, pair.left);
    EXPECT_EQ(app.capture.right->image.data, pair.right);
    s.tap("Store pair and reconstruct");
    s.settle();
    const std::string stored = app.statuses.message(capture_screen);
    EXPECT_NE(stored.find("3D image"), std::string::npos) << app.statuses.line(capture_screen);

    s.tap("Model");
    s.settle();
    ASSERT_TRUE(app.model_view.model()) << app.statuses.line(capture_screen);
    s.tap("Give north from a compass line");
    s.frame();
    ASSERT_TRUE(app.model.show_photograph);
    // The line's ends where the renderer drew them in the left photograph.
    const float k = app.model.photo_targets.screen_px_per_photo_px();
    ASSERT_GT(k, 0);
    for (int i = 0; i < 2; ++i) {
      const ImVec2 lo = app.model.photo_targets.image_min();
      const double u = line.at("left")[i][0].get<double>(), v = line.at("left")[i][1].get<double>();
      s.tap(lo.x + static_cast<float>(u + 0.5) * k, lo.y + static_cast<float>(v + 0.5) * k);
    }
    ASSERT_EQ(app.model.north.ends.size(), 2u);
    // The bearing as a compass is read, to a tenth of a degree.
    char typed[16];
    std::snprintf(typed, sizeof typed, "%.1f", line.at("azimuth_deg").get<double>());
    bearing_typed = typed;
    for (const char* c = typed; *c; ++c) s.tap(std::string(1, *c));
    s.tap("Give north");
    s.settle();
    // What the taps add to north (north_entry_test.cpp): each end within half
    // a screen pixel, 0.5 / k photograph pixels, turning the line by up to
    // (1 / k) / length rad, and the bearing typed to 0.05 deg.
    const Eigen::Vector2d a(line.at("left")[0][0].get<double>(),
                            line.at("left")[0][1].get<double>());
    const Eigen::Vector2d b(line.at("left")[1][0].get<double>(),
                            line.at("left")[1][1].get<double>());
    taps_deg = rad_to_deg((1.0 / k) / (a - b).norm()) + 0.05;
  }
  {
    auto store = storage::ProjectStore::open(project);
    const auto captures = store.list_captures(visit);
    ASSERT_EQ(captures.size(), 1u);
    ASSERT_TRUE(captures[0].calibration_id) << "the pair took the body's calibration";
    const storage::Model m = store.load_model(store.list_models().back().id);
    EXPECT_EQ(m.preset, "standard");
    const storage::ModelRegistration reg = storage::read_model_registration(m.registration);
    EXPECT_EQ(reg.kind, "range_pole_compass");
    EXPECT_TRUE(reg.oriented());
    // The scale against the stations' true distance (1.8 m): the pole's two
    // targets, 2 m apart at 9.5 m, are located to a few millimetres each in
    // 1200 px photographs (JPEG, blur 0.5 px), about 0.4 % of the scale;
    // 1 % also covers the ellipse-centre bias of the printed targets (as
    // card_folder_replay_test.cpp holds the replayed card's).
    const double base = test::true_base_m(truth.at("cameras")[0], truth.at("cameras")[1]);
    ASSERT_TRUE(reg.base_m);
    EXPECT_NEAR(*reg.base_m, base, 0.01 * base);
    // North: the compass line fixes it to ~0.1 deg from exact pixels; 0.5 deg
    // is a compass reading's own tolerance, plus what the taps add.
    ASSERT_TRUE(m.camera_to_mesh);
    const double off = std::abs(std::remainder(
        test::model_axis_bearing_deg(m) - test::true_view_bearing_deg(truth.at("cameras")[0]),
        360.0));
    std::printf("tablet visit: base %.4f m (true %.4f), north %.2f deg off (budget %.2f)\n",
                *reg.base_m, base, off, 0.5 + taps_deg);
    EXPECT_LT(off, 0.5 + taps_deg);
  }

  // 3. The traces mapped by the geologist's taps, the blocks, the report.
  const auto traces = test::face_traces(root / "render" / "truth.json");
  ASSERT_GE(traces.size(), 3u);
  const json picks = geologist_picks(traces);
  std::ofstream(root / "picks.json") << picks.dump(1);
  // The joints whose plane the compass gives (their traces straight on one
  // facet): not measured on the 3D image, so not held to its precision.
  std::set<std::string> by_compass;
  for (const auto& t : picks.at("traces"))
    if (t.contains("compass")) by_compass.insert(t.at("joint").get<std::string>());
  // Into the tablet's visit: one visit for the geologist's day at the face.
  r = run_rockface("measure " + project.string() + " --traces " + (root / "picks.json").string() +
                   " --out " + (root / "measures.json").string() + " --add-to-visit " +
                   std::to_string(visit));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  std::printf("%s", r.out.c_str());
  const json measures = json::parse(std::ifstream(root / "measures.json"));
  std::map<std::string, double> sigma_deg;
  for (const auto& j : measures.at("joints"))
    if (j.at("orientation_known").get<bool>())
      sigma_deg[j.at("label").get<std::string>()] = j.at("sigma_deg").get<double>();

  storage::RecordId mapped = 0;
  {
    // The tablet opens the project on its newest visit, its own, now
    // holding the traces; its Blocks screen runs the analysis.
    app::FieldRunners runners("");
    ui::FieldServices services = runners.services();
    services.sync = nullptr;
    services.camera = nullptr;
    ui::UiOptions options;
    options.project = project;
    options.max_display_triangles = 20000;
    ui::HeadlessSession s(options, services, 1280, 800);
    s.settle();
    ui::AppState& app = s.state();
    ASSERT_TRUE(app.session && app.session->visit());
    mapped = *app.session->visit();
    EXPECT_EQ(mapped, visit) << "the traces went into a visit of their own";
    s.tap("Blocks");
    s.tap("Run analysis");
    s.settle();
    ASSERT_TRUE(app.session->analysis()) << "no analysis stored";
  }
  auto store = storage::ProjectStore::open(project);
  // The joints measured from their traces across the fold against the
  // scene's true planes: the fit's own sigma to 3 sigma (the 3D image's
  // noise over the relief of the traces), plus north as given on the tablet
  // (its budget above) and the pole's levelling (~0.1 deg,
  // replay_face_picks_test.cpp), taken as 0.2.
  std::set<std::string> compared;
  for (const auto& j : store.list_joints(mapped))
    for (const auto& t : scene.at("joints"))
      if (t.at("id") == j.label && sigma_deg.count(j.label) && !by_compass.count(j.label)) {
        compared.insert(j.label);
        const double e = test::plane_angle_deg(
            test::pole_of(j.dip_deg, j.dipdir_deg),
            test::pole_of(t.at("dip").get<double>(), t.at("dipdir").get<double>()));
        std::printf("%s measured %.2f/%.2f (sigma %.2f deg), scene %.0f/%.0f: %.2f deg off\n",
                    j.label.c_str(), j.dip_deg, j.dipdir_deg, sigma_deg[j.label],
                    t.at("dip").get<double>(), t.at("dipdir").get<double>(), e);
        EXPECT_LT(e, 3 * sigma_deg[j.label] + 0.5 + taps_deg + 0.2) << j.label;
      }
  // J1 and J3 each cross the fold (the sample's T1/T2 and T4/T5).
  EXPECT_EQ(compared, (std::set<std::string>{"J1", "J3"})) << r.out;
  const auto runs = store.list_analyses(mapped);
  ASSERT_FALSE(runs.empty());
  const auto blocks = store.load_analysis(runs.back().id).blocks;
  ASSERT_GE(blocks.size(), 1u);
  // The demo's keyblock (J1 x J2 x J3 on the face): finite and removable.
  EXPECT_TRUE(std::any_of(blocks.begin(), blocks.end(),
                          [](const auto& b) { return b.finite && b.removable; }));

  // One report, of the one visit: its camera and calibration, what scaled
  // and oriented it, and its blocks with their verdicts.
  EXPECT_EQ(store.list_visits().size(), 1u);
  const fs::path visit_pdf = root / "visit.pdf";
  r = run_rockface("report " + project.string() + " --visit " + std::to_string(visit) + " --out " +
                   visit_pdf.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string tablet = pdf_text(visit_pdf), &blocks_text = tablet;
  // The body as it told its serial over USB (vcamera.c's DeviceInfo: "0.1").
  EXPECT_NE(tablet.find("camera: NIKON D750 (serial 0.1)"), std::string::npos) << tablet;
  EXPECT_NE(tablet.find("calibration: chessboard:9x6:0.035"), std::string::npos) << tablet;
  EXPECT_NE(tablet.find("preset: standard"), std::string::npos) << tablet;
  // What scaled and oriented it: the pole's length and the compass line's
  // bearing as the tablet took them.
  EXPECT_NE(tablet.find("scale: range pole (2.000 m)"), std::string::npos) << tablet;
  EXPECT_NE(tablet.find("north: compass"), std::string::npos) << tablet;
  EXPECT_NE(tablet.find("reference line bearing " + bearing_typed + " deg"), std::string::npos)
      << tablet;
  EXPECT_NE(blocks_text.find("removable"), std::string::npos) << blocks_text;
  ::unsetenv("TMPDIR");
}

}  // namespace
}  // namespace rockface

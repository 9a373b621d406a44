// `rockface measure` as a user runs it: the real binary on a replayed
// project and on a model file, real picks, the outputs and the store
// checked; bad picks refused by name with nothing stored.
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "storage/exchange/export_joints_csv.h"
#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/support/json_file.h"
#include "tests/support/plane_angle.h"
#include "tests/support/truth_picks.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rockface::test::CliRun;
using rockface::test::plane_angle_deg;
using rockface::test::pole_of;
using rockface::test::read_json;
using rockface::test::run_rockface;
using rockface::test::write_json;

// Pixel of a world point in a rendered camera of truth.json (pinhole with
// the Brown distortion of the intrinsics, OpenCV's model).
std::array<double, 2> project(const json& truth, int station, const json& world) {
  const json& cam = truth.at("cameras")[station];
  const json& k = truth.at("intrinsics");
  double c[3] = {0, 0, 0};
  for (int r = 0; r < 3; ++r)
    for (int i = 0; i < 3; ++i)
      c[r] += cam.at("rotation_world_to_camera")[r][i].get<double>() *
              (world[i].get<double>() - cam.at("position")[i].get<double>());
  const double x = c[0] / c[2], y = c[1] / c[2], r2 = x * x + y * y;
  const auto& d = k.at("distortion");
  const double k1 = d[0], k2 = d[1], p1 = d[2], p2 = d[3], k3 = d[4];
  const double radial = 1 + k1 * r2 + k2 * r2 * r2 + k3 * r2 * r2 * r2;
  const double xd = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x);
  const double yd = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y;
  return {k.at("fx").get<double>() * xd + k.at("cx").get<double>(),
          k.at("fy").get<double>() * yd + k.at("cy").get<double>()};
}

// The demo face rendered and replayed into a project (the true traces are
// what the replay analyses; this suite measures on its model).
struct Site {
  fs::path dir, project, truth;
  json truth_json;
};

Site make_site(const std::string& name) {
  Site s;
  s.dir = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(s.dir);
  fs::create_directories(s.dir);
  write_json(s.dir / "face.scene.json", rockface::test::demo_scene());
  const CliRun r = run_rockface("render " + (s.dir / "face.scene.json").string() + " --out " +
                                (s.dir / "render").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  s.truth = s.dir / "render" / "truth.json";
  s.truth_json = read_json(s.truth);
  s.project = s.dir / "site.rockface";
  return s;
}

// The true world polyline of a joint across both facets (west end, fold,
// east end): a trace given as 3D points.
json joint_points(const json& truth, const std::string& joint) {
  json pts = json::array();
  for (const char* patch : {"FACE_W", "FACE_E"})
    for (const auto& t : truth.at("traces"))
      if (t.at("joint") == joint && t.at("patch") == patch)
        for (const auto& p : t.at("world"))
          if (pts.empty() || pts.back() != p) pts.push_back(p);
  return pts;
}

TEST(MeasureCli, OnAProjectMeasuresStoresAndRefusesBadPicksByName) {
  const Site site = make_site("rockface-measure-cli");
  CliRun r = run_rockface("replay " + (site.dir / "face.scene.json").string() + " --project " +
                          site.project.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;

  json traces = rockface::test::face_picks(rockface::test::face_traces(site.truth));
  traces.push_back({{"id", "P-J1"}, {"points", joint_points(site.truth_json, "J1")}});
  traces.push_back({{"id", "P-J3"}, {"points", joint_points(site.truth_json, "J3")}});
  const json picks = {
      {"format", "rockface-picks/1"},
      {"traces", traces},
      // A patch of FACE_E (east of the fold at u ~ 750, away from the traces).
      {"areas",
       {{{"id", "A1"},
         {"photo", "left"},
         {"polygon", {{1000, 600}, {1200, 600}, {1200, 800}, {1000, 800}}},
         {"rock_side", "lower"}}}},
      {"points", {{{"id", "P1"}, {"photo", "left"}, {"pixel", {1100, 700}}, {"radius", 0.3}}}}};
  write_json(site.dir / "picks.json", picks);
  const fs::path out = site.dir / "measures.json", png = site.dir / "net.png",
                 csv = site.dir / "dips.csv";
  r = run_rockface("measure " + site.project.string() + " --traces " +
                   (site.dir / "picks.json").string() + " --out " + out.string() + " --png " +
                   png.string() + " --csv " + csv.string() + " --sets auto");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json m = read_json(out);
  EXPECT_EQ(m.at("format"), "rockface-measures/1");
  const double sigma = m.at("point_sigma_m").get<double>();
  EXPECT_GT(sigma, 0.001);  // the replay's predicted sigma_Z (7 mm at 10 m)
  EXPECT_LT(sigma, 0.02);
  std::map<std::string, json> by_id;
  for (const auto& x : m.at("measurements")) by_id[x.at("id").get<std::string>()] = x;
  ASSERT_EQ(by_id.size(), traces.size() + 2);

  // Each tapped piece lies on one flat facet: a straight line, no plane.
  for (const auto& [id, x] : by_id) {
    if (id[0] != 'T') continue;
    EXPECT_EQ(x.at("method"), "taps");
    EXPECT_FALSE(x.at("orientation_known").get<bool>()) << id;
    EXPECT_TRUE(x.at("dip").is_null()) << id;
    EXPECT_NE(x.at("note").get<std::string>().find("orientation unknown"), std::string::npos);
    EXPECT_EQ(x.at("photo"), "left");
    EXPECT_EQ(x.at("pixels").size(), 8u);
    EXPECT_GT(x.at("length_m").get<double>(), 0.5);
  }
  EXPECT_EQ(by_id.at("S1").at("method"), "semi_automatic");
  EXPECT_GT(by_id.at("S1").at("path_pixels").size(), 100u);  // one per pixel step

  // Fitted together across the fold, J1's and J3's pieces give their planes.
  // Expected error: the fit's sigma (0.2-0.5 deg, sigma_Z over ~0.1 m of
  // relief) and the registration's (~0.1 deg). Seen: 0.27 and 0.09 deg.
  const std::map<std::string, Eigen::Vector3d> truth{
      {"J1", pole_of(60, 200)}, {"J2", pole_of(75, 110)}, {"J3", pole_of(20, 350)}};
  for (const auto& j : m.at("joints")) {
    const std::string label = j.at("label");
    if (label == "J2") {  // one piece on one facet
      EXPECT_FALSE(j.at("orientation_known").get<bool>());
      continue;
    }
    ASSERT_TRUE(j.at("orientation_known").get<bool>()) << label << ": " << j.at("note");
    EXPECT_LT(plane_angle_deg(pole_of(j.at("dip"), j.at("dipdir")), truth.at(label)), 1.0) << label;
    EXPECT_LT(j.at("sigma_deg").get<double>(), 1.0);
  }
  // The true 3D points (west end, fold, east end) give the plane to within
  // the registration: they are exact, and the relief test sees the fold.
  for (const char* id : {"P-J1", "P-J3"}) {
    const json& x = by_id.at(id);
    ASSERT_TRUE(x.at("orientation_known").get<bool>()) << id << ": " << x.at("note");
    EXPECT_LT(plane_angle_deg(pole_of(x.at("dip"), x.at("dipdir")), truth.at(id + 2)), 0.01) << id;
  }
  // FACE_E: y = 5211880.3 - (x - 512340) / 15 + 0.04 (z - 410). The area
  // fits ~10^4 points of sigma 7 mm: its own error is hundredths of a
  // degree; the registration's ~0.1 deg and the surface smoothing of dense
  // matching near the fold dominate.
  const Eigen::Vector3d face_e(1.0 / 15, 1.0, -0.04);
  const json& a = by_id.at("A1");
  ASSERT_TRUE(a.at("orientation_known").get<bool>()) << a.at("note");
  EXPECT_LT(plane_angle_deg(pole_of(a.at("dip"), a.at("dipdir")), face_e), 0.5);
  EXPECT_GT(a.at("area_m2").get<double>(), 0.3);  // 200 x 200 px at ~230 px/m: ~0.75 m^2
  const json& p = by_id.at("P1");
  ASSERT_TRUE(p.at("orientation_known").get<bool>()) << p.at("note");
  EXPECT_LT(plane_angle_deg(pole_of(p.at("dip"), p.at("dipdir")), face_e), 2.0);

  // Sets over the known planes that are not free faces: P-J1, P-J3, P1.
  // Automatic clustering keeps a set only with two or more poles, and
  // leaves a pole more than 35 deg from every set out (a scattered joint):
  // of these three, 30 to 75 deg apart, at least two form a set.
  int members = 0;
  ASSERT_FALSE(m.at("sets").empty());
  for (const auto& s : m.at("sets")) {
    members += static_cast<int>(s.at("members").size());
    for (const auto& id : s.at("members")) {
      const std::string member = id.get<std::string>();
      EXPECT_TRUE(member == "P-J1" || member == "P-J3" || member == "P1") << member;
      EXPECT_EQ(by_id.at(member).at("set"), s.at("label"));
    }
    EXPECT_EQ(s.at("count").get<int>(), static_cast<int>(s.at("members").size()));
  }
  EXPECT_GE(members, 2);
  EXPECT_LE(members, 3);

  // The picture and the CSV.
  std::ifstream png_in(png, std::ios::binary);
  char magic[4] = {};
  png_in.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  std::ifstream csv_in(csv);
  const auto rows = rockface::storage::read_joints_csv(csv_in, Eigen::Vector3d::Zero(), "dips.csv");
  // P-J1, P-J3 (traces), P1 (point), and each joint the traces name whose
  // plane their points give (T1, T2, ... name J1-J3, MEASURES.json
  // joints[]), stored as the replay stores it; A1 is a free face.
  std::map<std::string, std::string> named;  // label -> "traces T1 T4 ..."
  for (const auto& j : m.at("joints"))
    if (j.at("orientation_known").get<bool>()) {
      std::string source = "traces";
      for (const auto& t : j.at("traces")) source += " " + t.get<std::string>();
      named[j.at("label").get<std::string>()] = source;
    }
  EXPECT_GE(named.size(), 1u) << m.at("joints").dump(1);
  EXPECT_EQ(rows.size(), 3u + named.size());

  // The store: a new visit with every measurement and the joint table.
  std::size_t visits = 0;
  {
    auto store = rockface::storage::ProjectStore::open(site.project);
    const auto v = store.list_visits();
    ASSERT_EQ(v.size(), 2u);  // the replay's and the measurement's
    visits = v.size();
    const auto ms = store.list_measurements(v.back().id);
    EXPECT_EQ(ms.size(), traces.size() + 2);
    for (const auto& x : ms)
      if (x.label == "S1") {
        EXPECT_EQ(x.photo, "left");
        EXPECT_GT(x.pixels.size(), 100u);  // the traced path
      }
    const auto joints = store.list_joints(v.back().id);
    EXPECT_EQ(joints.size(), 3u + named.size());
    for (const auto& j : joints) {
      if (const auto it = named.find(j.label); it != named.end()) {
        EXPECT_EQ(j.source, it->second);  // fitted to several traces: no one measurement
        EXPECT_EQ(j.type, "trace");
        continue;
      }
      EXPECT_TRUE(j.label == "P-J1" || j.label == "P-J3" || j.label == "P1") << j.label;
      EXPECT_TRUE(j.measurement_id.has_value()) << j.label;
    }
  }

  // The right photograph: a point picked in the left one, then where the
  // right camera sees that point, lands on the same surface point. Expected:
  // the registration's pose of the right camera from the relative
  // orientation (rotation sigma ~0.01 deg: ~2 mm at 10 m) and the pick's
  // rounding to the surface; seen 1 mm.
  {
    const json left = {{"format", "rockface-picks/1"},
                       {"points", {{{"id", "L"}, {"photo", "left"}, {"pixel", {1100, 700}}}}}};
    write_json(site.dir / "left.json", left);
    r = run_rockface("measure " + site.project.string() + " --traces " +
                     (site.dir / "left.json").string() + " --out " +
                     (site.dir / "left-out.json").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json seen = read_json(site.dir / "left-out.json").at("measurements")[0].at("point");
    const auto px = project(site.truth_json, 1, seen);
    const json right = {{"format", "rockface-picks/1"},
                        {"points", {{{"id", "R"}, {"photo", "right"}, {"pixel", {px[0], px[1]}}}}}};
    write_json(site.dir / "right.json", right);
    r = run_rockface("measure " + site.project.string() + " --traces " +
                     (site.dir / "right.json").string() + " --out " +
                     (site.dir / "right-out.json").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json again = read_json(site.dir / "right-out.json").at("measurements")[0].at("point");
    double d2 = 0;
    for (int i = 0; i < 3; ++i) d2 += std::pow(again[i].get<double>() - seen[i].get<double>(), 2);
    EXPECT_LT(std::sqrt(d2), 0.005);
    visits += 2;  // each run stores its visit
  }

  // Bad picks: exit 2, the pick named, nothing stored, no output.
  struct Bad {
    const char* name;
    std::string picks;
    const char* named;
  };
  const std::vector<Bad> bad{
      {"outside",
       R"({"format": "rockface-picks/1", "traces": [{"id": "T1", "photo": "left",
           "pixels": [[700, 500], [760, 540], [1700, 560]]}]})",
       "traces[0].pixels[2]: pixel (1700, 560) is outside the left photograph"},
      {"no-mesh",
       R"({"format": "rockface-picks/1", "areas": [{"id": "A1", "photo": "left",
           "polygon": [[2, 2], [30, 2], [30, 30], [2, 30]]}]})",
       // Its first corner is off the 3D image: named before the polygon.
       "areas[0].polygon[0]: pixel (2, 2) of the left photograph hits no surface of the 3D "
       "image: move the corner onto the mapped face"},
      {"one-point",
       R"({"format": "rockface-picks/1", "traces": [{"id": "T1", "photo": "left",
           "pixels": [[700, 500]]}]})",
       "traces[0].pixels: a trace needs at least two picks, found 1"},
      {"same-point",
       R"({"format": "rockface-picks/1", "traces": [{"id": "T1", "photo": "left",
           "pixels": [[700, 500], [700, 500]]}]})",
       "traces[0].pixels: all 2 picks are the same point"},
      {"nan",
       R"({"format": "rockface-picks/1", "traces": [{"id": "T1", "photo": "left",
           "pixels": [[700, 500], [NaN, 540]]}]})",
       "traces[0].pixels[1][0]: must be finite, not NaN"},
      {"nan-3d",
       R"({"format": "rockface-picks/1", "traces": [{"id": "T1",
           "points": [[512340, 5211880, 411], [512341, 5211880, null]]}]})",
       "traces[0].points[1][2]: must be a number, not null"},
  };
  for (const auto& b : bad) {
    const fs::path file = site.dir / (std::string(b.name) + ".json");
    std::ofstream(file) << b.picks;
    const fs::path bad_out = site.dir / (std::string(b.name) + "-out.json");
    r = run_rockface("measure " + site.project.string() + " --traces " + file.string() + " --out " +
                     bad_out.string());
    EXPECT_EQ(r.exit_code, 2) << b.name << ": " << r.err;
    EXPECT_NE(r.err.find(b.named), std::string::npos) << b.name << ": " << r.err;
    EXPECT_NE(r.err.find(file.string()), std::string::npos) << b.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(bad_out)) << b.name;
  }
  auto store = rockface::storage::ProjectStore::open(site.project);
  EXPECT_EQ(store.list_visits().size(), visits);  // nothing stored
  fs::remove_all(site.dir);
}

TEST(MeasureCli, OnAModelFileWithItsCamera) {
  const Site site = make_site("rockface-measure-cli-ply");
  const fs::path render = site.dir / "render", model = site.dir / "model.ply";
  CliRun r = run_rockface("reconstruct " + (render / "left.png").string() + " " +
                          (render / "right.png").string() + " --camera " +
                          (render / "camera.json").string() + " --out " + model.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  json picks = {{"format", "rockface-picks/1"},
                {"traces", rockface::test::face_picks(rockface::test::face_traces(site.truth))}};
  write_json(site.dir / "picks.json", picks);
  const fs::path out = site.dir / "measures.json";
  r = run_rockface("measure " + model.string() + " --traces " + (site.dir / "picks.json").string() +
                   " --out " + out.string() + " --camera " + (render / "camera.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json m = read_json(out);
  EXPECT_EQ(m.at("measurements").size(), picks.at("traces").size());
  // Unregistered (no scale source): the planes are in the model frame, but
  // flat-facet pieces are still lines and J1 across the fold still a plane.
  bool semi = false;
  for (const auto& x : m.at("measurements"))
    if (x.at("method") == "semi_automatic") {
      semi = true;
      EXPECT_GT(x.at("path_pixels").size(), 100u);  // the left photograph came from the PLY
    }
  EXPECT_TRUE(semi);
  for (const auto& j : m.at("joints")) {
    if (j.at("label") == "J1") {
      EXPECT_TRUE(j.at("orientation_known").get<bool>()) << j.at("note");
    }
  }

  // A model file knows only its left photograph.
  write_json(
      site.dir / "right.json",
      {{"format", "rockface-picks/1"},
       {"traces", {{{"id", "T1"}, {"photo", "right"}, {"pixels", {{700, 500}, {760, 540}}}}}}});
  r = run_rockface("measure " + model.string() + " --traces " + (site.dir / "right.json").string() +
                   " --out " + out.string() + " --camera " + (render / "camera.json").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("traces[0].photo"), std::string::npos) << r.err;
  // Without the camera, the model's pixels cannot be placed.
  r = run_rockface("measure " + model.string() + " --traces " + (site.dir / "picks.json").string() +
                   " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--camera"), std::string::npos) << r.err;
  fs::remove_all(site.dir);
}

}  // namespace

// Issue 43's round trip on a rendered tunnel face: "the same rendered face
// (a tunnel sample) exported by rockface and re-imported through every
// format gives the same joint planes within the stated error, and the same
// blocks". The demo tunnel face (tools/samples/tunnel-face-demo.scene.json,
// its picks) is replayed by rockface's own renderer (photographs, 3D image,
// traces measured, joints); the visit is exported (`export --what
// mesh,cloud`: the textured OBJ, the binary PLY, the cloud's PLY) and each
// file imported into a project of its own, seen from the left camera's
// station. On it the original visit's measured traces (their 3D points,
// projected into the imported visit's view) are measured again, as the
// tablet's taps would be, and the visit analysed. Against the original
// visit: each joint's plane, and every block's traces, code, finiteness and
// removability. The replayed 3D image is dense (150 k points at the fast
// preset), so its cloud meshes again (unlike the few-polygon meshes of
// tests/support/rendered_tunnel_project.h, whose clouds hold only their
// corners).
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "tests/integration/import/imported_view.h"
#include "tests/support/cli_run.h"
#include "tests/support/json_file.h"
#include "tests/support/truth_picks.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rockface::test::read_json;
using rockface::test::run_rockface;
using rockface::test::write_json;

// Upward unit normal of a plane by dip / dip direction (degrees), x East,
// y North, z Up (DESIGN.md), written out here rather than taken from core.
Eigen::Vector3d normal_of(double dip_deg, double dipdir_deg) {
  const double d = dip_deg * M_PI / 180, a = dipdir_deg * M_PI / 180;
  return {std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d)};
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180 / M_PI;
}

// The demo's left camera station (its scene's imaging.stations[0]): the
// imported visits are seen from where the field photographs were taken.
const std::string kLeftStation = "512339.1,5211870.5,411.6";

// `rockface analyse` of a visit's scene: its report.
json analysed(const fs::path& project, rockface::storage::RecordId visit, const fs::path& dir) {
  json scene;
  {
    auto store = rockface::storage::ProjectStore::open(project);
    scene = rockface::storage::make_scene_json(rockface::storage::load_scene_source(store, visit));
  }
  write_json(dir / "visit.scene.json", scene);
  const auto r = run_rockface("analyse " + (dir / "visit.scene.json").string() + " --out " +
                              (dir / "report.json").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? read_json(dir / "report.json") : json::object();
}

// One re-imported file: its joints (label to normal) and its analysis.
struct ImportedAgain {
  std::string file;
  std::map<std::string, Eigen::Vector3d> joints;
  std::map<std::string, double> sigma_deg;  // each fitted joint's stated one sigma
  json report;
};

class ImportRenderedRoundTrip : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("import-rendered-round-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    json scene = rockface::test::demo_scene();
    std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) +
                     "/tools/samples/tunnel-face-demo.scene.json");
    scene["picks"] = json::parse(in).at("picks");
    write_json(dir_ / "face.scene.json", scene);
    project_ = dir_ / "face.rockface";
    // The fast preset: the round trip does not depend on the 3D image's
    // resolution, and CI's time does.
    replay_ = run_rockface("replay " + (dir_ / "face.scene.json").string() + " --project " +
                           project_.string() + " --preset fast");
    if (replay_.exit_code != 0) return;
    const fs::path exported = dir_ / "exported";
    export_ = run_rockface("export " + project_.string() + " --visit 1 --what mesh,cloud --out " +
                           exported.string());
    if (export_.exit_code != 0) return;
    original_joints_ = joints_of(project_, 1);
    original_ = analysed(project_, 1, dir_);
    for (const auto& entry : fs::directory_iterator(exported)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".obj" && ext != ".ply") continue;
      again_.push_back(imported_again(entry.path()));
    }
    std::sort(again_.begin(), again_.end(),
              [](const ImportedAgain& a, const ImportedAgain& b) { return a.file < b.file; });
  }

  static std::map<std::string, Eigen::Vector3d> joints_of(const fs::path& project,
                                                          rockface::storage::RecordId visit) {
    std::map<std::string, Eigen::Vector3d> out;
    auto store = rockface::storage::ProjectStore::open(project);
    for (const auto& j : store.list_joints(visit))
      out[j.label] = normal_of(j.dip_deg, j.dipdir_deg);
    return out;
  }

  // `file` imported into a project of its own, the original visit's traces
  // (and free faces, if it has them) measured again on it through its view.
  static ImportedAgain imported_again(const fs::path& file) {
    ImportedAgain out;
    out.file = file.filename().string();
    const fs::path again = dir_ / ("again-" + out.file);
    fs::create_directories(again);
    const fs::path project = again / "site.rockface";
    auto r = run_rockface("import " + project.string() + " " + file.string() + " --view-from " +
                          kLeftStation);
    EXPECT_EQ(r.exit_code, 0) << out.file << ": " << r.err;
    if (r.exit_code != 0) return out;
    json picks = {
        {"format", "rockface-picks/1"}, {"traces", json::array()}, {"areas", json::array()}};
    rockface::storage::RecordId visit = 0;
    {
      auto original = rockface::storage::ProjectStore::open(project_);
      auto store = rockface::storage::ProjectStore::open(project);
      // Both projects' frames: the original's datum and the imported one's
      // (the export writes survey coordinates).
      const Eigen::Vector3d from_datum = original.project().datum;
      const auto view = rockface::test::newest_imported_view(store);
      EXPECT_TRUE(view) << out.file;
      if (!view) return out;
      const auto& K = view->K;
      const auto pixel = [&](const Eigen::Vector3d& p) { return view->pixel(p + from_datum); };
      const auto in_view = [&](const std::array<double, 2>& uv) {
        return uv[0] > 1 && uv[1] > 1 && uv[0] < K.width - 2 && uv[1] < K.height - 2;
      };
      visit = *store.latest_visit();
      std::vector<rockface::storage::Measurement> given;
      for (const auto& m : original.list_measurements(1)) {
        if (m.kind != rockface::storage::Measurement::Kind::trace) {
          // The demo's surface patches (its face's two facets, the floor
          // and the walls) are the scene's given geometry, stored as areas
          // by the replay, not measured on its 3D image: they go across as
          // given, moved to the imported project's datum.
          rockface::storage::Measurement a = m;
          a.id = 0;
          a.visit_id = visit;
          a.model_id.reset();
          a.photo_capture_id.reset();
          for (auto& p : a.points) p += from_datum - view->datum;
          given.push_back(std::move(a));
          continue;
        }
        json pixels = json::array();
        for (const auto& p : m.points)
          if (const auto uv = pixel(p); in_view(uv)) pixels.push_back({uv[0], uv[1]});
        EXPECT_EQ(pixels.size(), m.points.size()) << out.file << " " << m.label << " out of view";
        json t = {{"id", m.label}, {"photo", "left"}, {"pixels", pixels}};
        if (!m.joint_label.empty()) t["joint"] = m.joint_label;
        if (m.compass_dip_deg && m.compass_dipdir_deg)
          t["compass"] = {{"dip", *m.compass_dip_deg}, {"dip_direction", *m.compass_dipdir_deg}};
        picks["traces"].push_back(t);
      }
      store.save_measurements(visit, given);
    }
    write_json(again / "picks.json", picks);
    r = run_rockface(
        "measure " + project.string() + " --traces " + (again / "picks.json").string() + " --out " +
        (again / "measures.json").string() + " --add-to-visit " + std::to_string(visit));
    EXPECT_EQ(r.exit_code, 0) << out.file << ": " << r.err << r.out;
    if (r.exit_code != 0) return out;
    out.joints = joints_of(project, visit);
    const json measures = read_json(again / "measures.json");
    for (const auto& j : measures.at("joints"))
      if (j.contains("sigma_deg") && j.at("sigma_deg").is_number())
        out.sigma_deg[j.at("label").get<std::string>()] = j.at("sigma_deg").get<double>();
    out.report = analysed(project, visit, again);
    return out;
  }

  static void TearDownTestSuite() {  // kept for a look when a test failed
    if (::testing::UnitTest::GetInstance()->failed_test_count() == 0) fs::remove_all(dir_);
  }
  void SetUp() override {
    ASSERT_EQ(replay_.exit_code, 0) << replay_.err;
    ASSERT_EQ(export_.exit_code, 0) << export_.err << export_.out;
    ASSERT_EQ(again_.size(), 3u) << "the OBJ, the PLY and the cloud's PLY\n" << export_.out;
  }

  static inline fs::path dir_, project_;
  static inline rockface::test::CliRun replay_, export_;
  static inline std::map<std::string, Eigen::Vector3d> original_joints_;
  static inline json original_;
  static inline std::vector<ImportedAgain> again_;
};

// Through the meshes (the OBJ, the binary PLY) the imported surface is the
// original's triangles: to 0.05 mm in the OBJ (four decimals of survey
// metres), exactly in the PLY (doubles about the datum). The traces are
// tapped at the original trace's own points (one every ~5 mm along it), so
// the trace measured again holds the same surface points, draped anew
// between taps 5 mm apart (within a triangle, on the original polyline),
// and its fit weighs them a little differently. 0.02 degree: 0.05 mm over
// a 1.5 m trace tilts its plane by atan(0.05 mm / 1.5 m) = 0.002 degree,
// and a re-weighting of the same points moves it by a small part of its
// fitted one sigma (0.2 to 0.9 degree for J1 and J3 on the imported
// surfaces): 0.02 degree is a ninth of the smallest.
constexpr double kSameSurfaceTolDeg = 0.02;

bool is_cloud(const std::string& file) {
  return file.find("-cloud.ply") != std::string::npos;
}

// Every format: each joint within its stated error (the one sigma the
// measuring states for its fitted plane; J2 is the compass reading the demo
// picks give with its trace, carried across, and is the same reading). The
// cloud's PLY is meshed again by the import: the same vertices, other
// triangles (the import's meshing, not the stereo grid), so a point picked
// between vertices moves by a part of the 3D image's depth noise (14 mm one
// sigma predicted at the fast preset), independently from triangle to
// triangle: its planes move by a part of their one sigma, which is that
// noise's effect on the fit. The meshes are held to kSameSurfaceTolDeg.
void expect_the_same_joint_planes(const std::map<std::string, Eigen::Vector3d>& original_joints,
                                  const std::vector<ImportedAgain>& trips) {
  ASSERT_EQ(original_joints.size(), 3u);
  for (const auto& again : trips) {
    ASSERT_EQ(again.joints.size(), original_joints.size()) << again.file;
    for (const auto& [label, n] : original_joints) {
      ASSERT_TRUE(again.joints.count(label)) << again.file << " has no " << label;
      const double off = angle_deg(again.joints.at(label), n);
      const double sigma = again.sigma_deg.count(label) ? again.sigma_deg.at(label) : 0;
      std::printf("%s %s: %.5f deg from the original (stated one sigma %.2f deg)\n",
                  again.file.c_str(), label.c_str(), off, sigma);
      if (again.sigma_deg.count(label)) {
        EXPECT_LT(off, sigma) << again.file << " " << label;
      }
      if (!is_cloud(again.file)) {
        EXPECT_LT(off, kSameSurfaceTolDeg) << again.file << " " << label;
      }
    }
    // J1 and J3 are fitted from their traces; J2 is the compass's.
    EXPECT_TRUE(again.sigma_deg.count("J1") && again.sigma_deg.count("J3")) << again.file;
  }
}

// Every block: its traces, code, finiteness and removability the same
// through every format; through the meshes its volume within 1 %: its
// joint planes are within kSameSurfaceTolDeg (0.35 mm over a metre) and
// pass through the same surface points (to 0.05 mm), so its joint faces
// (a few m2 on the demo's 0.72 m3 keyblock; the face's patches do not
// move) shift by under 0.4 mm: a few dm3, under 1 %.
void expect_the_same_blocks(const json& original_report, const std::vector<ImportedAgain>& trips) {
  const json& original = original_report.at("blocks");
  ASSERT_GE(original.size(), 1u) << original_report.dump(1);
  for (const auto& a : original)
    std::printf("%s: traces %s, code %s, %s, %s\n", a.at("id").get<std::string>().c_str(),
                a.at("traces").dump().c_str(), a.at("code").get<std::string>().c_str(),
                a.at("finite").get<bool>() ? "finite" : "infinite",
                a.value("removable", false) ? "removable" : "not removable");
  for (const auto& again : trips) {
    ASSERT_EQ(again.report.at("blocks").size(), original.size()) << again.file;
    for (std::size_t i = 0; i < original.size(); ++i) {
      const json& a = original[i];
      const json& b = again.report.at("blocks")[i];
      EXPECT_EQ(b.at("traces"), a.at("traces")) << again.file << " block " << i;
      EXPECT_EQ(b.at("code"), a.at("code")) << again.file << " block " << i;
      EXPECT_EQ(b.at("finite"), a.at("finite")) << again.file << " block " << i;
      EXPECT_EQ(b.value("removable", false), a.value("removable", false))
          << again.file << " block " << i;
      std::printf("%s %s: volume %s m3 (original %s m3)\n", again.file.c_str(),
                  b.at("id").get<std::string>().c_str(), b.value("volume", json()).dump().c_str(),
                  a.value("volume", json()).dump().c_str());
      if (!is_cloud(again.file) && a.contains("volume") && a.at("volume").is_number()) {
        ASSERT_TRUE(b.contains("volume") && b.at("volume").is_number()) << again.file;
        EXPECT_NEAR(b.at("volume").get<double>(), a.at("volume").get<double>(),
                    0.01 * a.at("volume").get<double>())
            << again.file << " block " << i;
      }
    }
  }
}

// One test, so that the replay and the three round trips (~30 s) run once
// in CI, not once a test.
TEST_F(ImportRenderedRoundTrip, EveryFormatGivesTheSameJointPlanesAndBlocks) {
  std::printf("%s", replay_.out.c_str());
  expect_the_same_joint_planes(original_joints_, again_);
  expect_the_same_blocks(original_, again_);
}

}  // namespace

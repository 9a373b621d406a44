// Issue 43, "Out": `rockface export` of a visit made by the field workflow
// (the demo face replayed with its picks: a 3D image, traces, joints, joint
// sets and blocks, in LV95-like survey coordinates), read back by the
// office's own readers: the DXF by ezdxf (Debian's python3-ezdxf), the OBJ
// and PLY by CloudCompare's command line (under xvfb). The truth is the
// scene's joint planes and the stored records, not the export code.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/analysis/block_reading.h"
#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/support/dxf_reading.h"
#include "tests/support/truth_picks.h"

namespace rockface {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CliRun;
using test::run_rockface;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Eigen::Vector3d point_of(const json& p) {
  return {p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>()};
}

// Upward unit normal of a plane given by dip / dip direction (degrees):
// DESIGN.md's frame (x East, y North, z Up), written out here rather than
// taken from core/geometry, so that a convention slip there shows.
Eigen::Vector3d normal_of(double dip_deg, double dipdir_deg) {
  const double d = dip_deg * M_PI / 180, a = dipdir_deg * M_PI / 180;
  return {std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d)};
}

class VisitExport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("rockface-export-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    scene_ = test::demo_scene();
    std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) +
                     "/tools/samples/tunnel-face-demo.scene.json");
    const json with_picks = json::parse(in);
    scene_["picks"] = with_picks.at("picks");
    std::ofstream(root_ / "face.scene.json") << scene_.dump(2);
    project_ = root_ / "face.rockface";
    // The fast preset: the export's reading does not depend on the 3D
    // image's resolution, and CI's time does.
    replay_ = run_rockface("replay " + (root_ / "face.scene.json").string() + " --project " +
                           project_.string() + " --preset fast");
    out_ = root_ / "export";
    if (replay_.exit_code == 0)
      export_ = run_rockface("export " + project_.string() + " --visit 1 --out " + out_.string());
  }
  static void TearDownTestSuite() {
    if (!::testing::Test::HasFailure()) fs::remove_all(root_);
  }
  void SetUp() override {
    ASSERT_EQ(replay_.exit_code, 0) << replay_.err;
    ASSERT_EQ(export_.exit_code, 0) << export_.err << export_.out;
  }

  // The predicted depth precision (one sigma, m) the replay reports for the
  // 3D image: what the traces' distances to their true planes are held to.
  static double depth_sigma_m() {
    std::smatch m;
    const std::regex re("predicted depth precision ([0-9.]+) mm");
    if (!std::regex_search(replay_.out, m, re)) return -1;
    return std::stod(m[1]) / 1000;
  }

  static json dxf() {
    const test::DxfReading r = test::read_dxf(out_ / "visit-1.dxf");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return r.exit_code == 0 ? r.drawing : json::object();
  }

  static inline fs::path root_, project_, out_;
  static inline json scene_;
  static inline CliRun replay_, export_;
};

TEST_F(VisitExport, WritesEveryItemTheVisitHasAndSaysWhatItLacks) {
  for (const char* f : {"visit-1.dxf", "visit-1-traces.csv", "visit-1-joints.csv"})
    EXPECT_TRUE(fs::exists(out_ / f)) << f << "\n" << export_.out;
  int objs = 0, plys = 0, clouds = 0;
  for (const auto& e : fs::directory_iterator(out_)) {
    const std::string name = e.path().filename().string();
    objs += e.path().extension() == ".obj";
    clouds += name.find("-cloud.ply") != std::string::npos;
    plys += e.path().extension() == ".ply" && name.find("-cloud") == std::string::npos;
  }
  EXPECT_GE(objs, 1);
  EXPECT_EQ(plys, objs);
  EXPECT_EQ(clouds, objs);
  // The demo face has no tunnel: the profile is left out, and said.
  EXPECT_NE(export_.out.find("profile not exported"), std::string::npos) << export_.out;
}

TEST_F(VisitExport, DxfTracesLieOnTheTrueJointPlanesInSurveyCoordinates) {
  const json d = dxf();
  std::map<std::string, json> truth;
  for (const auto& j : scene_.at("joints")) truth[j.at("id").get<std::string>()] = j;
  storage::ProjectStore store = storage::ProjectStore::open(project_);
  std::map<std::string, std::string> set_of_joint;
  for (const auto& j : store.list_joints(1)) set_of_joint[j.label] = j.set_label;
  const auto measurements = store.list_measurements(1);

  const double sigma = depth_sigma_m();
  ASSERT_GT(sigma, 0) << replay_.out;
  // A picked point's distance to its true plane: the 3D image's depth error
  // (3 sigma of the precision it predicts) plus a pick's pixel at the face
  // (1 px at ~8 m, fx 2232 at the demo's 1500 px: 3.6 mm).
  const double tolerance = 3 * sigma + 0.0036;

  std::size_t traces = 0;
  for (const auto& m : measurements) {
    if (m.kind != storage::Measurement::Kind::trace) continue;
    ++traces;
    // Its polyline in the DXF: the same number of points, on its set's layer.
    const std::string layer =
        "TRACES_" + (set_of_joint[m.joint_label].empty() ? std::string("UNASSIGNED")
                                                         : set_of_joint[m.joint_label]);
    const auto it = truth.find(m.joint_label);
    ASSERT_NE(it, truth.end()) << m.label << " names joint " << m.joint_label;
    const Eigen::Vector3d n =
        normal_of(it->second.at("dip").get<double>(), it->second.at("dipdir").get<double>());
    const Eigen::Vector3d on = point_of(it->second.at("point"));
    bool found = false;
    for (const auto& e : d.at("entities")) {
      if (e.at("kind") != "polyline3d" || e.at("points").size() != m.points.size()) continue;
      // Matched by its first point (absolute, 0.1 mm: dxflib writes 16 decimals).
      const Eigen::Vector3d first = point_of(e.at("points").at(0));
      if ((first - (m.points.front() + store.project().datum)).norm() > 1e-4) continue;
      found = true;
      std::string l = e.at("layer");
      std::transform(l.begin(), l.end(), l.begin(), ::toupper);
      std::string want = layer;
      std::transform(want.begin(), want.end(), want.begin(), ::toupper);
      EXPECT_EQ(l, want) << m.label;
      EXPECT_FALSE(e.at("closed").get<bool>());
      for (const auto& p : e.at("points"))
        EXPECT_LT(std::abs(n.dot(point_of(p) - on)), tolerance)
            << m.label << " on " << m.joint_label;
    }
    EXPECT_TRUE(found) << "trace " << m.label << " not in the DXF";
  }
  EXPECT_GE(traces, 3u);
}

TEST_F(VisitExport, DxfJointDiscsHaveTheMeasuredOrientations) {
  const json d = dxf();
  storage::ProjectStore store = storage::ProjectStore::open(project_);
  const auto joints = store.list_joints(1);
  std::size_t discs = 0;
  for (const auto& e : d.at("entities")) {
    const std::string layer = e.at("layer");
    if (layer.rfind("JOINTS_", 0) != 0) continue;
    ASSERT_EQ(e.at("kind"), "polyline3d");
    EXPECT_TRUE(e.at("closed").get<bool>());
    ++discs;
    // The disc's plane from three of its points, a quarter turn apart.
    const auto& p = e.at("points");
    ASSERT_GE(p.size(), 12u);
    const Eigen::Vector3d a = point_of(p.at(0)), b = point_of(p.at(p.size() / 4)),
                          c = point_of(p.at(p.size() / 2));
    Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    if (n.z() < 0) n = -n;
    // One stored joint has this orientation (to 0.01°: the disc's points
    // are written to 16 digits, its plane is exact) and a point at the
    // disc's centre.
    const Eigen::Vector3d centre = (a + c) / 2;
    bool matched = false;
    for (const auto& j : joints) {
      if (!j.point) continue;
      const double angle =
          std::acos(std::clamp(n.dot(normal_of(j.dip_deg, j.dipdir_deg)), -1.0, 1.0)) * 180 / M_PI;
      if (angle < 0.01 && (centre - (*j.point + store.project().datum)).norm() < 1e-3)
        matched = true;
    }
    EXPECT_TRUE(matched) << "disc on " << layer << " matches no joint";
  }
  std::size_t placed = 0;
  for (const auto& j : joints) placed += j.point.has_value();
  EXPECT_EQ(discs, placed);
}

TEST_F(VisitExport, DxfBlocksAreClosedMeshesWithTheReportedVolume) {
  const json d = dxf();
  storage::ProjectStore store = storage::ProjectStore::open(project_);
  const auto runs = store.list_analyses(1);
  ASSERT_FALSE(runs.empty());
  const auto run = store.load_analysis(runs.back().id);
  std::vector<double> volumes;
  for (const auto& b : run.blocks)
    if (b.finite && b.volume && !analysis::vertices_are_surface_loop(b))
      volumes.push_back(*b.volume);
  // TB1, the demo's keyblock: finite and non-convex (its faces reported).
  ASSERT_FALSE(volumes.empty());
  std::size_t meshes = 0;
  for (const auto& e : d.at("entities")) {
    if (e.at("kind") != "polyface") continue;
    ++meshes;
    EXPECT_EQ(e.at("layer").get<std::string>().rfind("BLOCKS_", 0), 0u);
    std::vector<Eigen::Vector3d> v;
    for (const auto& p : e.at("vertices")) v.push_back(point_of(p));
    // Closed: every edge is shared by exactly two triangles, once each way.
    std::map<std::pair<int, int>, int> edges;
    double volume = 0;
    const Eigen::Vector3d o = v.front();  // about a corner: survey coordinates keep their digits
    for (const auto& f : e.at("faces")) {
      ASSERT_EQ(f.size(), 3u);
      const int i = f[0], j = f[1], k = f[2];
      for (auto [s, t] : {std::pair{i, j}, std::pair{j, k}, std::pair{k, i}}) ++edges[{s, t}];
      volume += (v[i] - o).dot((v[j] - o).cross(v[k] - o)) / 6;
    }
    for (const auto& [edge, count] : edges) {
      EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
      EXPECT_EQ(edges.count({edge.second, edge.first}), 1u)
          << "edge " << edge.first << "-" << edge.second << " has no twin: the mesh is open";
    }
    // The divergence theorem over the DXF's triangles against the volume
    // the analysis reported (its own mass properties of the same
    // polyhedron). The project stores the corners to 1e-5 m (survey
    // coordinates, storage/report/report_numbers.h), so the mesh's volume
    // may differ by its surface area times that step.
    double area = 0;
    for (const auto& f : e.at("faces"))
      area += ((v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]])).norm() / 2;
    bool matched = false;
    for (double rv : volumes) matched |= std::abs(volume - rv) <= area * 1e-5;
    std::ostringstream reported;
    for (double rv : volumes) reported << " " << rv;
    EXPECT_TRUE(matched) << "mesh volume " << volume << " m3 (surface " << area
                         << " m2) matches no reported block:" << reported.str();
  }
  EXPECT_EQ(meshes, volumes.size());
}

TEST_F(VisitExport, CloudCompareReadsTheMeshesWithTheStoredPointsInSurveyCoordinates) {
  storage::ProjectStore store = storage::ProjectStore::open(project_);
  const Eigen::Vector3d datum = store.project().datum;
  const auto models = store.list_visit_models(1);
  ASSERT_FALSE(models.empty());
  for (const auto& summary : models) {
    const auto model = store.load_model(summary.id);
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (const auto& v : model.mesh.vertices) {
      lo = lo.cwiseMin(v + datum);
      hi = hi.cwiseMax(v + datum);
    }
    for (const std::string suffix : {".obj", ".ply", "-cloud.ply"}) {
      const fs::path file = out_ / ("visit-1-model-" + std::to_string(summary.id) + suffix);
      const fs::path asc = root_ / ("cc-" + std::to_string(summary.id) + suffix + ".asc");
      // -GLOBAL_SHIFT AUTO: CloudCompare shifts large coordinates to keep
      // its float precision and restores them on saving (its own way with
      // survey coordinates); mesh files give their vertices as a cloud.
      const CliRun cc = test::run_command(
          "xvfb-run -a CloudCompare -SILENT -AUTO_SAVE OFF -O -GLOBAL_SHIFT AUTO " + file.string() +
          (suffix == ".obj" || suffix == ".ply" ? " -EXTRACT_VERTICES" : "") +
          " -C_EXPORT_FMT ASC -PREC 4 -SAVE_CLOUDS FILE " + asc.string());
      ASSERT_EQ(cc.exit_code, 0) << cc.out;
      ASSERT_TRUE(fs::exists(asc)) << file << "\n" << cc.out;
      std::ifstream in(asc);
      std::size_t count = 0;
      Eigen::Vector3d clo = Eigen::Vector3d::Constant(1e300), chi = -clo;
      for (std::string line; std::getline(in, line);) {
        std::istringstream row(line);
        Eigen::Vector3d p;
        if (!(row >> p.x() >> p.y() >> p.z())) continue;
        ++count;
        clo = clo.cwiseMin(p);
        chi = chi.cwiseMax(p);
      }
      EXPECT_EQ(count, model.mesh.vertices.size()) << file;
      // 0.2 mm: the OBJ's 4 decimals (0.05 mm) and CloudCompare's float
      // storage after its shift (~1e-7 of a few metres) and its 4 decimals.
      EXPECT_LT((clo - lo).cwiseAbs().maxCoeff(), 2e-4) << file << " min " << clo.transpose();
      EXPECT_LT((chi - hi).cwiseAbs().maxCoeff(), 2e-4) << file << " max " << chi.transpose();
    }
  }
}

TEST_F(VisitExport, CsvHoldsEveryTraceAndJointForDips) {
  storage::ProjectStore store = storage::ProjectStore::open(project_);
  std::size_t traces = 0;
  for (const auto& m : store.list_measurements(1))
    traces += m.kind == storage::Measurement::Kind::trace;
  std::istringstream csv(slurp(out_ / "visit-1-traces.csv"));
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("id,dip,dip_direction,set,", 0), 0u) << header;
  std::size_t rows = 0;
  while (std::getline(csv, line)) rows += !line.empty();
  EXPECT_EQ(rows, traces);
  std::istringstream joints(slurp(out_ / "visit-1-joints.csv"));
  std::getline(joints, header);
  rows = 0;
  while (std::getline(joints, line)) rows += !line.empty();
  EXPECT_EQ(rows, store.list_joints(1).size());
}

TEST_F(VisitExport, AnItemTheVisitLacksOrAnUnknownOneIsRefusedByName) {
  CliRun r = run_rockface("export " + project_.string() + " --visit 1 --what profile --out " +
                          (root_ / "none").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--what profile"), std::string::npos) << r.err;
  r = run_rockface("export " + project_.string() + " --visit 1 --what meshes --out " +
                   (root_ / "none").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no export item 'meshes'"), std::string::npos) << r.err;
  r = run_rockface("export " + project_.string() + " --visit 7 --out " + (root_ / "none").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no visit 7"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rockface

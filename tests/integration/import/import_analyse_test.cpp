// `analyse`, `rockmass` and `wedges` on an imported scan (issue 43): a
// face cloud written here from plain geometry (no rockface code: a shallow
// four-sided pyramid of rock standing out of the face, its points on an
// exact grid in survey coordinates), imported as a visit's 3D image, the
// traces of six joints (three sets of two) tapped on its virtual view where
// the joints' planes truly cut the pyramid (plane-triangle intersections
// computed here), and its four facets outlined as the free surface, all
// measured into the same visit, as the tablet does. Against the planes
// written: the measured joints; the keyblock that the analysis finds from
// the traces, its apex (the one point three of the planes pass through) and
// its volume (summed here); the rock-mass sheet's three sets and their
// spacing; the wedges' sets around the project's tunnel (refused by name
// while the project has none, and asking for the drive's axis while the
// visit is not placed in it).
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "tests/integration/import/imported_view.h"
#include "tests/support/cli_run.h"
#include "tests/support/json_file.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rockface::test::read_json;
using rockface::test::run_rockface;
using rockface::test::write_json;

// The face: a 6 x 5 m rim leaning back 0.06 m a metre of height (the
// drive runs north, the face looks south; no facet stands exactly vertical,
// where "upper" and "lower" would swap on a rounding), its centre kCentre
// standing 0.7 m out toward the viewer; four planar triangles, each a rim
// edge and the centre.
constexpr double kE0 = 512337.0, kE1 = 512343.0, kZ0 = 410.0, kZ1 = 415.0;
double rim_n(double z) {
  return 5211880.3 + 0.06 * (z - kZ0);
}
const Eigen::Vector3d kCentre(512340.0, rim_n(412.5) - 0.7, 412.5);

// The demo face's three sets, two joints each: J1 to J3 through one point
// 0.35 m behind the rim, so that their traces close a triangle on the face
// and the keyblock they cut has its apex there; J4 to J6 parallel to them
// kSpacing away, on the side away from that triangle (they cut no trace of
// the keyblock).
struct TrueJoint {
  std::string id;
  double dip, dipdir;
  double offset;  // m along the normal from kApex
};
constexpr double kSpacing = 0.6;
const TrueJoint kJoints[] = {{"J1", 60, 200, 0},         {"J2", 75, 110, 0},
                             {"J3", 20, 350, 0},         {"J4", 60, 200, -kSpacing},
                             {"J5", 75, 110, -kSpacing}, {"J6", 20, 350, kSpacing}};
const Eigen::Vector3d kApex(512339.5, 5211880.8, 412.5);

Eigen::Vector3d normal_of(double dip_deg, double dipdir_deg) {
  const double d = dip_deg * M_PI / 180, a = dipdir_deg * M_PI / 180;
  return {std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d)};
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180 / M_PI;
}

// The face's northing at (e, z): the rim's less the pyramid's height there.
double face_n(double e, double z) {
  const double u = (e - kCentre.x()) / (0.5 * (kE1 - kE0));
  const double w = (z - kCentre.z()) / (0.5 * (kZ1 - kZ0));
  return rim_n(z) - 0.7 * (1 - std::max(std::abs(u), std::abs(w)));
}

std::vector<std::array<Eigen::Vector3d, 3>> face_triangles() {
  const Eigen::Vector3d rim[4] = {{kE0, rim_n(kZ0), kZ0},
                                  {kE1, rim_n(kZ0), kZ0},
                                  {kE1, rim_n(kZ1), kZ1},
                                  {kE0, rim_n(kZ1), kZ1}};
  std::vector<std::array<Eigen::Vector3d, 3>> out;
  for (int i = 0; i < 4; ++i) out.push_back({rim[i], rim[(i + 1) % 4], kCentre});
  return out;
}

// The joint's true trace on the face: the segments where its plane cuts
// each triangle, sampled every 2 cm, kept 15 cm inside the rim (the mesh's
// border triangles are the hull's).
std::vector<Eigen::Vector3d> true_trace(const TrueJoint& j, int* pieces) {
  const Eigen::Vector3d n = normal_of(j.dip, j.dipdir);
  std::vector<Eigen::Vector3d> out;
  *pieces = 0;
  for (const auto& t : face_triangles()) {
    std::vector<Eigen::Vector3d> ends;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d &a = t[i], &b = t[(i + 1) % 3];
      const double da = n.dot(a - kApex) - j.offset, db = n.dot(b - kApex) - j.offset;
      if ((da < 0) != (db < 0)) ends.push_back(a + da / (da - db) * (b - a));
    }
    if (ends.size() != 2) continue;
    ++*pieces;
    const int steps = static_cast<int>((ends[1] - ends[0]).norm() / 0.02);
    for (int s = 0; s <= steps; ++s) {
      const Eigen::Vector3d p = ends[0] + (ends[1] - ends[0]) * (double(s) / steps);
      if (std::abs(p.x() - kCentre.x()) < 2.85 && std::abs(p.z() - kCentre.z()) < 2.35)
        out.push_back(p);
    }
  }
  // Triangle by triangle the pieces come in no order: as one polyline they
  // are sorted along the trace's strike (its direction in the face).
  const Eigen::Vector3d along = n.cross(Eigen::Vector3d::UnitY()).normalized();
  std::sort(out.begin(), out.end(), [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return along.dot(a) < along.dot(b);
  });
  return out;
}

// The true keyblock: the rock behind the face and inside the cone that J1
// to J3 cut from kApex toward the face. Its sides are those of the face
// triangle its traces close (the corners where each pair of planes' line
// through kApex comes out of the face, marched to 0.1 mm); its volume
// summed over columns of 2 x 2 mm of (E, Z), each column's depth exact (the
// cone's bounds and the face's northing are linear in N).
struct TrueKeyblock {
  std::array<Eigen::Vector3d, 3> corners;
  double volume_m3 = 0;
};
TrueKeyblock true_keyblock() {
  TrueKeyblock out;
  Eigen::Vector3d n[3];
  for (int k = 0; k < 3; ++k) n[k] = normal_of(kJoints[k].dip, kJoints[k].dipdir);
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int c = 0; c < 3; ++c) {
    Eigen::Vector3d d = n[pairs[c][0]].cross(n[pairs[c][1]]).normalized();
    if (d.y() > 0) d = -d;  // toward the viewer
    Eigen::Vector3d p = kApex;
    while (p.y() > face_n(p.x(), p.z())) p += 1e-4 * d;
    out.corners[c] = p;
  }
  const Eigen::Vector3d mid = (out.corners[0] + out.corners[1] + out.corners[2]) / 3;
  double side[3];
  for (int k = 0; k < 3; ++k) side[k] = n[k].dot(mid - kApex) > 0 ? 1 : -1;
  Eigen::Vector3d lo = kApex, hi = kApex;
  for (const auto& c : out.corners) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
  constexpr double h = 0.002;
  for (double e = lo.x() - 0.3; e < hi.x() + 0.3; e += h)
    for (double z = lo.z() - 0.3; z < hi.z() + 0.3; z += h) {
      const double ec = e + h / 2, zc = z + h / 2;
      double from = face_n(ec, zc), to = 1e300;
      for (int k = 0; k < 3; ++k) {
        // side * (n . (X - apex)) > 0, linear in N.
        const double a = side[k] * n[k].y();
        const double b = side[k] * (n[k].x() * (ec - kApex.x()) + n[k].z() * (zc - kApex.z()));
        if (a > 0)
          from = std::max(from, kApex.y() - b / a);
        else if (a < 0)
          to = std::min(to, kApex.y() - b / a);
        else if (b <= 0)
          to = -1e300;
      }
      if (to > from) out.volume_m3 += (to - from) * h * h;
    }
  return out;
}

class ImportAnalyse : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("import-analyse-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    project_ = dir_ / "site.rockface";
    // The cloud: a 2.5 cm grid over the rim's (E, Z), each point on the
    // pyramid, written to 0.1 mm as a scanner's export does.
    {
      std::ofstream csv(dir_ / "face.csv");
      csv << "x,y,z\n";
      char line[96];
      for (int i = 0; i <= 240; ++i)
        for (int k = 0; k <= 200; ++k) {
          const double e = kE0 + 0.025 * i, z = kZ0 + 0.025 * k;
          std::snprintf(line, sizeof line, "%.4f,%.4f,%.4f\n", e, face_n(e, z), z);
          csv << line;
        }
    }
    map_imported(project_, dir_ / "face.csv", dir_ / "picks.json", dir_ / "measures.json", visit_);
    // A failed import or measuring stopped map_imported at its assertion.
    if (visit_ == 0 || !fs::exists(dir_ / "measures.json")) return;
    ready_ = true;
  }
  // `file` imported into `project` as a new visit (`visit`), seen from the
  // scanner's station; the traces tapped on its virtual view where the
  // joints truly cut the pyramid, one per joint, named by it; the four
  // facets outlined as the free surface, the rock behind them; all measured
  // into the visit, as the tablet does.
  static void map_imported(const fs::path& project, const fs::path& file,
                           const fs::path& picks_file, const fs::path& measures_file,
                           rockface::storage::RecordId& visit) {
    auto r = run_rockface("import " + project.string() + " " + file.string() +
                          " --view-from 512340,5211870.5,411.6");
    ASSERT_EQ(r.exit_code, 0) << r.err;

    // The traces tapped on the virtual view, one per joint, named by it;
    // the four facets outlined as the free surface, the rock behind them.
    json picks = {
        {"format", "rockface-picks/1"}, {"traces", json::array()}, {"areas", json::array()}};
    {
      auto store = rockface::storage::ProjectStore::open(project);
      const auto view = rockface::test::newest_imported_view(store);
      ASSERT_TRUE(view);
      const auto& K = view->K;
      const auto pixel = [&](const Eigen::Vector3d& p) { return view->pixel(p); };
      int t = 0;
      for (const auto& j : kJoints) {
        int pieces = 0;
        json pixels = json::array();
        for (const auto& p : true_trace(j, &pieces)) {
          const auto [u, v] = pixel(p);
          if (u > 1 && v > 1 && u < K.width - 2 && v < K.height - 2) pixels.push_back({u, v});
        }
        // A trace on one planar triangle is a straight line, which gives
        // no plane: each must bend over a fold of the pyramid.
        ASSERT_GE(pieces, 2) << j.id;
        ASSERT_GE(pixels.size(), 40u) << j.id;
        picks["traces"].push_back({{"id", "T" + std::to_string(++t)},
                                   {"joint", j.id},
                                   {"photo", "left"},
                                   {"pixels", pixels}});
      }
      int a = 0;
      for (const auto& tri : face_triangles()) {
        // Its rim corners 3 cm in along the folds toward the centre (on the
        // mesh, off the hull's border): the facets' outlines share their
        // folds, the free surface has no gap between them.
        json polygon = json::array();
        for (const auto& corner : tri) {
          const auto [u, v] = pixel(corner + 0.03 * (kCentre - corner).normalized());
          polygon.push_back({u, v});
        }
        // The rock lies north of every facet (behind the face): on the side
        // of its upward normal ("upper") or not.
        Eigen::Vector3d up = (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalized();
        if (up.z() < 0) up = -up;
        picks["areas"].push_back({{"id", "F" + std::to_string(++a)},
                                  {"photo", "left"},
                                  {"polygon", polygon},
                                  {"rock_side", up.y() > 0 ? "upper" : "lower"}});
      }
      visit = *store.latest_visit();
    }
    write_json(picks_file, picks);
    r = run_rockface("measure " + project.string() + " --traces " + picks_file.string() +
                     " --out " + measures_file.string() + " --add-to-visit " +
                     std::to_string(visit));
    ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  }

  // `rockface analyse` of the visit's scene: its report.
  static json analysed(const fs::path& project, rockface::storage::RecordId visit,
                       const fs::path& dir) {
    json scene;
    {
      auto store = rockface::storage::ProjectStore::open(project);
      scene =
          rockface::storage::make_scene_json(rockface::storage::load_scene_source(store, visit));
    }
    write_json(dir / "visit.scene.json", scene);
    const auto r = run_rockface("analyse " + (dir / "visit.scene.json").string() + " --out " +
                                (dir / "report.json").string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_json(dir / "report.json");
  }

  static void TearDownTestSuite() {  // kept for a look when a test failed
    if (::testing::UnitTest::GetInstance()->failed_test_count() == 0) fs::remove_all(dir_);
  }
  void SetUp() override { ASSERT_TRUE(ready_) << "the import or the measuring failed"; }

  static inline fs::path dir_, project_;
  static inline rockface::storage::RecordId visit_ = 0;
  static inline bool ready_ = false;
};

// 0.01 degree for a measured plane: the traces are tapped exactly where
// the planes cut the written surface (no noise), and the picker lands on
// the stored mesh, whose vertices lie on the pyramid to 0.05 mm (the 0.1 mm
// digits); 0.05 mm over the 3 to 7 m of a trace tilts its plane by
// atan(0.05 mm / 1.5 m) = 0.002 degree. A trace measured on anything but the
// stored surface (a display copy's coarser triangles cut the folds by
// centimetres) misses by more.
constexpr double kPlaneTolDeg = 0.01;

TEST_F(ImportAnalyse, TheTracesMeasureTheWrittenPlanes) {
  const json measured = read_json(dir_ / "measures.json");
  int found = 0;
  for (const auto& m : measured.at("measurements"))
    for (std::size_t j = 0; j < std::size(kJoints); ++j)
      if (m.at("id") == "T" + std::to_string(j + 1)) {
        ++found;
        ASSERT_TRUE(m.at("orientation_known").get<bool>()) << m.dump();
        const double off =
            angle_deg(normal_of(m.at("dip").get<double>(), m.at("dipdir").get<double>()),
                      normal_of(kJoints[j].dip, kJoints[j].dipdir));
        EXPECT_LT(off, kPlaneTolDeg) << kJoints[j].id << " measured " << m.dump();
      }
  EXPECT_EQ(found, static_cast<int>(std::size(kJoints))) << measured.dump();
}

TEST_F(ImportAnalyse, AnalyseFindsTheKeyblockWithItsVerdicts) {
  const json report = analysed(project_, visit_, dir_);
  ASSERT_GE(report.at("blocks").size(), 1u) << report.dump(1);
  const auto nearest_to_apex = [](const json& b) {
    double d = 1e9;
    for (const auto& v : b.at("vertices"))
      d = std::min(
          d, (Eigen::Vector3d(v[0].get<double>(), v[1].get<double>(), v[2].get<double>()) - kApex)
                 .norm());
    return d;
  };
  const json* keyblock = nullptr;
  for (const auto& b : report.at("blocks")) {
    // An infinite block has no volume or mode (the slabs open between the parallel
    // joints of a set: core/analysis/README.md, "Joints taken as parallel").
    std::printf("%s: traces %s, code %s, %s, %s, mode %s, volume %s m3, %.4f m from the apex\n",
                b.at("id").get<std::string>().c_str(), b.at("traces").dump().c_str(),
                b.at("code").get<std::string>().c_str(),
                b.at("finite").get<bool>() ? "finite" : "infinite",
                b.value("removable", false) ? "removable" : "not removable",
                b.value("mode", json()).dump().c_str(), b.value("volume", json()).dump().c_str(),
                nearest_to_apex(b));
    std::set<std::string> traces;
    for (const auto& t : b.at("traces")) traces.insert(t.get<std::string>());
    if (traces == std::set<std::string>{"T1", "T2", "T3"}) keyblock = &b;
  }
  // The keyblock is the one the traces of J1 to J3 close.
  ASSERT_NE(keyblock, nullptr) << "no block of T1, T2 and T3";
  const json& block = *keyblock;
  EXPECT_EQ(block.at("source"), "traces");
  EXPECT_TRUE(block.at("finite").get<bool>()) << block.dump();
  EXPECT_TRUE(block.at("removable").get<bool>()) << block.dump();
  const TrueKeyblock truth = true_keyblock();
  // 1 %: the truth's 2 mm columns miss at most a column's width along the
  // footprint's 7 m of outline at a mean depth of 0.4 m (0.3 %, less as
  // the misses cancel); the measured planes, within kPlaneTolDeg, move the
  // faces by under 0.4 mm over their 3 m2 (0.1 %).
  EXPECT_NEAR(block.at("volume").get<double>(), truth.volume_m3, 0.01 * truth.volume_m3);
  std::printf("keyblock %.4f m3, true %.4f m3\n", block.at("volume").get<double>(),
              truth.volume_m3);
  // It slides (or falls) along the line of J1 and J2 when it moves along one:
  // that line, downward, from the written planes. 0.05 degree: the planes
  // are within kPlaneTolDeg each.
  const json& mode = block.at("mode");
  ASSERT_TRUE(mode.contains("type")) << block.dump();
  if (mode.at("type") == "sliding" && mode.at("planes").size() == 2) {
    Eigen::Vector3d line = normal_of(kJoints[0].dip, kJoints[0].dipdir)
                               .cross(normal_of(kJoints[1].dip, kJoints[1].dipdir));
    if (line.z() > 0) line = -line;
    const Eigen::Vector3d moves(mode.at("direction")[0].get<double>(),
                                mode.at("direction")[1].get<double>(),
                                mode.at("direction")[2].get<double>());
    EXPECT_LT(std::acos(std::min(1.0, line.normalized().dot(moves.normalized()))) * 180 / M_PI,
              0.05)
        << mode.dump();
  }
  // 1 mm: the measured planes are within kPlaneTolDeg of the written ones
  // and pass through their traces' points (on the surface to 0.05 mm) 1 to 2
  // m from the apex: tan(0.01 deg) x 2 m = 0.35 mm, and 0.05 mm more.
  EXPECT_LT(nearest_to_apex(block), 0.001) << block.dump();
}

// The visit exported by rockface (`export --what mesh,cloud`: the textured
// OBJ, the binary PLY, the cloud's PLY, all in survey coordinates) and each
// file imported again into a project of its own, the same traces tapped
// and the same facets outlined on it, analysed: each file's name and its
// analysis report, beside the original visit's report.
struct RoundTrips {
  json original;
  std::vector<std::pair<std::string, json>> again;
};

class ImportAnalyseRoundTrip : public ImportAnalyse {
 protected:
  static RoundTrips round_trips() {
    RoundTrips out;
    const fs::path exported = dir_ / "exported";
    const auto r =
        run_rockface("export " + project_.string() + " --visit " + std::to_string(visit_) +
                     " --what mesh,cloud --out " + exported.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    out.original = analysed(project_, visit_, dir_);
    for (const auto& entry : fs::directory_iterator(exported)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".obj" && ext != ".ply") continue;
      const std::string name = entry.path().filename().string();
      const fs::path again = dir_ / ("again-" + name);
      fs::create_directories(again);
      rockface::storage::RecordId visit = 0;
      map_imported(again / "site.rockface", entry.path(), again / "picks.json",
                   again / "measures.json", visit);
      if (visit == 0 || !fs::exists(again / "measures.json")) continue;  // failed, said above
      out.again.emplace_back(name, analysed(again / "site.rockface", visit, again));
    }
    return out;
  }
};

// The keyblock (J1 to J3's traces) through the round trip of every format:
// the same code, verdicts and mode, its volume within 0.1 %. The surfaces
// agree to 0.1 mm (the OBJ's four decimals; the PLYs' doubles about the
// datum exactly), the taps land on the same planes within 0.002 degree
// each (kPlaneTolDeg's reasoning), moving the block's faces by under 0.1 mm
// over its 3 m2 of footprint at a mean depth of 0.4 m: 0.03 %.
TEST_F(ImportAnalyseRoundTrip, ExportedAndImportedAgainTheKeyblockIsTheSame) {
  const RoundTrips trips = round_trips();
  ASSERT_EQ(trips.again.size(), 3u) << "the OBJ, the PLY and the cloud's PLY";
  const auto keyblock = [](const json& report) -> const json* {
    for (const auto& b : report.at("blocks"))
      if (b.at("traces").size() == 3) {
        std::set<std::string> traces;
        for (const auto& t : b.at("traces")) traces.insert(t.get<std::string>());
        if (traces == std::set<std::string>{"T1", "T2", "T3"}) return &b;
      }
    return nullptr;
  };
  const json* a = keyblock(trips.original);
  ASSERT_NE(a, nullptr);
  for (const auto& [name, report] : trips.again) {
    const json* b = keyblock(report);
    ASSERT_NE(b, nullptr) << name;
    EXPECT_EQ(b->at("code"), a->at("code")) << name;
    EXPECT_EQ(b->at("finite"), a->at("finite")) << name;
    EXPECT_EQ(b->at("removable"), a->at("removable")) << name;
    EXPECT_EQ(b->at("mode").at("type"), a->at("mode").at("type")) << name;
    EXPECT_NEAR(b->at("volume").get<double>(), a->at("volume").get<double>(),
                1e-3 * a->at("volume").get<double>())
        << name;
  }
}

// Every block through the round trip (issue 43: "the same blocks"). The
// meshes' round trips (the OBJ and the binary PLY; the planes measured
// again agree within kPlaneTolDeg) turn the exactly parallel joints J2 / J5
// and J1 / J4 (0.6 m apart) by a few ten-thousandths of a degree; the
// blocks between them once flipped with that turn (TB1 finite with corners
// ~1,000 km out, or infinite; TB2 and TB5 removable or not). Joints
// parallel within the uncertainty are now taken as parallel
// (core/analysis/README.md, "Joints taken as parallel"; the core case:
// tests/core/faces/parallel_joints_slab_test.cpp): every block keeps its
// loop, code, finiteness and removability.
TEST_F(ImportAnalyseRoundTrip, ExportedAndImportedAgainEveryBlockIsTheSame) {
  const RoundTrips trips = round_trips();
  ASSERT_EQ(trips.again.size(), 3u) << "the OBJ, the PLY and the cloud's PLY";
  const json& original = trips.original.at("blocks");
  for (const auto& a : original)
    std::printf("%s: code %s, %s, %s%s, margin %s deg\n", a.at("id").get<std::string>().c_str(),
                a.at("code").get<std::string>().c_str(),
                a.at("finite").get<bool>() ? "finite" : "infinite",
                a.value("removable", false) ? "removable" : "not removable",
                a.value("marginal", false) ? " (marginal)" : "",
                a.value("margin_deg", json()).dump().c_str());
  for (const auto& [name, report] : trips.again) {
    ASSERT_EQ(report.at("blocks").size(), original.size()) << name;
    for (std::size_t i = 0; i < original.size(); ++i) {
      const json& a = original[i];
      const json& b = report.at("blocks")[i];
      EXPECT_EQ(b.at("traces"), a.at("traces")) << name << " block " << i;
      EXPECT_EQ(b.at("code"), a.at("code")) << name << " block " << i;
      EXPECT_EQ(b.at("finite"), a.at("finite")) << name << " block " << i;
      EXPECT_EQ(b.value("removable", false), a.value("removable", false)) << name << " " << i;
    }
  }
}

TEST_F(ImportAnalyse, RockmassGivesASheetOfTheThreeSets) {
  const fs::path out = dir_ / "rockmass.json";
  const auto r = run_rockface("rockmass " + project_.string() + " --visit " +
                              std::to_string(visit_) + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json sheet = read_json(out);
  EXPECT_EQ(sheet.at("format"), "rockface-rockmass/1");
  // Three sets of two joints, each the written kSpacing apart along its
  // normal. 1 mm: the two planes of a set are each within kPlaneTolDeg of
  // the written orientation and pass through their traces (on the surface
  // to 0.05 mm); a spacing taken along the face (the apparent one, 0.64 to
  // 1.1 m here) or between the traces' ends misses by decimetres.
  ASSERT_EQ(sheet.at("sets").size(), 3u) << sheet.dump(1);
  for (const auto& s : sheet.at("sets")) {
    EXPECT_EQ(s.at("discontinuities"), 2) << s.dump();
    EXPECT_NEAR(s.at("spacing").at("mean_m").get<double>(), kSpacing, 0.001) << s.dump();
  }
  // Two measured lines and the rest to enter: RQD and Jn are the face's.
  EXPECT_EQ(sheet.at("q").at("jn").at("source"), "measured");
  EXPECT_EQ(sheet.at("q").at("jn").at("rating"), 9) << sheet.at("q").at("jn").dump();  // three sets
}

TEST_F(ImportAnalyse, WedgesAroundTheTunnelAndRefusedWithoutOne) {
  const fs::path out = dir_ / "wedges.json";
  auto r = run_rockface("wedges " + project_.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no tunnel"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  // The drive of the samples runs north along E 512340 at Z 410: the face
  // stands at its chainage 80.3.
  const std::string samples = std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/";
  r = run_rockface("tunnel " + project_.string() + " --alignment " + samples +
                   "tunnel-drive.alignment.csv --profile " + samples + "tunnel-drive.profile.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // An imported visit has no range pole to place it by chainage: the
  // drive's direction is given, as the refusal asks (the alignment's, north
  // and level).
  r = run_rockface("wedges " + project_.string() + " --visit " + std::to_string(visit_) +
                   " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--axis"), std::string::npos) << r.err;
  r = run_rockface("wedges " + project_.string() + " --visit " + std::to_string(visit_) +
                   " --axis 0/0 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json wedges = read_json(out);
  EXPECT_EQ(wedges.at("format"), "rockface-wedges/1");
  // The visit's three measured sets are the written planes.
  ASSERT_EQ(wedges.at("sets").size(), 3u) << wedges.at("sets").dump();
  for (std::size_t j = 0; j < 3; ++j) {
    bool found = false;
    for (const auto& set : wedges.at("sets"))
      found =
          found || angle_deg(normal_of(set.at("dip").get<double>(), set.at("dipdir").get<double>()),
                             normal_of(kJoints[j].dip, kJoints[j].dipdir)) < kPlaneTolDeg;
    EXPECT_TRUE(found) << kJoints[j].id << " not among " << wedges.at("sets").dump();
  }
  // Three sets around a horseshoe make wedges in its roof and walls, each
  // with its verdict.
  ASSERT_GE(wedges.at("wedges").size(), 1u) << wedges.dump(1);
  for (const auto& w : wedges.at("wedges")) {
    std::printf("%s: %s, code %s, %s, mode %s, fos %s, %.1f kg\n",
                w.at("id").get<std::string>().c_str(), w.at("place").get<std::string>().c_str(),
                w.at("code").get<std::string>().c_str(),
                w.at("removable").get<bool>() ? "removable" : "not removable",
                w.at("mode").at("type").get<std::string>().c_str(), w.at("fos").dump().c_str(),
                w.at("mass_kg").get<double>());
    EXPECT_TRUE(w.at("mode").contains("type")) << w.dump();
  }
}

}  // namespace

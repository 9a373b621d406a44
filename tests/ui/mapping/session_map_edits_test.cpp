// Issue 27: the Mapping screen's edits stored as `rockface measure` stores
// picks, on the demo project with the program's own runners: the face
// outlined by taps is stored as its flat pieces (the demo face is folded),
// each the area record the verb makes of the piece's polygon;
// a saved trace gets the joint the verb makes of the same trace (a straight
// one says why it has none); a saved trace taken back leaves with its
// joint; a degenerate outline is refused by name and leaves the stored one;
// a compass reading typed for a trace gives the verb's joint of a pick with
// that reading (issue 27).
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/progress.h"
#include "firmware-app/measure/visit_trace_joints.h"
#include "firmware-app/records/project_mesh.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "tests/ui/demo_project.h"
#include "ui/platform/headless_session.h"
#include "ui/view3d/model_view.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using namespace rockface::test;
using storage::Measurement;

// Small viewport and a decimated display model (the software renderer's
// cost); measuring uses the stored model at full resolution either way.
constexpr int kWidth = 800, kHeight = 500;
constexpr float kScale = 0.6f;
constexpr std::size_t kTriangles = 20000;

class MapEdits : public ::testing::Test {
 protected:
  void open(const fs::path& project) {
    project_ = project;
    ui::UiOptions options;
    options.project = project;
    options.scale = kScale;
    options.max_display_triangles = kTriangles;
    session_ = std::make_unique<ui::HeadlessSession>(options, runners_.services(), kWidth, kHeight);
    session_->settle();
    ASSERT_TRUE(app().model_view.has_model());
    visit_ = *app().session->visit();
  }
  ui::AppState& app() { return session_->state(); }
  // The Mapping screen's first frame updates the map's blocks on the
  // worker: the taps that follow are on the settled screen, not racing the
  // worker (a block's marker appearing between two taps takes the second).
  void to_mapping() {
    ui().tap("Mapping");
    ui().settle();
  }
  ui::HeadlessSession& ui() { return *session_; }

  // Points on the face around the model's centre, in screen pixels.
  ImVec2 around_centre(float dx, float dy) {
    const auto c = app().model_view.to_screen(app().model_view.display_mesh().centre);
    EXPECT_TRUE(c);
    return {c->x + dx * kScale, c->y + dy * kScale};
  }
  void tap(ImVec2 at) { ui().tap(at.x, at.y); }

  std::vector<Measurement> stored(Measurement::Kind kind, std::optional<storage::RecordId> visit) {
    auto store = storage::ProjectStore::open(project_);
    std::vector<Measurement> out;
    for (const auto& m : store.list_measurements(visit))
      if (m.kind == kind) out.push_back(m);
    return out;
  }
  std::optional<storage::Joint> joint(const std::string& label,
                                      std::optional<storage::RecordId> visit) {
    auto store = storage::ProjectStore::open(project_);
    for (const auto& j : store.list_joints(visit))
      if (j.label == label) return j;
    return std::nullopt;
  }

  // `rockface measure` on the project's visit with `picks` (rockface-picks/1
  // without its format line): the new visit it stores. The UI keeps the
  // project open meanwhile, as on a desktop where a verb runs beside
  // `rockface ui`: the file stays whole and the UI's own store sees the
  // verb's visit.
  storage::RecordId measure(const nlohmann::json& picks, const std::string& name) {
    nlohmann::json file = picks;
    file["format"] = "rockface-picks/1";
    const fs::path path = ui_test_dir() / (name + ".picks.json");
    std::ofstream(path) << file.dump(2);
    const fs::path log = ui_test_dir() / (name + ".txt");
    EXPECT_EQ(run_rockface_logged("measure " + project_.string() + " --visit " +
                                      std::to_string(visit_) + " --traces " + path.string() +
                                      " --out " + (ui_test_dir() / (name + ".json")).string(),
                                  log),
              0)
        << slurp(log);
    auto store = storage::ProjectStore::open(project_);
    const storage::IntegrityReport report =
        store.check_integrity(storage::OpenOptions::Check::full);
    EXPECT_TRUE(report.ok) << testing::PrintToString(report.problems);
    const storage::RecordId measured = *store.latest_visit();
    if (session_) {
      EXPECT_EQ(app().session->store().latest_visit(), measured);
    }
    return measured;
  }

  // Every test leaves its project whole: the UI closed, a full integrity
  // check (the lost-lock damage of a second program went unnoticed while
  // every assertion passed).
  void TearDown() override {
    session_.reset();
    if (project_.empty()) return;
    auto store = storage::ProjectStore::open(project_);
    const storage::IntegrityReport report =
        store.check_integrity(storage::OpenOptions::Check::full);
    EXPECT_TRUE(report.ok) << project_.filename() << ": "
                           << testing::PrintToString(report.problems);
  }

  app::FieldRunners runners_{""};
  std::unique_ptr<ui::HeadlessSession> session_;
  fs::path project_;
  storage::RecordId visit_ = 0;
};

// The same code on the same stored mesh: equal but for the rounding of a
// coordinate carried through the datum and back (~1e-12 m at the demo's
// datum), far under what a pick resolves.
constexpr double kSameMetres = 1e-9;
constexpr double kSameDegrees = 1e-6;

// The unit normal of a plane given by dip / dip direction (degrees).
Eigen::Vector3d normal_of(double dip_deg, double dipdir_deg) {
  const double d = dip_deg * M_PI / 180, a = dipdir_deg * M_PI / 180;
  return {std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d)};
}
double degrees_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180 / M_PI;
}
// The demo scene's patch `id`: its plane's normal (the polygon's corners'
// Newell normal; the demo's patches are exact planes).
Eigen::Vector3d demo_patch_normal(const std::string& id) {
  std::ifstream in(demo_scene());
  const auto scene = nlohmann::json::parse(in);
  for (const auto& p : scene["surface"]["patches"])
    if (p["id"] == id) {
      std::vector<Eigen::Vector3d> c;
      for (const auto& x : p["polygon"]) c.emplace_back(x[0], x[1], x[2]);
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      for (std::size_t k = 0; k < c.size(); ++k)
        n += (c[k] - c[0]).cross(c[(k + 1) % c.size()] - c[0]);
      return n.normalized();
    }
  ADD_FAILURE() << "no patch " << id << " in the demo scene";
  return Eigen::Vector3d::UnitZ();
}

TEST_F(MapEdits, TheFaceOutlineIsStoredAsItsFlatPiecesEachAsRockfaceMeasureStoresAnArea) {
  open(copy_of_demo("outline"));
  ASSERT_FALSE(stored(Measurement::Kind::area, visit_).empty()) << "the demo has its face";
  to_mapping();
  ui().tap("Outline the face");
  for (const ImVec2 at : {around_centre(-90, -60), around_centre(90, -60), around_centre(90, 60),
                          around_centre(-90, 60)})
    tap(at);
  ASSERT_EQ(app().mapping.outline.corners().size(), 4u) << app().mapping.outline.problem();
  // The demo visit has its face already: replacing it is asked first.
  ui().tap("Replace outline");
  ui().tap("Yes, replace outline");
  ui().settle();
  const std::string said = app().statuses.message(static_cast<std::size_t>(ui::Screen::mapping));
  // The demo face is folded (two walls, FACE_W and FACE_E): the outline
  // across its fold is stored as its two flat pieces, replacing the visit's
  // face (both of the demo's patches).
  const auto areas = stored(Measurement::Kind::area, visit_);
  ASSERT_EQ(areas.size(), 2u) << said;
  EXPECT_EQ(areas[0].label, "F1a");
  EXPECT_EQ(areas[1].label, "F1b");
  EXPECT_NE(said.find("face outline F1: 2 flat pieces, "), std::string::npos) << said;
  EXPECT_NE(said.find("° apart, RMS "), std::string::npos) << said;
  for (const auto& piece : areas) {
    EXPECT_TRUE(piece.rock_side.empty()) << "a mapped surface, not a free face";
    ASSERT_GE(piece.points.size(), 3u);
    EXPECT_EQ(piece.pixels.size(), piece.points.size());
    EXPECT_EQ(piece.photo, "left");
    ASSERT_TRUE(piece.dip_deg && piece.dipdir_deg) << piece.label << ": " << piece.note;
    EXPECT_FALSE(joint(piece.label, visit_)) << "the face is no joint";
  }
  EXPECT_FALSE(app().mapping.outlining) << "stored: the screen is back to traces";
  // The two pieces are the demo's two walls: as far apart as FACE_W and
  // FACE_E (11.5°). Expected error: each piece's plane is fitted to
  // thousands of points of the fast preset's 3D image (sigma_Z a few mm over
  // metres: hundredths of a degree), and its points near the fold may go to
  // the other wall (a band a few sigmas wide: tenths of a degree); 1° says
  // the pieces are the walls, not two facets of one of them.
  const double walls = degrees_between(demo_patch_normal("FACE_W"), demo_patch_normal("FACE_E"));
  const double pieces = degrees_between(normal_of(*areas[0].dip_deg, *areas[0].dipdir_deg),
                                        normal_of(*areas[1].dip_deg, *areas[1].dipdir_deg));
  EXPECT_NEAR(pieces, walls, 1.0) << said;
  // Each piece's corners lie in its plane; the pieces share their common
  // edge (two corners each, the same pixels' rays met with both planes on
  // their common line: equal to rounding).
  std::size_t shared = 0;
  for (const auto& p : areas[0].points)
    for (const auto& q : areas[1].points) shared += (p - q).norm() < 1e-6;
  EXPECT_EQ(shared, 2u);

  // The verb, given each piece's polygon in the same photograph: the record
  // it stores is of the same kind and form, its plane that of every point
  // inside the polygon where the piece's is of the points nearest its
  // plane: they differ in the band along the fold only, under 1°.
  nlohmann::json picks = nlohmann::json::array();
  for (const auto& piece : areas) {
    nlohmann::json polygon = nlohmann::json::array();
    for (const auto& p : piece.pixels) polygon.push_back({p.x(), p.y()});
    picks.push_back({{"id", piece.label}, {"photo", "left"}, {"polygon", polygon}});
  }
  const auto measured_visit = measure({{"areas", picks}}, "outline-measure");
  const auto by_verb = stored(Measurement::Kind::area, measured_visit);
  ASSERT_EQ(by_verb.size(), areas.size());
  for (std::size_t k = 0; k < areas.size(); ++k) {
    const Measurement &verb = by_verb[k], &piece = areas[k];
    EXPECT_EQ(verb.label, piece.label);
    ASSERT_TRUE(verb.dip_deg && verb.dipdir_deg);
    EXPECT_LT(degrees_between(normal_of(*verb.dip_deg, *verb.dipdir_deg),
                              normal_of(*piece.dip_deg, *piece.dipdir_deg)),
              1.0)
        << piece.label;
    EXPECT_EQ(verb.model_id, piece.model_id);
    EXPECT_EQ(verb.photo_capture_id, piece.photo_capture_id);
    EXPECT_EQ(verb.pixels.size(), piece.pixels.size());
  }

  // The analysis takes the pieces as the mapped face: two patches.
  auto store = storage::ProjectStore::open(project_);
  const auto scene = storage::make_scene_json(storage::load_scene_source(store, visit_));
  ASSERT_EQ(scene["surface"]["patches"].size(), 2u);
  EXPECT_EQ(scene["surface"]["patches"][0]["id"], "F1a");
  NoProgress none;
  runners_.analysis.analyse(project_, visit_, none);
}

TEST_F(MapEdits, ASavedTraceGetsTheJointRockfaceMeasureMakesOfIt) {
  open(copy_of_demo("trace-joint"));
  to_mapping();
  // Taps along the demo's joint J1 where it crosses from one face to the
  // next (its traces T2 then T1, one per face: each alone is straight, a
  // line on its face, so that no plane is known; across the edge it is).
  const Measurement* first = nullptr;
  const Measurement* second = nullptr;
  for (const auto& m : app().session->measurements()) {
    if (m.label == "T2") first = &m;
    if (m.label == "T1") second = &m;
  }
  ASSERT_TRUE(first && second);
  std::vector<Eigen::Vector3d> along;
  for (const double f : {0.0, 0.5, 0.9})
    along.push_back(first->points[static_cast<std::size_t>(f * (first->points.size() - 1))]);
  for (const double f : {0.3, 0.7, 1.0})
    along.push_back(second->points[static_cast<std::size_t>(f * (second->points.size() - 1))]);
  for (const auto& p : along) {
    const auto at = app().model_view.to_screen(p);
    ASSERT_TRUE(at);
    tap(*at);
  }
  ASSERT_EQ(app().mapping.marker.taps().size(), along.size()) << app().mapping.marker.problem();
  ASSERT_TRUE(app().mapping.marker.plane() && app().mapping.marker.plane()->known)
      << app().mapping.marker.plane()->problem;
  ui().tap("Save trace");
  ui().settle();
  const auto traces = stored(Measurement::Kind::trace, visit_);
  const Measurement tablet = traces.back();
  const auto tablet_joint = joint(tablet.label, visit_);
  ASSERT_TRUE(tablet_joint) << "joint " << tablet.label;
  EXPECT_EQ(tablet_joint->measurement_id, tablet.id);
  const std::string said = app().statuses.message(static_cast<std::size_t>(ui::Screen::mapping));
  EXPECT_NE(said.find("joint " + tablet.label), std::string::npos) << said;

  // Taken back (asked first): the trace and its joint leave the visit, and
  // the map's blocks are updated without it.
  const std::string undo = "Undo " + tablet.label;
  ui().tap(undo);
  ASSERT_EQ(stored(Measurement::Kind::trace, visit_).size(), traces.size())
      << "nothing goes before Yes";
  ui().tap("Yes, undo " + tablet.label);
  ui().settle();
  EXPECT_EQ(stored(Measurement::Kind::trace, visit_).size(), traces.size() - 1);
  EXPECT_FALSE(joint(tablet.label, visit_));
  EXPECT_FALSE(app().mapping.blocks.stale);
  std::size_t deleted = 0;
  for (const auto& a : storage::ProjectStore::open(project_).list_actions(visit_))
    deleted += a.action == "measurement deleted" && a.detail == tablet.label;
  EXPECT_EQ(deleted, 1u);

  // The verb, given the stored trace's points (absolute, as a picks file
  // holds them).
  const Eigen::Vector3d datum = storage::ProjectStore::open(project_).project().datum;
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : tablet.points) {
    const Eigen::Vector3d a = datum + p;
    points.push_back({a.x(), a.y(), a.z()});
  }
  const auto measured_visit =
      measure({{"traces", {{{"id", tablet.label}, {"points", points}}}}}, "trace-measure");
  const auto verb_joint = joint(tablet.label, measured_visit);
  ASSERT_TRUE(verb_joint);
  EXPECT_NEAR(tablet_joint->dip_deg, verb_joint->dip_deg, kSameDegrees);
  EXPECT_NEAR(tablet_joint->dipdir_deg, verb_joint->dipdir_deg, kSameDegrees);
  ASSERT_TRUE(tablet_joint->point && verb_joint->point);
  EXPECT_LT((*tablet_joint->point - *verb_joint->point).norm(), kSameMetres);
  ASSERT_TRUE(tablet_joint->persistence_m && verb_joint->persistence_m);
  EXPECT_NEAR(*tablet_joint->persistence_m, *verb_joint->persistence_m, kSameMetres);
  EXPECT_EQ(tablet_joint->source, verb_joint->source);
  EXPECT_EQ(tablet_joint->type, verb_joint->type);
  // The trace record itself is the verb's too (the tablet's as it was
  // stored, before it was taken back).
  const Measurement verb = stored(Measurement::Kind::trace, measured_visit).front();
  ASSERT_TRUE(verb.sigma_deg && tablet.sigma_deg);
  EXPECT_NEAR(*tablet.sigma_deg, *verb.sigma_deg, kSameDegrees);
  ASSERT_TRUE(verb.trace_length_m && tablet.trace_length_m);
  EXPECT_NEAR(*tablet.trace_length_m, *verb.trace_length_m, kSameMetres);
  EXPECT_EQ(tablet.censored, verb.censored);
}

TEST_F(MapEdits, AStraightTraceSaysItsPlaneIsUnknownAndMakesNoJoint) {
  open(copy_of_demo("straight"));
  to_mapping();
  // Two taps: a line, no plane.
  tap(around_centre(-80, 0));
  tap(around_centre(80, 0));
  ASSERT_EQ(app().mapping.marker.points().size(), 2u);
  ui().tap("Save trace");
  ui().settle();
  const Measurement tablet = stored(Measurement::Kind::trace, visit_).back();
  EXPECT_FALSE(tablet.dip_deg);
  EXPECT_FALSE(joint(tablet.label, visit_));
  const std::string said = app().statuses.message(static_cast<std::size_t>(ui::Screen::mapping));
  EXPECT_NE(said.find("no joint (orientation unknown"), std::string::npos) << said;
}

// Issue 27: a straight trace (no plane of its own) given a compass reading
// on the Mapping screen's keypad gets the joint `rockface measure` makes of
// the same trace with `compass` in its pick; the reading cleared (asked
// first) takes the joint away, and given again to the saved trace brings it
// back.
TEST_F(MapEdits, ACompassReadingTypedOnTheTabletIsTheVerbsPickWithCompass) {
  open(copy_of_demo("compass"));
  to_mapping();
  tap(around_centre(-80, 0));
  tap(around_centre(80, 0));
  ASSERT_EQ(app().mapping.marker.points().size(), 2u);
  for (const char* key : {"Compass", "7", "4", "Dip direction", "1", "1", "1"}) ui().tap(key);
  EXPECT_EQ(app().mapping.compass.dip(), 74);
  EXPECT_EQ(app().mapping.compass.dip_direction(), 111);
  ui().tap("Save trace");
  ui().settle();
  const Measurement tablet = stored(Measurement::Kind::trace, visit_).back();
  ASSERT_TRUE(tablet.compass_dip_deg && tablet.compass_dipdir_deg && tablet.compass_off_deg);
  EXPECT_EQ(*tablet.compass_dip_deg, 74);
  EXPECT_EQ(*tablet.compass_dipdir_deg, 111);
  ASSERT_TRUE(tablet.dip_deg && tablet.dipdir_deg);
  const auto tablet_joint = joint(tablet.label, visit_);
  ASSERT_TRUE(tablet_joint) << tablet.note;
  EXPECT_EQ(tablet_joint->source, "trace " + tablet.label + " (compass)");
  const std::string said = app().statuses.message(static_cast<std::size_t>(ui::Screen::mapping));
  EXPECT_NE(said.find("joint " + tablet.label + " 74.0° / 111.0°"), std::string::npos) << said;
  EXPECT_NE(said.find("(compass)"), std::string::npos) << said;
  EXPECT_FALSE(app().mapping.compass.given()) << "the reading went with the trace";

  // Cleared on the saved trace (asked first): no plane, no joint.
  ui().tap("Compass");
  ui().tap("Clear reading");
  EXPECT_TRUE(stored(Measurement::Kind::trace, visit_).back().compass_dip_deg)
      << "nothing goes before Yes";
  ui().tap("Yes, clear reading");
  ui().settle();
  const Measurement cleared = stored(Measurement::Kind::trace, visit_).back();
  EXPECT_EQ(cleared.id, tablet.id);
  EXPECT_FALSE(cleared.compass_dip_deg);
  EXPECT_FALSE(cleared.dip_deg);
  EXPECT_FALSE(joint(tablet.label, visit_));
  // Given again to the saved trace: the same joint as at first.
  for (const char* key : {"Dip", "7", "4", "Dip direction", "1", "1", "1"}) ui().tap(key);
  ui().tap("Save reading");
  ui().settle();
  const Measurement again = stored(Measurement::Kind::trace, visit_).back();
  EXPECT_EQ(again.compass_dip_deg, tablet.compass_dip_deg);
  EXPECT_EQ(again.note, tablet.note);
  const auto again_joint = joint(tablet.label, visit_);
  ASSERT_TRUE(again_joint);
  EXPECT_EQ(again_joint->dip_deg, tablet_joint->dip_deg);

  // The verb, given the stored trace's points and the same reading.
  const Eigen::Vector3d datum = storage::ProjectStore::open(project_).project().datum;
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : tablet.points) {
    const Eigen::Vector3d a = datum + p;
    points.push_back({a.x(), a.y(), a.z()});
  }
  const auto measured_visit =
      measure({{"traces",
                {{{"id", tablet.label},
                  {"points", points},
                  {"compass", {{"dip", 74.0}, {"dip_direction", 111.0}}}}}}},
              "compass-measure");
  const auto verb_joint = joint(tablet.label, measured_visit);
  ASSERT_TRUE(verb_joint);
  // Both are the reading itself, through the same centroid: equal but for
  // rounding (1e-9, see kSameMetres).
  EXPECT_NEAR(tablet_joint->dip_deg, verb_joint->dip_deg, 1e-9);
  EXPECT_NEAR(tablet_joint->dipdir_deg, verb_joint->dipdir_deg, 1e-9);
  ASSERT_TRUE(tablet_joint->point && verb_joint->point);
  EXPECT_LT((*tablet_joint->point - *verb_joint->point).norm(), kSameMetres);
  EXPECT_EQ(tablet_joint->source, verb_joint->source);
  const Measurement verb = stored(Measurement::Kind::trace, measured_visit).front();
  ASSERT_TRUE(verb.compass_off_deg && verb.sigma_deg && tablet.sigma_deg);
  // The angle off the plane read, from the same points: equal to the
  // rounding of the picks file's absolute coordinates (an ulp of 5.2e6 m is
  // 9e-10 m; over the ~1.6 m trace, ~6e-10 rad = 3.5e-8 degrees).
  EXPECT_NEAR(*tablet.compass_off_deg, *verb.compass_off_deg, 1e-7);
  EXPECT_NEAR(*tablet.sigma_deg, *verb.sigma_deg, 1e-9);
  EXPECT_EQ(tablet.note, verb.note);
}

// Issue 27: in a visit of two pairs each saved trace is measured on its own
// pair's 3D image (its record's model), whichever pair is on display: a
// trace saved on pair 2 (with a compass reading, so that it has a joint)
// keeps that joint when pair 1 is on display and the joints are remade;
// and the visit's joint table routes it to pair 2's mesh, exactly as
// measuring it alone on that mesh.
TEST_F(MapEdits, ATraceOfAFurtherPairIsMeasuredOnItsOwnPair) {
  const fs::path project = ui_test_dir() / "compass-two-pairs.rockface";
  fs::copy_file(two_pair_project(), project, fs::copy_options::overwrite_existing);
  open(project);
  const auto pairs = app().session->pairs();
  ASSERT_EQ(pairs.size(), 2u);
  // The Mapping screen loads pair 1's 3D image on the worker; its pair
  // buttons stay disabled until that is done.
  to_mapping();
  ui().tap("Pair 2");
  ui().settle();
  ASSERT_EQ(app().model_view.model_id(), pairs[1].id);
  for (int i = 0; i < 4; ++i) tap(around_centre(-100.0f + 66.0f * i, -50.0f + 33.0f * i));
  ASSERT_EQ(app().mapping.marker.taps().size(), 4u) << app().mapping.marker.problem();
  for (const char* key : {"Compass", "7", "4", "Dip direction", "1", "1", "1"}) ui().tap(key);
  ui().tap("Save trace");
  ui().settle();
  const Measurement on_two = stored(Measurement::Kind::trace, visit_).back();
  EXPECT_EQ(on_two.model_id, pairs[1].id);
  const auto joint_two = joint(on_two.label, visit_);
  ASSERT_TRUE(joint_two) << on_two.note;

  // Pair 1 on display; a trace saved there remakes the visit's joints.
  ui().tap("Pair 1");
  ui().settle();
  ASSERT_EQ(app().model_view.model_id(), pairs[0].id);
  tap(around_centre(-80, 0));
  tap(around_centre(80, 0));
  ui().tap("Save trace");
  ui().settle();
  const auto after = joint(on_two.label, visit_);
  ASSERT_TRUE(after);
  EXPECT_EQ(after->dip_deg, joint_two->dip_deg);
  EXPECT_EQ(after->point, joint_two->point);
  EXPECT_EQ(after->persistence_m, joint_two->persistence_m);

  // The routing itself, on the stored meshes: measured in the visit's
  // table (pair 1's mesh the default) it is what pair 2's mesh alone gives.
  session_.reset();
  auto store = storage::ProjectStore::open(project_);
  const auto one = app::surface_mesh(store.load_model(pairs[0].id).mesh, 0, 0);
  const auto two = app::surface_mesh(store.load_model(pairs[1].id).mesh, 0, 0);
  const measure::MeshPicker first(one), second(two);
  Measurement plain = on_two;  // without its reading: the plane from the trace and the meshes
  plain.compass_dip_deg.reset();
  plain.compass_dipdir_deg.reset();
  measure::MeasureSettings settings;
  settings.point_sigma = 0.01;
  const auto routed = app::trace_joint_table({plain}, first, settings, visit_,
                                             {{pairs[0].id, &first}, {pairs[1].id, &second}});
  const auto alone = app::trace_joint_table({plain}, second, settings, visit_);
  ASSERT_EQ(routed.joints.size(), alone.joints.size());
  for (std::size_t k = 0; k < routed.joints.size(); ++k) {
    EXPECT_EQ(routed.joints[k].dip_deg, alone.joints[k].dip_deg);
    EXPECT_EQ(routed.joints[k].dipdir_deg, alone.joints[k].dipdir_deg);
  }
  EXPECT_EQ(routed.without_joint, alone.without_joint);
  const auto on_first = app::trace_joint_table({plain}, first, settings, visit_);
  std::printf("pair 2's trace %s: on its own mesh %s; on pair 1's %s\n", plain.label.c_str(),
              alone.joints.empty() ? alone.without_joint.front().c_str() : "a joint",
              on_first.joints.empty() ? on_first.without_joint.front().c_str() : "a joint");
}

TEST_F(MapEdits, ADegenerateOutlineIsRefusedByNameAndTheStoredOneStays) {
  open(copy_of_demo("degenerate"));
  const auto before = stored(Measurement::Kind::area, visit_);
  to_mapping();
  ui().tap("Outline the face");
  // A tap beside the face (the panel's corner: background): no corner.
  const ImVec2 corner = app().model_view.panel_min();
  tap({corner.x + 3, corner.y + 3});
  EXPECT_TRUE(app().mapping.outline.corners().empty());
  EXPECT_EQ(app().mapping.outline.problem().rfind("corner 1: no surface under the tap", 0), 0u)
      << app().mapping.outline.problem();
  // Two corners do not close.
  tap(around_centre(-60, 0));
  tap(around_centre(60, 0));
  ui::TraceContext context;
  context.picker = app().model_view.picker();
  context.photo_view = &*app().model_view.left_view();
  try {
    app().mapping.outline.corner_pixels(context);
    ADD_FAILURE() << "two corners closed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face outline: needs 3 or more corners to close, has 2"),
              std::string::npos)
        << e.what();
  }
  // The runner refuses the same, and three corners on one line (no area
  // inside), naming the outline; the stored face stays.
  ui::MapEdit edit;
  edit.visit_id = visit_;
  edit.picker = app().model_view.picker();
  edit.view = context.photo_view;
  NoProgress none;
  const auto pixels = measure::project_to_view(
      *context.photo_view,
      {app().mapping.outline.corners()[0], app().mapping.outline.corners()[1]});
  edit.outline = pixels;
  try {
    runners_.trace_map.store(project_, edit, none);
    ADD_FAILURE() << "two corners stored";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face outline: needs 3 or more corners"),
              std::string::npos)
        << e.what();
  }
  edit.outline = {pixels[0], 0.5 * (pixels[0] + pixels[1]), pixels[1]};
  try {
    runners_.trace_map.store(project_, edit, none);
    ADD_FAILURE() << "a line stored as an outline";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face outline"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("corners enclose no area (they lie on one line)"),
              std::string::npos)
        << e.what();
  }
  const auto after = stored(Measurement::Kind::area, visit_);
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t k = 0; k < after.size(); ++k) EXPECT_EQ(after[k].id, before[k].id);
}

}  // namespace

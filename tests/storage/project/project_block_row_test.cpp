// A block verdict (analysis::ReportBlock) stored in the project file and
// read back (storage/project/project_block_row.h,
// storage/report/report_block_reader.cpp):
// the row holds the same bytes as before the store took the verdict type
// (key columns + the report's block JSON), every part of the verdict comes
// back, unknowns (NaN) and absent parts stay so, and rows stored by older
// versions (a short report JSON, or a damaged one) still open.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "storage/project/project_block_row.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"
#include "storage/report/report.h"
#include "tests/support/sample_records.h"

namespace {

using namespace rockface::storage;
using rockface::analysis::ReportBlock;
using rockface::storage::test::TempDir;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A trace block with every part of the verdict set, numbers chosen with
// more digits than the report keeps (the JSON rounds to 9 significant
// digits, report_numbers.h), at survey coordinates.
ReportBlock full_block() {
  ReportBlock b;
  b.id = "TB7";
  b.source = "traces";
  b.traces = {"T1", "T3", "T4"};
  b.code = "0120";
  b.convex = false;
  b.vertices = {{512340.123456, 5211870.5, 410.25}, {512341.0, 5211871.75, 409.125}};
  b.volume = 0.7131234567891;
  b.mass = 1925.43210987;
  b.centroid = Eigen::Vector3d(512340.6, 5211871.1, 409.7);
  Eigen::Matrix3d inertia;
  inertia << 120.5, -3.25, 1.5, -3.25, 98.75, 0.5, 1.5, 0.5, 150.125;
  b.inertia = inertia;
  b.principal_moments = Eigen::Vector3d(97.5, 121.25, 150.75);
  b.face_areas = {{"J1", 2.5}, {"J3", 1.25}, {"face", 3.75}};
  b.finite = b.removable = true;
  b.margin_deg = 4.123456789123;
  b.marginal = false;
  b.mode = rockface::analysis::ReportMode{};
  b.mode->type = "sliding";
  b.mode->planes = {"J1", "J3"};
  b.mode->direction = Eigen::Vector3d(0, -0.6, -0.8);
  b.mode->marginal = true;
  b.fos = 0.7234567891234;
  b.fos_marginal = true;
  b.resultant_force = Eigen::Vector3d(0, 0, -18888.5);
  b.resultant_moment = Eigen::Vector3d(1.5, -2.25, 0);
  rockface::analysis::ReportRotation rot;
  rockface::analysis::ReportCorner corner;
  corner.vertex = 1;
  corner.rotatable = true;
  corner.margin_deg = 2.5;
  corner.rotation_edges = {{0, 0, 1}, {0.6, 0.8, 0}};
  corner.sliding_on = {"J3"};
  rot.corners = {corner};
  rockface::analysis::ReportEdge edge;
  edge.vertices = {0, 1};
  edge.margin_deg = -1.5;
  edge.marginal = true;
  rot.edges = {edge};
  b.rotation = rot;
  rockface::analysis::ReportRemoteAxis axis;
  axis.found = true;
  axis.point = Eigen::Vector3d(512339.5, 5211870.25, 411);
  axis.direction = Eigen::Vector3d(0, 1, 0);
  axis.starts = 64;
  axis.hits = 9;
  axis.penalty = 0.015625;
  b.remote_axis = axis;
  rockface::analysis::ReportStability stability;
  stability.fos = kNaN;  // no finite value: written null, read back as none
  stability.static_mode = {1, 0, 0.5};
  stability.dynamic_mode = {0, 1};
  stability.path = {{0.5, {0.001, 0.002}}, {1.0, {0.01, 0.03}}};
  b.stability = stability;
  rockface::analysis::ReportMechanics mechanics;
  mechanics.outcome = "no limit point reached";  // fos_limit_point absent
  mechanics.failure_mode.translation = Eigen::Vector3d(0, -0.6, -0.8);
  mechanics.dynamic_mode.rotation = Eigen::Vector3d(0.1, 0, 0);
  mechanics.dynamic_mode.kind = "rotation";
  mechanics.stability = "stable";
  mechanics.flutter_lambda = 1.75;
  mechanics.path = {{0.25, 0.0001}, {0.5, 0.0004}};
  mechanics.contacts = 12;
  mechanics.steps = 40;
  mechanics.joint_law = "coulomb";
  mechanics.plot = "TB7-path.png";
  b.mechanics = mechanics;
  rockface::analysis::ReportDynamics d;
  d.trigger = "limit equilibrium: FoS 0.72 < 1";
  d.outcome = "lands";
  d.strength_divisor = 0.75;
  d.friction_deg = {{"J1", 30}, {"J3", 27.5}};
  d.events = {{0, "slides", "slides on J1 and J3", {"J1", "J3"}},
              {0.75, "leaves", "leaves J3", {"J3"}}};
  rockface::analysis::ReportMotionSample s0, s1;
  s0.position = *b.centroid;
  s1.time_s = 0.5;
  s1.position = *b.centroid + Eigen::Vector3d(0, -0.3, -0.4);
  s1.orientation = Eigen::Vector4d(0.99, 0.1, 0, 0);
  s1.velocity = Eigen::Vector3d(0, -1.2, -1.6);
  s1.angular_velocity = Eigen::Vector3d(0.2, 0, 0);
  s1.kinetic_translational = 3850;
  s1.kinetic_rotational = 12.5;
  s1.work = 3900;
  s1.dissipated = 37.5;
  d.path = {s0, s1};
  rockface::analysis::ReportLanding landing;
  landing.time_s = 1.25;
  landing.point = Eigen::Vector3d(512340.5, 5211869.0, 407.5);
  landing.centroid = Eigen::Vector3d(512340.6, 5211869.2, 407.9);
  landing.speed = 5.5;
  landing.distance_from_start = 2.25;
  landing.distance_from_face = 1.5;
  landing.face = "F1";
  d.landing = landing;
  d.floor = std::make_pair(Eigen::Vector3d(512340, 5211869, 407.5), Eigen::Vector3d(0, 0, 1));
  d.duration_s = 3;
  d.sample_s = 0.05;
  d.end_time_s = 1.25;
  d.abs_tol = 1e-6;
  d.rel_tol = 1e-5;
  d.max_step_s = 0.01;
  d.steps = 420;
  d.rejected_steps = 3;
  d.evaluations = 2600;
  d.drift_before_m = 1e-7;
  d.drift_after_m = 2e-7;
  d.drift_bound_m = 1e-3;
  d.picture = "TB7-motion.png";
  d.notes = {"the floor is the tunnel's invert"};
  b.dynamics = d;
  b.notes = {"face J3 opens under water pressure"};
  return b;
}

// A block that is no block: no mode, no factor of safety, none of the
// optional parts.
ReportBlock bare_block() {
  ReportBlock b;
  b.id = "B2";
  b.code = "1102";
  b.margin_deg = -3.5;
  return b;
}

struct StoredProject {
  TempDir dir{"block-rows"};
  std::filesystem::path file = dir / "blocks.rockface";
  RecordId analysis = 0;
};

// Saves the blocks as one analysis of a fresh project.
void store_blocks(StoredProject& p, const std::vector<ReportBlock>& blocks) {
  auto store = ProjectStore::create(p.file, test::sample_project());
  AnalysisRun run;
  run.visit_id = store.begin_visit("test");
  run.preset = "standard";
  run.blocks = blocks;
  p.analysis = store.save_analysis(run);
}

std::vector<ReportBlock> load_blocks(const StoredProject& p) {
  auto store = ProjectStore::open(p.file);
  return store.load_analysis(p.analysis).blocks;
}

TEST(ProjectBlockRow, AVerdictComesBackWhole) {
  StoredProject p;
  const ReportBlock want = full_block();
  store_blocks(p, {want});
  const auto back = load_blocks(p);
  ASSERT_EQ(back.size(), 1u);
  const ReportBlock& b = back[0];
  // Every part, as the report writes it (rounded as the report rounds).
  EXPECT_EQ(block_to_json(b), block_to_json(want));
  // The key columns' numbers to the bit: the columns keep full precision.
  EXPECT_EQ(b.volume, want.volume);
  EXPECT_EQ(b.fos, want.fos);
  EXPECT_EQ(b.id, "TB7");
  EXPECT_EQ(b.traces, want.traces);
  EXPECT_FALSE(b.convex);
  ASSERT_TRUE(b.mode);
  EXPECT_EQ(b.mode->planes, want.mode->planes);
  EXPECT_TRUE(b.mode->marginal);
  EXPECT_TRUE(b.fos_marginal);
  // Survey coordinates keep 0.1 mm (report_numbers.h: 1e-5 m at 5e6 m).
  ASSERT_EQ(b.vertices.size(), 2u);
  EXPECT_NEAR(b.vertices[0].x(), 512340.123456, 1e-5);
  ASSERT_TRUE(b.inertia);
  EXPECT_EQ(*b.inertia, *want.inertia);  // values with few digits survive exactly
  ASSERT_TRUE(b.rotation);
  EXPECT_EQ(b.rotation->corners[0].sliding_on, std::vector<std::string>{"J3"});
  EXPECT_EQ(b.rotation->edges[0].vertices, (std::array<int, 2>{0, 1}));
  ASSERT_TRUE(b.stability);
  EXPECT_FALSE(b.stability->fos) << "a NaN factor of safety is written null and read as none";
  ASSERT_TRUE(b.mechanics);
  EXPECT_FALSE(b.mechanics->fos_limit_point);
  EXPECT_EQ(b.mechanics->flutter_lambda, 1.75);
  ASSERT_TRUE(b.dynamics);
  EXPECT_EQ(b.dynamics->events.size(), 2u);
  EXPECT_EQ(b.dynamics->events[1].what, "leaves J3");
  ASSERT_TRUE(b.dynamics->landing);
  EXPECT_EQ(b.dynamics->landing->distance_from_face, 1.5);
  EXPECT_EQ(b.dynamics->steps, 420);
  EXPECT_EQ(b.dynamics->abs_tol, 1e-6);
  EXPECT_EQ(b.dynamics->notes, want.dynamics->notes);
  EXPECT_EQ(b.notes, want.notes);
}

TEST(ProjectBlockRow, AbsentPartsAndUnknownsStaySo) {
  StoredProject p;
  ReportBlock infinite_fos = bare_block();
  infinite_fos.id = "B3";
  infinite_fos.finite = infinite_fos.removable = true;
  infinite_fos.mode = rockface::analysis::ReportMode{};
  infinite_fos.mode->type = "sliding";
  // No sliding force: the factor of safety is +inf, which JSON cannot hold.
  infinite_fos.fos = std::numeric_limits<double>::infinity();
  store_blocks(p, {bare_block(), infinite_fos});
  const auto back = load_blocks(p);
  ASSERT_EQ(back.size(), 2u);
  const ReportBlock& b = back[0];
  EXPECT_EQ(block_to_json(b), block_to_json(bare_block()));
  EXPECT_FALSE(b.mode) << "no mode stored as the column's \"none\" stays none";
  EXPECT_FALSE(b.fos);
  EXPECT_FALSE(b.volume) << "a volume column of 0 with none in the report is none";
  EXPECT_FALSE(b.mass);
  EXPECT_FALSE(b.rotation);
  EXPECT_FALSE(b.remote_axis);
  EXPECT_FALSE(b.stability);
  EXPECT_FALSE(b.mechanics);
  EXPECT_FALSE(b.dynamics);
  EXPECT_TRUE(b.notes.empty());
  EXPECT_EQ(b.margin_deg, -3.5);
  // The infinite factor of safety: null in the JSON, +inf in the column.
  ASSERT_TRUE(back[1].fos);
  EXPECT_TRUE(std::isinf(*back[1].fos));
  EXPECT_EQ(block_to_json(back[1]), block_to_json(infinite_fos));
}

TEST(ProjectBlockRow, TheStoredBytesAreTheReportsBlockAndItsColumns) {
  StoredProject p;
  const ReportBlock want = full_block();
  store_blocks(p, {want});
  sqlite::Connection db(p.file, sqlite::Connection::Access::read_only);
  sqlite::Statement st(db,
                       "SELECT label, source, code, volume_m3, finite, removable, marginal, mode, "
                       "fos, report_json FROM block",
                       "test");
  ASSERT_TRUE(st.step());
  EXPECT_EQ(st.column_text(0), "TB7");
  EXPECT_EQ(st.column_text(1), "traces");
  EXPECT_EQ(st.column_text(2), "0120");
  EXPECT_EQ(st.column_double(3), *want.volume);
  EXPECT_EQ(st.column_int(4), 1);
  EXPECT_EQ(st.column_int(5), 1);
  EXPECT_EQ(st.column_int(6), 0);
  EXPECT_EQ(st.column_text(7), "sliding");
  EXPECT_EQ(st.column_optional_double(8), want.fos);
  // The report's own writer's text, as `rockface analyse` writes the block.
  EXPECT_EQ(st.column_text(9), block_to_json(want));
}

// Rows as older versions stored them: the columns right, the report JSON
// short (only what that version wrote) or damaged.
TEST(ProjectBlockRow, AnOlderRowOpensWithWhatItHolds) {
  StoredProject p;
  store_blocks(p, {bare_block(), bare_block()});
  {
    sqlite::Connection db(p.file, sqlite::Connection::Access::read_write);
    db.exec(
        "UPDATE block SET label = 'B1', source = 'traces', code = '0102', volume_m3 = 12.5, "
        "finite = 1, removable = 1, marginal = 0, mode = 'sliding', fos = 1.35, report_json = "
        "'{\"id\":\"B1\",\"source\":\"traces\",\"code\":\"0102\",\"volume\":12.5,"
        "\"vertices\":[[1,2,3],[4,5]],\"rotation\":{\"corners\":[{\"rotatable\":true}]}}' "
        "WHERE id = (SELECT min(id) FROM block);"
        "UPDATE block SET label = 'B9', finite = 1, removable = 0, marginal = 1, mode = 'none', "
        "fos = NULL, volume_m3 = 0.5, report_json = 'not json' "
        "WHERE id = (SELECT max(id) FROM block)",
        "test");
  }
  const auto back = load_blocks(p);
  ASSERT_EQ(back.size(), 2u);
  const ReportBlock& old = back[0];
  EXPECT_EQ(old.id, "B1");
  EXPECT_EQ(old.source, "traces");
  EXPECT_TRUE(old.finite && old.removable && !old.marginal);
  ASSERT_TRUE(old.mode) << "the column's mode, though the report has none";
  EXPECT_EQ(old.mode->type, "sliding");
  EXPECT_TRUE(old.mode->planes.empty());
  EXPECT_EQ(old.fos, 1.35);
  EXPECT_EQ(old.volume, 12.5);
  ASSERT_EQ(old.vertices.size(), 1u) << "the malformed point is left out";
  EXPECT_EQ(old.vertices[0], Eigen::Vector3d(1, 2, 3));
  ASSERT_TRUE(old.rotation);
  ASSERT_EQ(old.rotation->corners.size(), 1u);
  EXPECT_TRUE(old.rotation->corners[0].rotatable);
  EXPECT_EQ(old.margin_deg, 0) << "absent: the verdict's default";
  EXPECT_FALSE(old.dynamics);
  // A damaged report: the columns alone.
  const ReportBlock& damaged = back[1];
  EXPECT_EQ(damaged.id, "B9");
  EXPECT_TRUE(damaged.finite && !damaged.removable && damaged.marginal);
  EXPECT_FALSE(damaged.mode);
  EXPECT_FALSE(damaged.fos);
  EXPECT_EQ(damaged.volume, 0.5) << "the column's volume, the report having none";
  EXPECT_TRUE(damaged.vertices.empty());
}

// The mapping without a file: the row's columns and JSON from a verdict.
TEST(ProjectBlockRow, TheRowsColumnsComeFromTheVerdict) {
  const BlockRow row = block_row(bare_block());
  EXPECT_EQ(row.label, "B2");
  EXPECT_EQ(row.mode, "none");
  EXPECT_EQ(row.volume_m3, 0);
  EXPECT_FALSE(row.fos);
  EXPECT_EQ(row.report_json, block_to_json(bare_block()));
  EXPECT_EQ(block_to_json(block_of_row(row)), row.report_json);
}

}  // namespace

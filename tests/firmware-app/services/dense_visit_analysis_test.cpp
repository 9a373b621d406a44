// The tablet's analysis of a densely mapped visit (issue 28): 200 traces
// stored with a joint plane each, analysed by the UI's runner
// (StoreAnalysisRunner, the same workflow as `rockface analyse`): the
// analysis is saved with the blocks of every trace and their verdicts.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/progress.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project_store.h"
#include "tests/support/dense_face.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;

TEST(DenseVisitAnalysis, TwoHundredStoredTracesWithTheirOwnPlanesAnalyse) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-dense-visit-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "face.rockface";
  storage::ProjectInfo info;
  info.name = "densely mapped face";
  info.datum = {2690000.0, 1170000.0, 1100.0};
  const test::DenseFace face = test::dense_face(200);
  storage::RecordId visit = 0;
  {
    storage::ProjectStore store = storage::ProjectStore::create(file, info);
    visit = store.begin_visit("tablet");
    std::vector<storage::Measurement> measurements;
    storage::Measurement area;
    area.kind = storage::Measurement::Kind::area;
    area.label = "FACE";
    area.points = face.polygon();
    area.dip_deg = 90;
    area.dipdir_deg = 180;
    area.rock_side = "lower";
    measurements.push_back(area);
    std::vector<storage::Joint> joints;
    for (const auto& t : face.traces) {
      storage::Measurement m;
      m.kind = storage::Measurement::Kind::trace;
      m.label = t.id;
      m.joint_label = t.joint;
      m.points = {t.from, t.point, t.to};
      m.dip_deg = t.dip;
      m.dipdir_deg = t.dipdir;
      measurements.push_back(m);
      storage::Joint j;
      j.label = t.joint;
      j.dip_deg = t.dip;
      j.dipdir_deg = t.dipdir;
      j.point = t.point;
      j.friction_deg = t.friction;
      j.cohesion_pa = 0;
      j.source = "trace " + t.id;
      j.type = "trace";
      joints.push_back(j);
    }
    store.save_measurements(visit, measurements);
    store.save_joints(visit, {}, joints);
  }

  NoProgress progress;
  app::StoreAnalysisRunner runner;
  const storage::RecordId id = runner.analyse(file, visit, progress);
  storage::ProjectStore store = storage::ProjectStore::open(file);
  const storage::AnalysisRun run = store.load_analysis(id);
  int trace_blocks = 0, finite = 0, with_margin = 0;
  for (const auto& b : run.blocks) {
    if (b.source != "traces") continue;
    ++trace_blocks;
    finite += b.finite;
    const nlohmann::json report = nlohmann::json::parse(b.report_json);
    with_margin += report.contains("margin_deg") && report.at("margin_deg").is_number();
  }
  // 200 traces of 2-8 m on a 20 x 10 m face cut it into hundreds of loops,
  // each a block with its verdicts and margin.
  EXPECT_GT(trace_blocks, 100);
  EXPECT_GT(finite, 0);
  EXPECT_EQ(with_margin, trace_blocks);
  fs::remove_all(dir);
}

}  // namespace

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
#include "storage/project/project_store.h"
#include "tests/support/dense_face_visit.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;

TEST(DenseVisitAnalysis, TwoHundredStoredTracesWithTheirOwnPlanesAnalyse) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-dense-visit-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "face.rockface";
  const test::DenseFace face = test::dense_face(200);
  const storage::RecordId visit = test::make_dense_visit(file, face, face.traces.size());

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

// `rockface analyse SCENE.json [--out REPORT.json] [--summary]`
#include <iostream>
#include <memory>

#include "core/analysis/scene_analysis.h"
#include "firmware-app/analysis/report_files.h"
#include "firmware-app/analysis/scene_input.h"
#include "firmware-app/cli/verb_registry.h"
#include "storage/report/report.h"
#include "storage/scene/scene.h"

namespace rockface::app {
namespace {

struct AnalyseOptions {
  std::string scene;
  std::string out;
  bool summary = false;
};

VerbRun setup_analyse(CLI::App& sub) {
  auto opts = std::make_shared<AnalyseOptions>();
  sub.add_option("SCENE", opts->scene, "scene file (rockface-scene/1)")->required();
  sub.add_option("--out", opts->out,
                 "write the report (rockface-report/1) to this file instead of stdout");
  sub.add_flag("--summary", opts->summary,
               "print a readable table of verdicts instead of the JSON report");
  return [opts] {
    const storage::Scene scene = storage::load_scene(opts->scene);
    NoProgress progress;
    analysis::Report report = analysis::analyse(analysis_input(scene), progress);
    // The path of each block's equilibrium-path analysis as a PNG beside the report.
    if (!opts->out.empty()) write_report_files(report, opts->out);
    if (opts->summary) {
      std::cout << (scene.name.empty() ? opts->scene : scene.name) << "\n"
                << analysis::report_summary(report);
    } else if (opts->out.empty()) {
      std::cout << storage::report_to_json(report);
    }
    return 0;
  };
}

const VerbRegistrar analyse_verb{
    "analyse", "geometric and mechanical analysis of a scene; report on stdout or to a file",
    setup_analyse};

}  // namespace
}  // namespace rockface::app

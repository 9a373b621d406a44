// `rockface analyse SCENE.json [--out REPORT.json] [--summary]`
#include <cstdio>
#include <fstream>
#include <iostream>

#include "firmware-app/mechanics_plot.h"
#include "firmware-app/scene_analysis.h"
#include "firmware-app/verb_registry.h"
#include "storage/scene.h"

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
    storage::Report report = analyse_scene(scene, progress);
    // The path of each block's equilibrium-path analysis as a PNG beside the report.
    if (!opts->out.empty()) write_mechanics_plots(report, opts->out);
    const std::string json = storage::report_to_json(report);
    if (!opts->out.empty()) {
      // Write beside the target and rename, so a full disk never leaves a
      // half-written report in place of a good one.
      const std::string tmp = opts->out + ".part";
      {
        std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
        f << json;
        f.flush();
        if (!f) {
          std::remove(tmp.c_str());
          throw Error(opts->out + ": cannot write the report (disk full or no permission?)");
        }
      }
      if (std::rename(tmp.c_str(), opts->out.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw Error(opts->out + ": cannot write the report");
      }
    }
    if (opts->summary) {
      std::cout << (scene.name.empty() ? opts->scene : scene.name) << "\n"
                << storage::report_summary(report);
    } else if (opts->out.empty()) {
      std::cout << json;
    }
    return 0;
  };
}

const VerbRegistrar reg{
    "analyse", "geometric and mechanical analysis of a scene; report on stdout or to a file",
    setup_analyse};

}  // namespace
}  // namespace rockface::app

// `rockface replay CAPTURE_DIR_OR_SCENE --project PROJECT.rockface`
#include <cstdio>
#include <iostream>

#include "core/common/preset.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/replay/field_replay.h"

namespace rockface::app {
namespace {

// Progress on stderr, one line per stage, so a long replay shows where it is.
class StderrProgress final : public Progress {
 public:
  void report(std::string_view stage, double) override {
    if (stage != last_) std::cerr << "replay: " << stage << "\n";
    last_ = std::string(stage);
  }
  bool cancel_requested() const override { return false; }

 private:
  std::string last_;
};

VerbRun setup_replay(CLI::App& sub) {
  auto req = std::make_shared<ReplayRequest>();
  auto preset = std::make_shared<std::string>();
  sub.add_option("SOURCE", req->source,
                 "a scene with an imaging section, or a folder of captures with camera.json")
      ->required();
  sub.add_option("--project", req->project, "project file (*.rockface); created when missing")
      ->required();
  CLI::Option* preset_option = sub.add_option(
      "--preset", *preset, "fast | standard | precise (default: the scene's analysis.preset)");
  return [req, preset, preset_option] {
    if (preset_option->count() > 0) req->preset = parse_preset(*preset, "--preset");
    StderrProgress progress;
    const ReplayOutcome out = replay_field_workflow(*req, progress);
    std::cout << "project " << req->project << ": visit " << out.visit_id << ", capture "
              << out.capture_id << ", model " << out.model_id << " (" << out.model_points
              << " points; " << out.registration << "; predicted depth precision "
              << out.predicted_depth_sigma_m * 1000 << " mm)\n";
    for (const auto& g : out.guidance) std::cout << "capture: " << g << "\n";
    if (out.report) std::cout << storage::report_summary(*out.report);
    return 0;
  };
}

const VerbRegistrar reg{
    "replay", "the field workflow, headless, through the mock camera, stored in a project",
    setup_replay};

}  // namespace
}  // namespace rockface::app

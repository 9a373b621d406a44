// `rockface replay CAPTURE_DIR_OR_SCENE --project PROJECT.rockface`
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "core/common/number_format.h"
#include "core/common/preset.h"
#include "firmware-app/cli/registration_cli.h"
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

// Each joint measured from its picked traces beside the scene's plane.
void print_joint_comparisons(const std::vector<JointComparison>& joints) {
  if (joints.empty()) return;
  const auto plane = [](double dip, double dipdir) {
    return format_fixed(dip, 1) + "/" + format_zero_padded(dipdir, 5, 1);
  };
  std::cout << "\njoints measured from the picked traces (dip/dip direction, degrees):\n"
            << std::left << std::setw(7) << "joint" << std::setw(20) << "measured (1 sigma)"
            << std::setw(13) << "scene" << std::setw(10) << "apart"
            << "traces\n";
  for (const auto& j : joints) {
    std::string traces;
    for (const auto& t : j.traces) {
      traces += (traces.empty() ? "" : " ") + t;
      // The plane a geologist read with a compass on this trace's joint.
      for (const auto& read : j.compass_read)
        if (read == t) traces += " (compass)";
    }
    const std::string sigma = " (" + format_fixed(j.sigma, 1) + ")";
    const std::string apart = format_fixed(j.angle, 1, " deg");
    std::cout << std::setw(7) << j.id << std::setw(20)
              << (j.measured ? plane(j.dip, j.dipdir) + sigma : "unknown") << std::setw(13)
              << plane(j.scene_dip, j.scene_dipdir) << std::setw(10) << (j.measured ? apart : "-")
              << traces << (j.measured ? "" : " (the scene's plane is kept)") << "\n";
  }
  std::cout << std::right;
}

VerbRun setup_replay(CLI::App& sub) {
  auto req = std::make_shared<ReplayRequest>();
  auto preset = std::make_shared<std::string>();
  sub.add_option("SOURCE", req->source,
                 "a scene with an imaging section, or a folder of photographs with camera.json "
                 "(and visit.json: the pole, the compass line, rockface-visit/1)")
      ->required();
  sub.add_option("--project", req->project, "project file (*.rockface); created when missing")
      ->required();
  add_registration_options(sub, req->registration);
  sub.add_option("--heading", req->heading,
                 "the face the visit is taken at, when the tunnel is driven from more than one "
                 "(e.g. \"North portal\", \"Bench\"; default: the visit file's)")
      ->type_name("NAME");
  sub.add_option("--geologist", req->geologist,
                 "the geologist who maps the visit, by name (default: the visit file's)")
      ->type_name("NAME");
  CLI::Option* preset_option = sub.add_option(
      "--preset", *preset, "fast | standard | precise (default: the scene's analysis.preset)");
  return [req, preset, preset_option] {
    if (preset_option->count() > 0) req->preset = parse_preset(*preset, "--preset");
    StderrProgress progress;
    const ReplayOutcome out = replay_field_workflow(*req, progress);
    std::cout << "project " << req->project << ": visit " << out.visit_id << ", capture "
              << out.capture_id << ", model " << out.model_id << " (" << out.model_points
              << " points; " << out.registration << "; predicted depth precision ";
    // An unscaled model's lengths are in base lengths, not metres (issue 38).
    if (out.scaled)
      std::cout << out.predicted_depth_sigma_m * 1000 << " mm)\n";
    else
      std::cout << format_significant(out.predicted_depth_sigma_m, 3)
                << " base lengths: unscaled, no range pole, control points or baseline)\n";
    if (!out.heading.empty()) std::cout << "heading: " << out.heading << "\n";
    if (!out.geologist.empty()) std::cout << "geologist: " << out.geologist << "\n";
    for (const auto& g : out.guidance) std::cout << "capture: " << g << "\n";
    print_joint_comparisons(out.joints);
    if (out.report) std::cout << analysis::report_summary(*out.report);
    return 0;
  };
}

const VerbRegistrar replay_verb{
    "replay", "the field workflow, headless, through the mock camera, stored in a project",
    setup_replay};

}  // namespace
}  // namespace rockface::app

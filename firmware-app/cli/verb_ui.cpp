// `rockface ui [--project P] [--camera SOURCE] [[--headless] --script STEPS.json --screenshots
// DIR]`
#include "firmware-app/cli/verb_ui.h"

#include <iostream>

#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/services/ui_services.h"
#include "ui/platform/headless_session.h"
#include "ui/platform/window_runner.h"
#include "ui/widgets/format.h"

namespace rockface::app {
namespace {

struct UiRequest {
  std::string project, camera, projects_folder = ".", script, screenshots;
  bool headless = false;
  float scale = 0;  // 0: from --dpi, else 1
  float dpi = 0;    // 0: the window's, else what the scale stands for
  std::string settings;
  std::size_t max_triangles = ui::UiOptions{}.max_display_triangles;
};

int run_ui(const UiRequest& req) {
  ui::UiOptions options;
  options.project = req.project;
  options.projects_folder = req.projects_folder;
  // The scale follows the density when only the density is given: the
  // layout of a 10" 1280 x 800 tablet at any pixel density.
  options.scale = req.scale > 0 ? req.scale : req.dpi > 0 ? req.dpi / ui::kScaleOneDpi : 1;
  options.dpi = req.dpi;
  options.settings_file =
      req.settings.empty() ? ui::default_settings_file() : std::filesystem::path(req.settings);
  options.max_display_triangles = req.max_triangles;
  FieldRunners runners(req.camera);
  const ui::FieldServices services = runners.services();
  if (req.script.empty()) {
    ui::run_in_window(options, services);
    return 0;
  }
  const ui::UiScript script = ui::load_ui_script(req.script);
  ui::ScriptRun run;
  if (req.headless) {
    ui::HeadlessSession session(options, services, script.width, script.height);
    std::cout << "renderer: " << session.renderer() << "\n";
    run = ui::run_ui_script(session, script, req.screenshots);
  } else {
    run = ui::run_script_in_window(options, services, script, req.screenshots);
  }
  for (const auto& s : run.screenshots) std::cout << "screenshot " << s.string() << "\n";
  // What the script cost on each screen (docs/accuracy-cost.md, the UI).
  int taps = 0;
  double seconds = 0;
  for (const auto& u : run.screens) {
    std::cout << "screen " << u.screen << ": " << u.taps << (u.taps == 1 ? " tap, " : " taps, ")
              << ui::format::text(ui::format::Duration{u.seconds}) << "\n";
    taps += u.taps;
    seconds += u.seconds;
  }
  std::cout << "screens in all: " << taps << " taps, "
            << ui::format::text(ui::format::Duration{seconds}) << "\n";
  std::cout << "status: " << run.status << "\n";
  return 0;
}

VerbRun setup_ui(CLI::App& sub) {
  auto req = std::make_shared<UiRequest>();
  sub.add_option("--project", req->project, "project to open (*.rockface)")
      ->check(CLI::ExistingFile);
  sub.add_option("--camera", req->camera,
                 "mock camera: a scene with an imaging section or a folder of captures "
                 "(default: the DSLR over USB)");
  sub.add_option("--projects-folder", req->projects_folder,
                 "where the Project screen lists and creates projects (default: .)");
  sub.add_option("--scale", req->scale,
                 "UI scale, 1 = a 10\" 1280x800 tablet (default: --dpi / 150, else 1)")
      ->check(CLI::Range(0.3, 4.0));
  sub.add_option("--dpi", req->dpi,
                 "the screen's pixels per inch, for 9 mm touch targets (default: the window's; "
                 "headless: 150 x scale)")
      ->check(CLI::Range(50.0, 1000.0));
  sub.add_option("--settings", req->settings,
                 "the tablet's settings file (theme); default $XDG_CONFIG_HOME/rockface/ui.json");
  sub.add_option("--max-triangles", req->max_triangles,
                 "triangles the model view draws at most (the model is decimated for display)");
  auto* headless = sub.add_flag("--headless", req->headless,
                                "no window: surfaceless EGL (Mesa), replays --script");
  auto* script = sub.add_option("--script", req->script,
                                "STEPS.json: taps and screenshots to replay (in the window "
                                "unless --headless), then exit")
                     ->check(CLI::ExistingFile);
  sub.add_option("--screenshots", req->screenshots, "folder for the script's screenshots")
      ->needs(script);
  headless->needs(script);
  return [req] {
    if (req->screenshots.empty()) req->screenshots = ".";
    return run_ui(*req);
  };
}

const VerbRegistrar ui_verb{
    "ui", "the tablet UI (a window; a script of taps replayed in it or headless)", setup_ui};

}  // namespace

int start_tablet_ui() {
  return run_ui(UiRequest{});
}

}  // namespace rockface::app

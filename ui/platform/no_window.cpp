// The window platform of a build without X11 (see ui/CMakeLists.txt).
#ifndef ROCKFACE_UI_X11
#include "core/common/error.h"
#include "ui/platform/window_runner.h"

namespace rockface::ui {

namespace {
[[noreturn]] void no_window() {
  throw Error(
      "this build has no window support (libx11-dev was missing); run it headless: "
      "rockface ui --headless --script STEPS.json --screenshots DIR");
}
}  // namespace

void run_in_window(const UiOptions&, const FieldServices&) {
  no_window();
}

ScriptRun run_script_in_window(const UiOptions&, const FieldServices&, const UiScript&,
                               const std::filesystem::path&) {
  no_window();
}

}  // namespace rockface::ui
#endif

// The window platform of a build without X11 (see ui/CMakeLists.txt).
#ifndef ROCKFACE_UI_X11
#include "core/common/error.h"
#include "ui/window_runner.h"

namespace rockface::ui {

void run_in_window(const UiOptions&, const FieldServices&) {
  throw Error(
      "this build has no window support (libx11-dev was missing); run it headless: "
      "rockface ui --headless --script STEPS.json --screenshots DIR");
}

}  // namespace rockface::ui
#endif

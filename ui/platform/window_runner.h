#pragma once
// The tablet UI on a screen: an X11 window with a GLES 3 context (EGL).
// Fingers come as XInput 2.2 touch sequences where the server offers them
// (pinch and two-finger pan); otherwise the pointer is the one finger and
// the mouse wheel pinches.
#include <filesystem>

#include "ui/app/app_state.h"
#include "ui/app/ui_driver.h"

namespace rockface::ui {

// Runs until the window is closed. Throws rockface::Error when there is no
// display to open (DISPLAY unset, or a build without X11), saying what to
// do instead.
void run_in_window(const UiOptions& options, const FieldServices& services);

// Replays a script in the window (a demonstration on the device, or a test
// of the window platform) and returns at its end.
ScriptRun run_script_in_window(const UiOptions& options, const FieldServices& services,
                               const UiScript& script,
                               const std::filesystem::path& screenshots_dir);

}  // namespace rockface::ui

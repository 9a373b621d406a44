#pragma once
// The tablet UI on a screen: a full-screen X11 window with a GLES 3 context
// (EGL), the pointer (which the X server drives from the touch screen, with
// touch emulation) as the primary finger and the wheel as pinch. Runs until
// the window is closed.
#include "ui/app_state.h"

namespace rockface::ui {

// Throws rockface::Error when there is no display to open (DISPLAY unset,
// or a build without X11) with what to do instead.
void run_in_window(const UiOptions& options, const FieldServices& services);

}  // namespace rockface::ui

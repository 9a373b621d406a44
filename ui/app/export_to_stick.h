#pragma once
// Issue 43: "Export to USB stick", on the Blocks and Project screens: the
// visit's exports for the office's tools (the 3D image as OBJ / PLY, traces,
// joints, blocks and the profile as DXF and CSV) into a folder on the USB
// stick plugged in; without one, the status line says to plug one in.
#include "ui/app/app_state.h"

namespace rockface::ui {

// A button in the current row; nothing without an export service or a visit.
void draw_export_to_stick(AppState& app);

}  // namespace rockface::ui

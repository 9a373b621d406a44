#pragma once
// The Mapping screen's "Compass reading" (issue 27): for the trace being
// marked (saved with it) or a saved trace (its plane and joint remade by
// the map's runner, as `rockface measure` measures a trace whose pick
// carries `compass`).
#include "ui/app_state.h"

namespace rockface::ui {

// The block of the side panel: which trace, dip and dip direction with
// their keypad, and Save reading / Clear reading for a saved trace.
void draw_compass_entry(AppState& app);

// The reading typed for the trace being marked, put on its record by Save
// trace. False, with the reason on the status line, when what was typed is
// no reading (nothing is saved then: the geologist mends it).
bool attach_compass_reading(AppState& app, storage::Measurement& m);

// An edit of the map on the 3D image on display (its picker, model and the
// point precision the screen measures with); mapping_screen.cpp.
MapEdit map_edit(const AppState& app);

}  // namespace rockface::ui

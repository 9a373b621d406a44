#pragma once
// The Mapping screen's "Compass reading" (issue 27): for the trace being
// marked (saved with it) or a saved trace (its plane and joint remade by
// the map's runner, as `rockface measure` measures a trace whose pick
// carries `compass`).
#include "ui/app/app_state.h"

namespace rockface::ui {

// "Compass", in the row of Outline the face: opens the compass panel.
void draw_compass_button(AppState& app);
// The compass panel in place of the side panel's other controls while it is
// open (all of it in view at once: keys a gloved thumb hits take room):
// which trace, dip and dip direction with their keypad, Save trace for the
// trace being marked or Save reading / Clear reading for a saved one, and
// Done. False (nothing drawn) when it is closed.
bool draw_compass_panel(AppState& app);

// The reading typed for the trace being marked, put on its record by Save
// trace. False, with the reason on the status line, when what was typed is
// no reading (nothing is saved then: the geologist mends it).
bool attach_compass_reading(AppState& app, storage::Measurement& m);

// An edit of the map on the 3D image on display (its picker, model and the
// point precision the screen measures with); mapping_screen.cpp.
MapEdit map_edit(const AppState& app);
// Save trace of the trace being marked (with its reading); mapping_screen.cpp.
void save_trace(AppState& app);

}  // namespace rockface::ui

#pragma once
// The five screens of the field workflow, one file each; each draws the
// main area of one frame from the shared AppState.
#include "ui/app_state.h"

namespace rockface::ui {

void draw_project_screen(AppState& app);
void draw_capture_screen(AppState& app);
void draw_model_screen(AppState& app);
void draw_mapping_screen(AppState& app);
void draw_blocks_screen(AppState& app);

// The Mapping screen's save of one trace (hand-marked or a proposal) and
// the update of the map's blocks after it, on the worker. False (nothing
// started) while the worker is busy.
bool store_trace(AppState& app, storage::Measurement m);

// Shared by the screens that need a model: a note where it is missing.
bool require_model(AppState& app);

}  // namespace rockface::ui

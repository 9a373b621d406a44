#pragma once
// The five screens of the field workflow, one file each; each draws the
// main area of one frame from the shared AppState.
#include <functional>
#include <string>

#include "ui/app/app_state.h"

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
// Issue 27: any edit of the map (a trace, the face outline, a trace taken
// back) stored by FieldServices::trace_map on the worker, the blocks
// updated after it; `then` runs on the UI thread once stored.
bool store_map_edit(AppState& app, MapEdit edit, const std::string& title,
                    std::function<void(AppState&)> then);

// Shared by the screens that need a model: a note where it is missing.
bool require_model(AppState& app);

}  // namespace rockface::ui

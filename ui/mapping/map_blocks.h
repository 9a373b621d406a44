#pragma once
// The blocks of the trace map on the Mapping screen (issue 28): after every
// saved trace the worker updates them (FieldServices::trace_map, which
// recomputes only the regions the edit touched); the screen draws each
// finite block's loop on the model in its verdict's colour and lists them
// beside it, where it lies on the 3D image. Loops that are not finite are
// counted, not drawn: they are no block.
#include <memory>
#include <optional>
#include <string>

#include <imgui.h>

#include "core/common/progress.h"
#include "ui/app/field_services.h"

namespace rockface::ui {

struct AppState;

struct MapBlocksState {
  std::shared_ptr<const MapVerdicts> verdicts;  // of `visit`'s traces as last saved
  storage::RecordId visit = 0;
  std::string problem;  // why there are none (no surface, a bad trace); stays until the next edit
  bool stale = true;    // the traces changed since `verdicts`
  // The block tapped on the model ("TB<n>" is block n of `selected_of`): its
  // verdict is shown beside its marker and in the panel. A new set of
  // verdicts (another edit) numbers its blocks anew: the selection goes.
  std::optional<int> selected;
  const MapVerdicts* selected_of = nullptr;
};

// Runs on the worker after a trace was saved (or when the screen opens):
// the verdicts of the visit's stored traces. Null when the services have
// no trace map runner.
std::shared_ptr<const MapVerdicts> update_map_blocks(const FieldServices& services,
                                                     const std::filesystem::path& project,
                                                     storage::RecordId visit, Progress& progress);

// One line for the status bar: "3 blocks (1 moves, 2 hold), updated in 42 ms".
std::string map_blocks_summary(const MapVerdicts& verdicts);

// Starts the update on the worker when the verdicts are stale and the worker
// is free (the Mapping screen calls it every frame).
void refresh_map_blocks(AppState& app);

// The finite blocks' loops laid on the model's surface (before the model
// view draws: ui/view3d/overlay_blocks.h), and their markers and labels on top
// (after it, inside its clip rectangle). Each marker is a touch target (a
// disc 9 mm across at the tablet's DPI, "map block TB<n>", like the Blocks
// screen's markers) around the block's dot in its verdict's colour.
void add_map_blocks_to_overlay(AppState& app);
void draw_map_blocks_on_model(AppState& app);

// A tap on the model (after ModelView::draw): on a block's marker it selects
// that block, or takes the selection back when it is already selected, and
// is used up (true). While a trace or the face's outline is being marked,
// taps are its corners and no marker takes them (false).
bool tap_map_block(AppState& app, ImVec2 tap);

// The selected block in words: "TB2 moves: sliding, factor of safety 0.85,
// margin 4.3°"; empty when none is selected.
std::string selected_map_block_in_words(const MapBlocksState& blocks);

// The side panel's list: counts by verdict, each finite block with its mode,
// factor of safety and margin, and what the map left out.
void draw_map_blocks_panel(AppState& app);

}  // namespace rockface::ui

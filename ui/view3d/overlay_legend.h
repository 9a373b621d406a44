#pragma once
// The legend of the colours on the 3D image, in the model panel's bottom
// right corner: what the screen draws and nothing else (the joints whose
// traces are shown, the verdicts of the blocks shown, the open / unknown
// border of a block past the 3D image, the range-pole targets).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <imgui.h>

namespace rockface::ui {

struct AppState;

struct LegendEntry {
  ImU32 colour = 0;
  std::string words;
  enum class Swatch { line, dashed, area, ring } swatch = Swatch::line;
};

// The entries for each screen that draws on the 3D image.
std::vector<LegendEntry> model_legend(const AppState& app);
std::vector<LegendEntry> mapping_legend(const AppState& app);
std::vector<LegendEntry> blocks_legend(const AppState& app);

// Records where it drew as the model view's flat mark "legend" (as the
// scale bar and the north arrow: "scale bar", "north arrow"), for tests.
// In the panel's bottom right corner; `keep_clear` (a rectangle already
// drawn, e.g. the scale bar) makes it sit above that rectangle when it
// would otherwise cover it.
void draw_legend(AppState& app, const std::vector<LegendEntry>& entries,
                 std::optional<std::pair<ImVec2, ImVec2>> keep_clear = std::nullopt);

// The Model and Mapping screens' legend, scale bar and north arrow, the
// Blocks screen's legend: one call after ModelView::draw, inside the
// panel's clip rectangle.
enum class ModelScreen { model, mapping, blocks };
void draw_model_overlays(AppState& app, ModelScreen screen);

}  // namespace rockface::ui

#pragma once
// Scripts of taps for headless runs (tests, documentation screenshots):
//
//   { "viewport": [1280, 800],
//     "steps": [ { "tap": "Blocks" },              // a button (or target) by its label
//                { "tap": [640, 400] },            // a pixel, origin top left
//                { "drag": [[600, 400], [700, 420]] },
//                { "pinch": { "centre": [640, 400], "from": 100, "to": 200 } },
//                { "wait": "task" },               // until the worker is idle
//                { "frames": 3 },
//                { "screenshot": "blocks" } ] }    // DIR/blocks.png
//
// A step names a target that was drawn in the previous frame; an unknown
// label is an InputError naming the step.
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>

namespace rockface::ui {

struct ScriptStep {
  enum class Kind { tap, drag, pinch, wait_task, frames, screenshot };
  Kind kind = Kind::frames;
  std::string label;                    // tap by label; screenshot name
  std::vector<Eigen::Vector2f> points;  // tap: one; drag: from, to; pinch: centre
  float pinch_from = 0, pinch_to = 0;   // finger spread, px
  int frames = 1;
};

struct UiScript {
  int width = 1280, height = 800;
  std::vector<ScriptStep> steps;
};

// Throws InputError naming the file and the step.
UiScript load_ui_script(const std::filesystem::path& file);
UiScript parse_ui_script(const std::string& text, const std::string& source);

}  // namespace rockface::ui

#pragma once
// The synthetic mock camera to files (`rockface render`): a scene's imaging
// section rendered and written to a folder as left.png, right.png,
// depth-left.pfm, camera.json and truth.json (render_truth_json.h), each
// file whole or not at all.
#include <cstddef>
#include <string>

namespace rockface::app {

struct RenderedPair {
  int width = 0, height = 0;        // of each image
  std::size_t trace_segments = 0;   // true traces seen
  std::size_t targets = 0;          // range pole targets
  std::size_t targets_in_both = 0;  // of them, visible in both images
};

// Throws InputError naming the scene file or the folder at fault, Error
// when a file cannot be written.
RenderedPair render_scene_files(const std::string& scene_file, const std::string& folder);

}  // namespace rockface::app

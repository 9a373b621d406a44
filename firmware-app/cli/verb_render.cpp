// `rockface render SCENE.json --out DIR`: the synthetic mock camera. Writes
// left.png, right.png, camera.json, truth.json and depth-left.pfm.
#include <iostream>
#include <memory>

#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/render/render_scene_files.h"

namespace rockface::app {
namespace {

struct RenderOptions {
  std::string scene;
  std::string out;
};

VerbRun setup_render(CLI::App& sub) {
  auto opts = std::make_shared<RenderOptions>();
  sub.add_option("SCENE", opts->scene, "scene file with an imaging section (rockface-scene/1)")
      ->required();
  sub.add_option("--out", opts->out,
                 "folder for left.png, right.png, camera.json, truth.json, depth-left.pfm")
      ->required();
  return [opts] {
    const RenderedPair r = render_scene_files(opts->scene, opts->out);
    std::cout << "rendered " << r.width << "x" << r.height << " pair to " << opts->out << ": "
              << r.trace_segments << " trace segment(s), " << r.targets_in_both << " of "
              << r.targets << " target(s) visible in both images\n";
    return 0;
  };
}

const VerbRegistrar render_verb{
    "render",
    "the synthetic mock camera: both images of a scene with poses, depth, "
    "target centres and true traces",
    setup_render};

}  // namespace
}  // namespace rockface::app

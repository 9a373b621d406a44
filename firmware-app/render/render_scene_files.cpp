#include "firmware-app/render/render_scene_files.h"

#include <filesystem>

#include "camera/synthetic_renderer.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "firmware-app/render/render_truth_json.h"
#include "firmware-app/render/synthetic_scene_from_scene.h"
#include "storage/exchange/image_file.h"
#include "storage/scene/camera_json.h"
#include "storage/scene/scene.h"

namespace rockface::app {

namespace {

namespace fs = std::filesystem;

}  // namespace

RenderedPair render_scene_files(const std::string& scene_file, const std::string& folder) {
  const storage::Scene scene = storage::load_scene(scene_file);
  const SyntheticSceneInput input = synthetic_scene_from_scene(scene);
  NoProgress progress;
  const camera::SyntheticRender render = camera::render_scene(input.scene, progress);

  const fs::path dir(folder);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir))
    throw InputError(folder, "cannot create the output folder" +
                                 (ec ? " (" + ec.message() + ")" : std::string()));
  storage::write_image_file(dir / "left.png", render.images[0]);
  storage::write_image_file(dir / "right.png", render.images[1]);
  storage::write_image_file(dir / "depth-left.pfm", render.depth_left);
  photogrammetry::CameraIntrinsics cam = render.intrinsics;
  cam.body = "rockface synthetic camera";
  cam.lens = "synthetic";
  cam.focus = "fixed";
  storage::save_camera_json((dir / "camera.json").string(), cam);
  const std::string truth = render_truth_json(input.scene, render, input.origin,
                                              scene.name.empty() ? scene_file : scene.name);
  write_file_atomically(dir / "truth.json", [&](std::ostream& o) { o << truth; });

  RenderedPair out;
  out.width = render.intrinsics.width;
  out.height = render.intrinsics.height;
  out.trace_segments = render.traces.size();
  out.targets = render.targets.size();
  for (const auto& t : render.targets) out.targets_in_both += t.visible[0] && t.visible[1];
  return out;
}

}  // namespace rockface::app

// `rockface render SCENE.json --out DIR`: the synthetic mock camera. Writes
// left.png, right.png, camera.json, truth.json and depth-left.pfm.
#include <filesystem>
#include <fstream>
#include <iostream>

#include <opencv2/imgcodecs.hpp>

#include "camera/synthetic_renderer.h"
#include "core/common/error.h"
#include "firmware-app/render_truth_json.h"
#include "firmware-app/synthetic_scene_from_scene.h"
#include "firmware-app/verb_registry.h"
#include "storage/camera_json.h"
#include "storage/export_file.h"
#include "storage/scene.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;

struct RenderOptions {
  std::string scene;
  std::string out;
};

// Writes an image through a temporary file, so a full card never leaves a
// truncated image under the final name.
void write_image(const fs::path& path, const cv::Mat& image) {
  const fs::path part = path.string() + ".part" + path.extension().string();
  bool ok = false;
  try {
    ok = cv::imwrite(part.string(), image);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) {
    fs::remove(part);
    throw Error(path.string() + ": cannot write the image (disk full or no permission?)");
  }
  fs::rename(part, path);
}

VerbRun setup_render(CLI::App& sub) {
  auto opts = std::make_shared<RenderOptions>();
  sub.add_option("SCENE", opts->scene, "scene file with an imaging section (rockface-scene/1)")
      ->required();
  sub.add_option("--out", opts->out,
                 "folder for left.png, right.png, camera.json, truth.json, depth-left.pfm")
      ->required();
  return [opts] {
    const storage::Scene scene = storage::load_scene(opts->scene);
    const SyntheticSceneInput input = synthetic_scene_from_scene(scene);
    NoProgress progress;
    const camera::SyntheticRender render = camera::render_scene(input.scene, progress);

    const fs::path dir(opts->out);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (!fs::is_directory(dir))
      throw InputError(opts->out, "cannot create the output folder" +
                                      (ec ? " (" + ec.message() + ")" : std::string()));
    write_image(dir / "left.png", render.images[0]);
    write_image(dir / "right.png", render.images[1]);
    write_image(dir / "depth-left.pfm", render.depth_left);
    photogrammetry::CameraIntrinsics cam = render.intrinsics;
    cam.body = "rockface synthetic camera";
    cam.lens = "synthetic";
    cam.focus = "fixed";
    storage::save_camera_json((dir / "camera.json").string(), cam);
    const std::string truth = render_truth_json(input.scene, render, input.origin,
                                                scene.name.empty() ? opts->scene : scene.name);
    storage::write_file_atomically(dir / "truth.json", [&](std::ostream& o) { o << truth; });

    int visible = 0;
    for (const auto& t : render.targets) visible += t.visible[0] && t.visible[1];
    std::cout << "rendered " << render.intrinsics.width << "x" << render.intrinsics.height
              << " pair to " << opts->out << ": " << render.traces.size() << " trace segment(s), "
              << visible << " of " << render.targets.size()
              << " target(s) visible in both images\n";
    return 0;
  };
}

const VerbRegistrar reg{"render",
                        "the synthetic mock camera: both images of a scene with poses, depth, "
                        "target centres and true traces",
                        setup_render};

}  // namespace
}  // namespace rockface::app

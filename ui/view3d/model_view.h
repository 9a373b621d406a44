#pragma once
// The 3D image in a panel: the stored model, decimated for display and
// textured with its photograph, seen through an orbit camera that one
// finger turns, two fingers pan and pinch zoom. Screens draw their overlays
// (targets, traces, blocks) on top with to_screen().
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include <imgui.h>

#include "core/measure/mesh_picker.h"
#include "core/measure/photo_view.h"
#include "storage/project/project_records.h"
#include "ui/view3d/display_mesh.h"
#include "ui/view3d/model_renderer.h"
#include "ui/view3d/orbit_camera.h"
#include "ui/view3d/overlay_blocks.h"
#include "ui/view3d/overlay_drape.h"
#include "ui/view3d/overlay_scene.h"
#include "ui/view3d/overlay_targets.h"
#include "ui/view3d/overlay_text.h"
#include "ui/widgets/touch_input.h"

namespace rockface::ui {

// A model read and prepared on a worker, ready to upload on the UI thread.
// Measuring works on the stored mesh at full resolution (picker); only the
// display is decimated.
struct PreparedModel {
  storage::RecordId id = 0;
  std::shared_ptr<const storage::Model> model;  // the record; its mesh moved to `surface`
  std::shared_ptr<const photogrammetry::SurfaceMesh> surface;
  std::shared_ptr<const measure::MeshPicker> picker;  // on `surface`
  std::optional<measure::PhotoView> left_view;        // when the capture's calibration is stored
  DisplayMesh mesh;
  std::shared_ptr<const SurfaceDrape> drape;  // on `mesh`: overlays are laid on what is drawn
  cv::Mat photo_bgr;                          // the texture photograph (full size); empty when none
  std::vector<TargetOnModel> targets;         // the range pole's, located on `surface`
};

// Worker side: opens its own store on `project`.
PreparedModel prepare_model(const std::filesystem::path& project, storage::RecordId model_id,
                            std::size_t max_triangles);

class ModelView {
 public:
  // UI thread (GL context current).
  void install(PreparedModel prepared);
  void clear();
  bool has_model() const { return model_ != nullptr; }
  storage::RecordId model_id() const { return id_; }
  const storage::Model* model() const { return model_.get(); }
  const photogrammetry::SurfaceMesh* surface() const { return surface_.get(); }
  const measure::MeshPicker* picker() const { return picker_.get(); }
  const std::optional<measure::PhotoView>& left_view() const { return left_view_; }
  const cv::Mat& photo() const { return photo_; }
  // The range pole's targets located on the mesh (ui/view3d/overlay_targets.h).
  const std::vector<TargetOnModel>& targets() const { return targets_; }
  const DisplayMesh& display_mesh() const { return mesh_; }
  // The drawn surface that overlays are laid on; null without a model.
  const SurfaceDrape* drape() const { return drape_.get(); }
  // Lines already laid on this model's surface (emptied with the model).
  DrapeCache& drape_cache() { return drape_cache_; }
  BlockFaceCache& block_cache() { return block_cache_; }

  // What the next draw() renders on the surface (depth-tested); screens set
  // it each frame before draw(), which then empties it.
  OverlayScene& overlay() { return overlay_; }
  // What the last draw() rendered on the surface.
  const OverlayScene& drawn_overlay() const { return drawn_overlay_; }
  // Rectangles of the panel covered by flat marks drawn this frame over the
  // 3D image (legend, scale bar, north arrow), by name; emptied by draw().
  void add_flat_mark(const std::string& name, ImVec2 min, ImVec2 max) {
    // Antialiased edges reach a pixel or two beyond what was asked.
    flat_marks_[name] = {ImVec2(min.x - 2, min.y - 2), ImVec2(max.x + 2, max.y + 2)};
  }
  const std::map<std::string, std::pair<ImVec2, ImVec2>>& flat_marks() const { return flat_marks_; }

  struct Interaction {
    std::optional<ImVec2> tap;  // a touch that went up where it went down (screen px)
  };
  // Draws the panel of `size` at the cursor and applies this frame's
  // gestures.
  Interaction draw(ImVec2 size, const TouchGesture& gesture);

  // Screen pixel (this frame's panel) of a project point; nothing when it
  // is behind the camera.
  std::optional<ImVec2> to_screen(const Eigen::Vector3d& point) const;
  ScreenRay ray_at(ImVec2 screen) const;
  ImVec2 panel_min() const { return panel_min_; }
  ImVec2 panel_max() const { return panel_max_; }
  // The panel as the area that words drawn on the 3D image belong to.
  TextArea text_area() const { return {panel_min_, panel_max_, "3D image"}; }
  // Triangles of the 3D image drawn in the last frame (fewer while turning).
  int drawn_triangles() const { return renderer_ ? renderer_->drawn_triangles() : 0; }
  // Frames the renderer drew (a still view's frame is not drawn again).
  long frames_drawn() const { return renderer_ ? renderer_->frames_drawn() : 0; }
  OrbitCamera& camera() { return camera_; }
  const OrbitCamera& camera() const { return camera_; }

 private:
  std::unique_ptr<ModelRenderer> renderer_;
  std::shared_ptr<const storage::Model> model_;
  std::shared_ptr<const photogrammetry::SurfaceMesh> surface_;
  std::shared_ptr<const measure::MeshPicker> picker_;
  std::optional<measure::PhotoView> left_view_;
  cv::Mat photo_;
  std::vector<TargetOnModel> targets_;
  DisplayMesh mesh_;
  std::shared_ptr<const SurfaceDrape> drape_;
  DrapeCache drape_cache_;
  BlockFaceCache block_cache_;
  OverlayScene overlay_, drawn_overlay_;
  std::map<std::string, std::pair<ImVec2, ImVec2>> flat_marks_;
  storage::RecordId id_ = 0;
  OrbitCamera camera_;
  ImVec2 panel_min_{0, 0}, panel_max_{0, 0};
};

}  // namespace rockface::ui

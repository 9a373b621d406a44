#include "ui/view3d/model_view.h"

#include <algorithm>
#include <cstdint>

#include <opencv2/imgcodecs.hpp>

#include "storage/project/project_store.h"
#include "ui/widgets/widgets_scroll.h"

namespace rockface::ui {

namespace {
// A touch that moves less than this (pixels at scale 1) between down and
// up is a tap, not a drag: a fingertip wobbles by a few pixels.
constexpr float kTapSlopPx = 12;
}  // namespace

namespace {

// The stored mesh as a lattice on its photograph (`texture`, empty when it
// has none): the pixels from the texture coordinates once here, on the
// worker that opens the model, so that Find traces does not copy the whole
// mesh to add them after the geologist's tap (issue 45).
photogrammetry::SurfaceMesh surface_of(storage::Mesh&& mesh, const cv::Mat& texture) {
  photogrammetry::SurfaceMesh s;
  s.vertices = std::move(mesh.vertices);
  s.triangles.reserve(mesh.faces.size());
  for (const auto& f : mesh.faces) s.triangles.push_back({f[0], f[1], f[2]});
  s.texcoords.reserve(mesh.texcoords.size());
  for (const auto& t : mesh.texcoords) s.texcoords.emplace_back(t[0], t[1]);
  s.colours = std::move(mesh.colours);
  if (!texture.empty()) s.pixels_from_texcoords(texture.cols, texture.rows);
  return s;
}

}  // namespace

PreparedModel prepare_model(const std::filesystem::path& project, storage::RecordId model_id,
                            std::size_t max_triangles) {
  storage::OpenOptions options;
  options.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(project, options);
  PreparedModel out;
  out.id = model_id;
  auto model = std::make_shared<storage::Model>(store.load_model(model_id));
  out.mesh = make_display_mesh(model->mesh, max_triangles);
  out.drape = std::make_shared<SurfaceDrape>(out.mesh);
  if (model->texture_capture_id) {
    const storage::ImageBlob blob =
        store.load_capture_image(*model->texture_capture_id, model->texture_side);
    out.photo_bgr = cv::imdecode(blob.bytes, cv::IMREAD_COLOR);
    const storage::Capture capture = store.load_capture(*model->texture_capture_id);
    // A further pair stored before schema 4 keeps no camera pose: no view.
    if (capture.calibration_id && model->texture_side == "left" && model->camera_to_mesh)
      out.left_view = measure::left_view(
          *model->camera_to_mesh, store.load_calibration(*capture.calibration_id).intrinsics);
  }
  auto surface = std::make_shared<photogrammetry::SurfaceMesh>(
      surface_of(std::move(model->mesh), out.photo_bgr));
  model->mesh = {};
  out.picker = std::make_shared<measure::MeshPicker>(*surface);
  out.targets = locate_targets(*model, out.left_view, *surface, *out.picker);
  out.surface = std::move(surface);
  out.model = std::move(model);
  return out;
}

void ModelView::install(PreparedModel prepared) {
  if (!renderer_) renderer_ = std::make_unique<ModelRenderer>();
  renderer_->upload(prepared.mesh, prepared.photo_bgr);
  id_ = prepared.id;
  model_ = std::move(prepared.model);
  picker_ = std::move(prepared.picker);  // before the surface it points into
  surface_ = std::move(prepared.surface);
  left_view_ = std::move(prepared.left_view);
  photo_ = std::move(prepared.photo_bgr);
  targets_ = std::move(prepared.targets);
  mesh_ = std::move(prepared.mesh);
  drape_ = std::move(prepared.drape);
  drape_cache_.clear();
  block_cache_.clear();
  overlay_ = {};
  drawn_overlay_ = {};
  camera_.frame(mesh_.centre, mesh_.radius, mesh_.mean_normal);
}

void ModelView::clear() {
  picker_.reset();
  surface_.reset();
  left_view_.reset();
  photo_ = cv::Mat();
  targets_.clear();
  model_.reset();
  mesh_ = {};
  drape_.reset();
  drape_cache_.clear();
  block_cache_.clear();
  overlay_ = {};
  drawn_overlay_ = {};
  id_ = 0;
  if (renderer_) renderer_->upload(mesh_, {});
}

ModelView::Interaction ModelView::draw(ImVec2 size, const TouchGesture& gesture) {
  Interaction out;
  flat_marks_.clear();
  size.x = std::max(size.x, 1.0f);
  size.y = std::max(size.y, 1.0f);
  camera_.set_viewport(static_cast<int>(size.x), static_cast<int>(size.y));
  panel_min_ = ImGui::GetCursorScreenPos();
  panel_max_ = ImVec2(panel_min_.x + size.x, panel_min_.y + size.y);
  ImGui::InvisibleButton("##model", size);
  // Issue 27 (touch): a drag on the 3D image turns it (or takes a trace's
  // taps), never scrolls the panel around it.
  last_item_takes_drags();
  const ImGuiIO& io = ImGui::GetIO();
  const float slop = kTapSlopPx;
  bool turning = false;
  if (ImGui::IsItemActive() && io.MouseDragMaxDistanceSqr[0] > slop * slop) {
    camera_.orbit(io.MouseDelta.x, io.MouseDelta.y);
    turning = true;
  }
  // The finger's own place, not ImGui's floored pixel: a tap on a target
  // ringed a pixel wide lands where it was aimed (issue 43's pole taps).
  if (ImGui::IsItemDeactivated() && io.MouseDragMaxDistanceSqr[0] <= slop * slop)
    out.tap = ImVec2(gesture.pointer.x(), gesture.pointer.y());
  const bool over = ImGui::IsMouseHoveringRect(panel_min_, panel_max_, false);
  if (gesture.active || gesture.pinch != 1) {
    if (over || gesture.active) {
      camera_.zoom(gesture.pinch);
      camera_.pan(gesture.pan.x(), gesture.pan.y());
      turning = true;
    }
  }
  if (renderer_ && model_) {
    // While the view moves, the turning copy keeps the frame rate of a
    // software renderer (issue 45); the whole is drawn again when it stops.
    const unsigned texture = renderer_->render(camera_, overlay_, turning);
    // The framebuffer's first row is the bottom one: flip v.
    ImGui::GetWindowDrawList()->AddImage(
        reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)), panel_min_, panel_max_,
        ImVec2(0, 1), ImVec2(1, 0));
  } else {
    ImGui::GetWindowDrawList()->AddRectFilled(panel_min_, panel_max_, IM_COL32(46, 46, 51, 255));
    overlay_ = {};  // nothing to lay it on
  }
  drawn_overlay_ = std::move(overlay_);
  overlay_ = {};
  return out;
}

std::optional<ImVec2> ModelView::to_screen(const Eigen::Vector3d& point) const {
  if (!camera_.in_front(point)) return std::nullopt;
  const Eigen::Vector3d p = camera_.project(point);
  return ImVec2(panel_min_.x + static_cast<float>(p.x()), panel_min_.y + static_cast<float>(p.y()));
}

ScreenRay ModelView::ray_at(ImVec2 screen) const {
  return camera_.ray(screen.x - panel_min_.x, screen.y - panel_min_.y);
}

}  // namespace rockface::ui

#pragma once
// The range pole's targets on the 3D image, marked where the detector found
// them in the left photograph: where the ray of the left camera through each
// detected pixel meets the face. When the mesh is under that pixel, that is
// its hit, the spot of the textured surface that shows the target. A pole
// standing in front of the face is left out of the 3D image by dense
// matching (the mesh has a hole the pole's shape there); then it is where
// the ray meets the face's plane fitted around the hole, and the ring lies
// on the face around the hole. (The registration's own 3D positions of the
// targets sit on the pole in front of the face and are not drawn: a mark
// floating before the rock says nothing about where the scale came from.)
//
// The ring and its four ticks are laid on the drawn surface like a trace
// (ui/view3d/overlay_drape.h), cut where there is no surface, and drawn by the GLES
// renderer with the model's depth; the target's name is a flat label.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/measure/mesh_picker.h"
#include "core/measure/photo_view.h"
#include "core/photogrammetry/surface/surface_mesh.h"
#include "storage/project/project_records.h"
#include "ui/model/overlay_photo_targets.h"

namespace rockface::ui {

class ModelView;

struct TargetOnModel {
  DetectedTarget detected;
  // Where the left camera's ray through the detected pixel meets the face;
  // nothing when it cannot be known (why_not says why).
  std::optional<Eigen::Vector3d> point;
  // True: the stored mesh is under the pixel (the point is its hit). False:
  // the pole stands in front of the face and dense matching left it out of
  // the 3D image (a hole the target's shape), so the point is where the ray
  // meets the plane fitted to the face around that hole.
  bool on_surface = false;
  double plane_rms_m = 0;  // the fitted plane's RMS distance of its points (m), when not on_surface
  int plane_points = 0;
  std::string why_not;
};

// Where the model's detected targets lie on its mesh (worker side: it
// projects the mesh into the left view once); empty when the model was not
// scaled by a range pole.
std::vector<TargetOnModel> locate_targets(const storage::Model& model,
                                          const std::optional<measure::PhotoView>& left,
                                          const photogrammetry::SurfaceMesh& surface,
                                          const measure::MeshPicker& picker);

// The ring's radius (m) around a target on the surface: wider than the
// target's own disc (its diameter in pixels at its distance from the left
// camera), so that it lies on the face around the hole the target leaves,
// and never under 12 px on the screen at `scale`.
double target_ring_radius(const ModelView& view, const TargetOnModel& target, float scale);

// Adds each target's ring and ticks ("target lower ring", "target lower
// tick") to the view's overlay; call before ModelView::draw.
void add_targets_to_overlay(ModelView& view, float scale);
// The targets' names beside their rings (flat labels, recorded as flat
// marks "target lower" ...); call after ModelView::draw, inside its clip.
void draw_target_labels(ModelView& view, float scale);

}  // namespace rockface::ui

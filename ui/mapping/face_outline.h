#pragma once
// The face's outline being marked on the Mapping screen (issue 27): the
// geologist taps the corners of the mapped area on the 3D image, as for a
// trace (a tap with no surface under it is refused), takes the last one
// back, and closes the polygon. Closed, it is measured as `rockface
// measure` measures an area pick: the corners in the left photograph (the
// one the model is textured with), then, on the worker
// (FieldServices::trace_map), split into the flat pieces of the 3D image it
// covers (core/measure/outline_pieces.h), each an area as measure_area
// makes it. The analysis takes the pieces as the visit's mapped face.
#include <cstdint>
#include <string>
#include <vector>

#include <imgui.h>
#include <Eigen/Core>

#include "core/measure/plane_measurement.h"
#include "ui/mapping/trace_marker.h"
#include "ui/view3d/orbit_camera.h"
#include "ui/view3d/overlay_drape.h"
#include "ui/view3d/overlay_scene.h"

namespace rockface::ui {

class FaceOutline {
 public:
  // A corner where the ray meets the surface; false (and `problem()` names
  // the corner) when it meets none.
  bool tap(const measure::Ray& ray, const measure::MeshPicker* picker);
  void undo();
  void clear();

  const std::vector<Eigen::Vector3d>& corners() const { return corners_; }
  const std::string& problem() const { return problem_; }

  // The closed outline's corners in the context's photograph (the pick
  // `rockface measure` takes for an area; the runner measures it). Throws
  // InputError naming the outline and, where it is one corner, the corner:
  // fewer than 3 corners, a corner outside the photograph or with no
  // surface under it seen from there.
  std::vector<Eigen::Vector2d> corner_pixels(const TraceContext& context) const;

 private:
  std::vector<Eigen::Vector3d> corners_;
  std::string problem_;
};

// Drawing an outline on the 3D image (issue 27): its edges are laid on the
// drawn surface as the traces are (ui/view3d/overlay_drape.h), so the renderer
// depth-tests them against the model (a ridge in front hides them) and
// cuts them where they leave the mapped area, never a straight line across
// the screen. Three corners or more close the polygon.

// A straight edge between two corners on patches of the face that meet at a
// bend leaves the surface by up to half its length times sin(bend / 2):
// 0.05 of its length allows bends up to 11 degrees, as a block's footprint
// (ui/view3d/overlay_blocks.cpp); a sharper bend cuts the edge there, which shows
// the geologist that the edge does not follow the rock.
constexpr double kOutlineEdgeSag = 0.05;

// The outline's lines on the surface (one per run), for an OverlayScene.
std::vector<OverlayLine> outline_on_surface(const SurfaceDrape& drape, DrapeCache& cache,
                                            const std::string& what,
                                            const std::vector<Eigen::Vector3d>& corners,
                                            std::uint32_t rgba, float width_px);

// Whether a corner on the surface is the first surface a ray from the eye
// toward it meets (`ray` through the corner's pixel): a corner behind a
// ridge is not, and its dot is not drawn. `tolerance` (m): how far in front
// of the corner the ray may meet the surface and still be the corner's own
// (the ray through the rounded pixel meets a slanting face a little apart).
bool corner_in_sight(const measure::MeshPicker& picker, const ScreenRay& ray,
                     const Eigen::Vector3d& corner, double tolerance);

}  // namespace rockface::ui

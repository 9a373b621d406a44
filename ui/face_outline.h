#pragma once
// The face's outline being marked on the Mapping screen (issue 27): the
// geologist taps the corners of the mapped area on the 3D image, as for a
// trace (a tap with no surface under it is refused), takes the last one
// back, and closes the polygon. Closed, it is measured as `rockface
// measure` measures an area pick: the corners in the left photograph (the
// one the model is textured with), then core/measure's measure_area on the
// worker (FieldServices::trace_map). The analysis takes it as the visit's
// mapped face (the free surface).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/measure/plane_measurement.h"
#include "ui/trace_marker.h"

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

}  // namespace rockface::ui

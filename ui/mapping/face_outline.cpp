#include "ui/mapping/face_outline.h"

#include "core/common/error.h"

namespace rockface::ui {

namespace {

const char kWhat[] = "face outline";

std::string corner_name(std::size_t k) {
  return "corner " + std::to_string(k + 1);
}

}  // namespace

bool FaceOutline::tap(const measure::Ray& ray, const measure::MeshPicker* picker) {
  problem_.clear();
  if (!picker) return false;
  const auto hit = picker->pick(ray);
  if (!hit) {
    problem_ = corner_name(corners_.size()) + ": no surface under the tap; tap on the face";
    return false;
  }
  corners_.push_back(hit->point);
  return true;
}

void FaceOutline::undo() {
  problem_.clear();
  if (!corners_.empty()) corners_.pop_back();
}

void FaceOutline::clear() {
  corners_.clear();
  problem_.clear();
}

std::vector<Eigen::Vector2d> FaceOutline::corner_pixels(const TraceContext& context) const {
  if (corners_.size() < 3)
    throw InputError(kWhat,
                     "needs 3 or more corners to close, has " + std::to_string(corners_.size()));
  if (!context.picker || !context.photo_view)
    throw InputError(kWhat, "no 3D image with its photograph's camera to measure it on");
  const std::vector<Eigen::Vector2d> pixels =
      measure::project_to_view(*context.photo_view, corners_);
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    const std::string where = std::string(kWhat) + " " + corner_name(k);
    if (!measure::pixel_in_image(*context.photo_view, pixels[k]))
      throw InputError(where, "lies outside the photograph the 3D image is made from");
    // The area is measured from the photograph (measure_area), which keeps
    // only the corners it sees surface under; an outline needs every one.
    if (!context.picker->pick(*context.photo_view, pixels[k], where))
      throw InputError(where,
                       "has no surface under it seen from the photograph (hidden behind a "
                       "ridge?); tap it where the face is seen");
  }
  return pixels;
}

std::vector<OverlayLine> outline_on_surface(const SurfaceDrape& drape, DrapeCache& cache,
                                            const std::string& what,
                                            const std::vector<Eigen::Vector3d>& corners,
                                            std::uint32_t rgba, float width_px) {
  std::vector<OverlayLine> out;
  if (corners.size() < 2) return out;
  for (const auto& run : cache.runs(drape, corners, corners.size() >= 3, kOutlineEdgeSag))
    out.push_back({what, run, rgba, width_px, false});
  return out;
}

bool corner_in_sight(const measure::MeshPicker& picker, const ScreenRay& ray,
                     const Eigen::Vector3d& corner, double tolerance) {
  const auto hit = picker.pick({ray.origin, ray.direction});
  if (!hit) return false;
  // Along the ray: the surface met first lies no nearer than the corner.
  const double to_corner = (corner - ray.origin).dot(ray.direction.normalized());
  const double to_hit = (hit->point - ray.origin).dot(ray.direction.normalized());
  return to_hit >= to_corner - tolerance;
}

}  // namespace rockface::ui

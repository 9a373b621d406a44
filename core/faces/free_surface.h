#pragma once
// The free surface as planar polygon patches (a tunnel face with its crown
// and walls, the benches and faces of a slope). Each patch is listed
// counter-clockwise seen from the open side (from the air), so its
// right-handed normal points out of the rock; neighbouring patches then run
// along their shared edge in opposite directions. Coordinates are
// datum-relative.
//
// Each patch carries a 2D frame in its plane (e1, e2, outward right-handed),
// so that counter-clockwise in 2D is counter-clockwise seen from outside.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/plane.h"

namespace rockface::faces {

struct PatchInput {
  std::string id;
  std::vector<Eigen::Vector3d> polygon;  // datum-relative
};

struct SurfacePatch {
  std::string id;                        // the input's id; "ID.k" for piece k of a non-convex input
  int input = -1;                        // index of the input patch (surface.patches[input])
  std::vector<Eigen::Vector3d> polygon;  // projected onto the plane
  Eigen::Vector3d outward = Eigen::Vector3d::UnitZ();  // unit, out of the rock
  geometry::Plane plane;                               // upward normal convention
  geometry::HalfSpace rock_side = geometry::HalfSpace::Lower;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), e1 = Eigen::Vector3d::UnitX(),
                  e2 = Eigen::Vector3d::UnitY();
  std::vector<Eigen::Vector2d> polygon2d;

  Eigen::Vector2d to2d(const Eigen::Vector3d& x) const {
    const Eigen::Vector3d d = x - origin;
    return {d.dot(e1), d.dot(e2)};
  }
  Eigen::Vector3d to3d(const Eigen::Vector2d& p) const { return origin + p.x() * e1 + p.y() * e2; }
  // 2D direction of a 3D vector lying in the plane.
  Eigen::Vector2d dir2d(const Eigen::Vector3d& d) const { return {d.dot(e1), d.dot(e2)}; }
  Eigen::Vector3d dir3d(const Eigen::Vector2d& d) const { return d.x() * e1 + d.y() * e2; }
  // Signed distance along the outward normal (> 0 in the air).
  double height(const Eigen::Vector3d& x) const { return outward.dot(x - origin); }
  // Whether a point of the plane lies inside the polygon or within `slack` of it.
  bool contains(const Eigen::Vector2d& p, double slack) const;
};

class FreeSurface {
 public:
  FreeSurface() = default;
  // Fits each patch's plane and checks it: planar within `tolerance` (m),
  // at least three distinct corners, counter-clockwise seen from the open
  // side as given, an outline that does not cross itself. A non-convex patch
  // is split into convex pieces on its plane (ids "ID.1", "ID.2", ...).
  // Throws rockface::InputError naming the patch
  // ("surface.patches[2] (S3)") and what is wrong.
  static FreeSurface build(const std::vector<PatchInput>& patches, double tolerance);

  const std::vector<SurfacePatch>& patches() const { return patches_; }
  // Where a patch is named in messages: "surface.patches[2] (S3)".
  std::string where(int patch) const;
  // Whether the rock behind patches a and b, which share an edge, is the
  // union of their rock half-spaces (a re-entrant edge: the toe of a slope,
  // the edge between a tunnel's crown and wall) rather than the intersection
  // (a salient edge: the crest of a bench).
  bool rock_is_union(int a, int b, double tolerance) const;

 private:
  std::vector<SurfacePatch> patches_;
};

}  // namespace rockface::faces

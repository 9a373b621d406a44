#include "core/faces/free_surface.h"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/common/error.h"
#include "core/faces/convex_partition.h"
#include "core/faces/tolerances.h"
#include "core/geometry/cross2.h"

namespace rockface::faces {

using geometry::cross2;

namespace {

// Whether closed segments ab and cd share a point.
bool segments_meet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
  const double d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a);
  const double d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  auto on = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& x,
               double side) {
    return side == 0 && x.x() >= std::min(p.x(), q.x()) && x.x() <= std::max(p.x(), q.x()) &&
           x.y() >= std::min(p.y(), q.y()) && x.y() <= std::max(p.y(), q.y());
  };
  return on(a, b, c, d1) || on(a, b, d, d2) || on(c, d, a, d3) || on(c, d, b, d4);
}

}  // namespace

bool SurfacePatch::contains(const Eigen::Vector2d& p, double slack) const {
  // Convex, counter-clockwise: inside means left of (or within slack of) every edge.
  const size_t n = polygon2d.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = polygon2d[i], b = polygon2d[(i + 1) % n];
    const Eigen::Vector2d e = b - a;
    const double len = e.norm();
    if (len == 0) continue;
    if (cross2(e, p - a) / len < -slack) return false;
  }
  return true;
}

std::string FreeSurface::where(int patch) const {
  return "surface.patches[" + std::to_string(patches_[patch].input) + "] (" + patches_[patch].id +
         ")";
}

FreeSurface FreeSurface::build(const std::vector<PatchInput>& inputs, double tolerance) {
  FreeSurface surface;
  for (size_t k = 0; k < inputs.size(); ++k) {
    const PatchInput& in = inputs[k];
    const std::string where = "surface.patches[" + std::to_string(k) + "] (" + in.id + ")";
    // Drop repeated corners (a closing point equal to the first, doubled clicks).
    std::vector<Eigen::Vector3d> pts;
    for (const auto& p : in.polygon)
      if (pts.empty() || (p - pts.back()).norm() > tolerance) pts.push_back(p);
    while (pts.size() > 1 && (pts.front() - pts.back()).norm() <= tolerance) pts.pop_back();
    if (pts.size() < 3) throw InputError(where, "needs at least 3 distinct corners");

    // Newell's normal keeps the sense of the listed order; the least-squares
    // plane gives the direction.
    Eigen::Vector3d newell = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < pts.size(); ++i) {
      const Eigen::Vector3d& a = pts[i];
      const Eigen::Vector3d& b = pts[(i + 1) % pts.size()];
      newell += a.cross(b);
      centroid += a;
    }
    centroid /= static_cast<double>(pts.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : pts) cov += (p - centroid) * (p - centroid).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    Eigen::Vector3d normal = eig.eigenvectors().col(0);
    if (eig.eigenvalues()(1) <= 0 || newell.norm() == 0)
      throw InputError(where, "corners are collinear: the patch has no plane");
    if (normal.dot(newell) < 0) normal = -normal;
    for (size_t i = 0; i < pts.size(); ++i) {
      const double d = normal.dot(pts[i] - centroid);
      if (std::abs(d) > tolerance)
        throw InputError(where, "not planar: corner " + std::to_string(i) + " is " +
                                    std::to_string(std::abs(d)) +
                                    " m off the patch plane (snap tolerance " +
                                    std::to_string(tolerance) + " m)");
    }

    SurfacePatch patch;
    patch.id = in.id;
    patch.input = static_cast<int>(k);
    patch.outward = normal;
    patch.origin = centroid;
    // e1 along the longest edge keeps the frame well defined for slivers.
    size_t longest = 0;
    for (size_t i = 0; i < pts.size(); ++i)
      if ((pts[(i + 1) % pts.size()] - pts[i]).norm() >
          (pts[(longest + 1) % pts.size()] - pts[longest]).norm())
        longest = i;
    Eigen::Vector3d e1 = pts[(longest + 1) % pts.size()] - pts[longest];
    e1 -= normal * normal.dot(e1);
    patch.e1 = e1.normalized();
    patch.e2 = normal.cross(patch.e1);
    for (const auto& p : pts) {
      patch.polygon.push_back(p - normal * normal.dot(p - centroid));
      patch.polygon2d.push_back(patch.to2d(p));
    }
    // A simple outline: no two edges that are not neighbours meet.
    const size_t n = patch.polygon2d.size();
    for (size_t i = 0; i < n; ++i)
      for (size_t j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;  // neighbours across the closing corner
        if (segments_meet(patch.polygon2d[i], patch.polygon2d[(i + 1) % n], patch.polygon2d[j],
                          patch.polygon2d[(j + 1) % n]))
          throw InputError(where, "its outline crosses itself (edges " + std::to_string(i) +
                                      " and " + std::to_string(j) +
                                      "): list the corners in order round it");
      }
    const std::vector<std::vector<int>> pieces =
        convex_partition(patch.polygon2d, kConvexCornerSine);
    if (pieces.empty())
      throw InputError(where, "its outline crosses itself: list the corners in order round it");
    // Upward-normal plane and the rock's half-space code.
    Eigen::Vector3d up = normal;
    if (up.z() < 0 || (up.z() == 0 && (up.y() < 0 || (up.y() == 0 && up.x() < 0)))) up = -up;
    patch.plane.normal = up;
    patch.plane.offset = up.dot(centroid);
    patch.rock_side = up.dot(normal) > 0 ? geometry::HalfSpace::Lower : geometry::HalfSpace::Upper;
    if (pieces.size() == 1) {
      surface.patches_.push_back(std::move(patch));
      continue;
    }
    // A non-convex patch becomes convex patches on its plane, named ID.1,
    // ID.2, ...: the edges between them are flat, so loops cross them freely.
    for (size_t k = 0; k < pieces.size(); ++k) {
      SurfacePatch piece = patch;
      piece.id = in.id + "." + std::to_string(k + 1);
      piece.polygon.clear();
      piece.polygon2d.clear();
      for (int i : pieces[k]) {
        piece.polygon.push_back(patch.polygon[i]);
        piece.polygon2d.push_back(patch.polygon2d[i]);
      }
      surface.patches_.push_back(std::move(piece));
    }
  }
  return surface;
}

bool FreeSurface::rock_is_union(int a, int b, double tolerance) const {
  // Salient edge: b lies on the rock side of a's plane (below a crest).
  // Re-entrant edge: b rises into a's air side (above a toe).
  double highest = -1e300;
  for (const auto& p : patches_[b].polygon) highest = std::max(highest, patches_[a].height(p));
  return highest > tolerance;
}

}  // namespace rockface::faces

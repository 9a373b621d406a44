#include "core/mechanics/dynamics/joint_contacts.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/mechanics/contact_points.h"
#include "core/mechanics/dynamics/block_diameter.h"
#include "core/mechanics/dynamics/tolerances.h"

namespace rockface::mechanics {

namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a(0) * b(1) - a(1) * b(0);
}

double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

bool near_any(const std::vector<JointContact>& found, size_t from, const Eigen::Vector3d& x,
              double tol) {
  for (size_t k = from; k < found.size(); ++k)
    if ((found[k].point - x).norm() <= tol) return true;
  return false;
}

}  // namespace

bool inside_polygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p,
                    double tol) {
  const size_t n = polygon.size();
  bool in = false;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if (segment_distance(p, a, b) <= tol) return true;
    if ((a(1) > p(1)) != (b(1) > p(1)) &&
        p(0) < (b(0) - a(0)) * (p(1) - a(1)) / (b(1) - a(1)) + a(0))
      in = !in;
  }
  return in;
}

JointContacts::JointContacts(const blocks::Polyhedron& block, const Eigen::Vector3d& centroid,
                             const std::vector<double>& friction_deg)
    : centroid_(centroid), length_(std::max(block_diameter(block), 1e-300)) {
  for (const auto& v : block.vertices()) arms_.push_back(v - centroid_);
  for (const blocks::BlockPlane& bp : block.planes()) {
    plane_inward_.push_back(bp.inward_normal());
    plane_offset_.push_back(bp.plane.offset * (bp.inward_normal().dot(bp.plane.normal)));
  }
  for (int p = 0; p < static_cast<int>(block.planes().size()); ++p) {
    const blocks::BlockPlane& bp = block.planes()[p];
    if (bp.kind != blocks::PlaneKind::Joint) continue;
    const std::vector<int> faces = block.faces_on_plane(p);
    if (faces.empty()) continue;
    JointSurface s;
    s.plane = p;
    s.name = bp.name;
    s.normal = bp.inward_normal();
    s.origin = block.vertices()[block.faces()[faces[0]].loop[0]];
    joint_frame(s.normal, s.e1, s.e2);
    const double phi = p < static_cast<int>(friction_deg.size()) ? friction_deg[p] : 0.0;
    s.friction = std::tan(phi * M_PI / 180.0);
    for (int f : faces) {
      const std::vector<int>& loop = block.faces()[f].loop;
      std::vector<Eigen::Vector2d> poly;
      std::vector<std::string> across;
      for (size_t k = 0; k < loop.size(); ++k) {
        const Eigen::Vector3d d = block.vertices()[loop[k]] - s.origin;
        poly.emplace_back(d.dot(s.e1), d.dot(s.e2));
        const int he = block.half_edge_between(loop[k], loop[(k + 1) % loop.size()]);
        std::string name = "?";
        if (he >= 0) {
          const int twin = block.half_edges()[he].twin;
          if (twin >= 0)
            name = block.planes()[block.faces()[block.half_edges()[twin].face].plane].name;
        }
        across.push_back(name);
      }
      s.polygons.push_back(std::move(poly));
      s.loops.push_back(loop);
      s.edge_planes.push_back(std::move(across));
    }
    surfaces_.push_back(std::move(s));
  }
}

bool JointContacts::entered_through(const Eigen::Vector3d& y, int plane, double depth) const {
  for (size_t p = 0; p < plane_inward_.size(); ++p) {
    if (static_cast<int>(p) == plane) continue;
    const double d = plane_inward_[p].dot(y) - plane_offset_[p];
    if (d < depth) return false;  // outside the block, or nearer another face
  }
  return true;
}

std::vector<JointContact> JointContacts::contacts(const BlockPose& pose, double gap_limit) const {
  std::vector<JointContact> out;
  const double tol = kSupportEdgeRel * length_;
  const double deepest = kMaxPenetrationRel * length_;
  // Penetration within the closed band is drift, whatever face is nearest
  // (a rock corner on the block's side face lies on both).
  const double shallow = kContactGapRel * length_;
  const Eigen::Matrix3d r = pose.q.toRotationMatrix();
  for (int si = 0; si < static_cast<int>(surfaces_.size()); ++si) {
    const JointSurface& s = surfaces_[si];
    const size_t first = out.size();
    auto to_plane = [&](const Eigen::Vector3d& x) {
      const Eigen::Vector3d d = x - s.origin;
      return Eigen::Vector2d(d.dot(s.e1), d.dot(s.e2));
    };
    auto on_surface = [&](const Eigen::Vector2d& p) {
      for (const auto& poly : s.polygons)
        if (inside_polygon(poly, p, tol)) return true;
      return false;
    };
    // A point of space in the block's frame at rest, and its gap below the
    // block's face (the face at rest is the plane itself).
    auto body = [&](const Eigen::Vector3d& x) {
      return Eigen::Vector3d(centroid_ + r.transpose() * (x - centroid_ - pose.u));
    };
    const Eigen::Vector3d face_normal = r * s.normal;
    // 1. The block's corners over the joint surface.
    std::set<int> seen;
    std::vector<std::vector<Eigen::Vector2d>> moved(s.loops.size());
    for (size_t li = 0; li < s.loops.size(); ++li)
      for (int v : s.loops[li]) {
        const Eigen::Vector3d x = vertex(pose, v);
        moved[li].push_back(to_plane(x));
        if (!seen.insert(v).second) continue;
        const double gap = s.normal.dot(x - s.origin);
        if (gap > gap_limit || gap < -deepest || !on_surface(moved[li].back())) continue;
        JointContact c;
        c.surface = si;
        c.kind = ContactKind::BlockCorner;
        c.point = x;
        c.normal = s.normal;
        c.gap = gap;
        c.vertex = v;
        out.push_back(c);
      }
    // 2. The surface's corners under the block's face.
    int corner = 0;
    for (const auto& poly : s.polygons)
      for (const Eigen::Vector2d& p : poly) {
        const int index = corner++;
        const Eigen::Vector3d x = s.origin + p(0) * s.e1 + p(1) * s.e2;
        const Eigen::Vector3d y = body(x);
        const double gap = -s.normal.dot(y - s.origin);
        if (gap > gap_limit || near_any(out, first, x, tol)) continue;
        if (gap < -shallow && (gap < -deepest || !entered_through(y, s.plane, -gap))) continue;
        bool under = false;
        for (const auto& face : s.polygons) under = under || inside_polygon(face, to_plane(y), tol);
        if (!under) continue;
        JointContact c;
        c.surface = si;
        c.kind = ContactKind::RockCorner;
        c.point = x;
        c.normal = face_normal;
        c.gap = gap;
        c.vertex = index;
        out.push_back(c);
      }
    // 3. Crossings of the face's edges (projected on the plane) with the
    // surface's edges: where the overlap's outline turns between the two.
    for (const auto& face : moved)
      for (size_t i = 0; i < face.size(); ++i) {
        const Eigen::Vector2d a = face[i], ab = face[(i + 1) % face.size()] - a;
        for (const auto& poly : s.polygons)
          for (size_t k = 0; k < poly.size(); ++k) {
            const Eigen::Vector2d c = poly[k], cd = poly[(k + 1) % poly.size()] - c;
            const double den = cross2(ab, cd);
            if (std::abs(den) <= 1e-12 * ab.norm() * cd.norm()) continue;  // parallel
            const double t = cross2(c - a, cd) / den, u = cross2(c - a, ab) / den;
            if (t <= 0 || t >= 1 || u <= 0 || u >= 1) continue;
            const Eigen::Vector2d p = c + u * cd;
            const Eigen::Vector3d x = s.origin + p(0) * s.e1 + p(1) * s.e2;
            const Eigen::Vector3d y = body(x);
            const double gap = -s.normal.dot(y - s.origin);
            if (gap > gap_limit || near_any(out, first, x, tol)) continue;
            if (gap < -shallow && (gap < -deepest || !entered_through(y, s.plane, -gap))) continue;
            JointContact jc;
            jc.surface = si;
            jc.kind = ContactKind::EdgeCrossing;
            jc.point = x;
            jc.normal = face_normal;
            jc.gap = gap;
            out.push_back(jc);
          }
      }
  }
  return out;
}

}  // namespace rockface::mechanics

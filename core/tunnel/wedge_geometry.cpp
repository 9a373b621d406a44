#include "core/tunnel/wedge_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

#include "core/blocks/construction.h"
#include "core/common/units.h"
#include "core/geometry/cross2.h"
#include "core/tunnel/tolerances.h"

namespace rockface::tunnel {

using geometry::cross2;

namespace {

// "E3": a plane's name from a letter and a number (built in steps: GCC 12
// warns falsely on "E" + std::to_string(...) under -O3).
std::string plane_name(char letter, std::size_t number) {
  std::string s(1, letter);
  s += std::to_string(number);
  return s;
}

Eigen::Vector3d to3(const TunnelFrame& f, const Eigen::Vector2d& uv) {
  return uv.x() * f.right + uv.y() * f.up;
}

// A half-space given by its inward normal and a point of its plane, in the
// upward-normal convention of geometry::Plane.
blocks::HalfSpaceInput halfspace(int index, std::string name, blocks::PlaneKind kind,
                                 const Eigen::Vector3d& inward, const Eigen::Vector3d& point) {
  blocks::HalfSpaceInput h;
  h.index = index;
  h.name = std::move(name);
  h.kind = kind;
  Eigen::Vector3d n = inward.normalized();
  h.side = geometry::HalfSpace::Upper;
  if (n.z() < 0) {
    n = -n;
    h.side = geometry::HalfSpace::Lower;
  }
  h.plane.normal = n;
  h.plane.offset = n.dot(point);
  return h;
}

// Faces of several convex pieces joined into one solid: shared vertices
// merged, faces on the planes between pieces dropped, the pieces' faces on
// one plane joined into one loop where they share edges.
struct PieceFace {
  int plane_key = 0;
  blocks::FaceInput input;
};

// apex: the wedge's apex, where every piece's joints meet (exact: it is
// where the pieces were built from); apex_snap: the distance within which a
// piece's corner is that apex.
blocks::Polyhedron join_pieces(const std::string& id, const Eigen::Vector3d& datum,
                               const std::vector<blocks::Polyhedron>& pieces, double size,
                               const Eigen::Vector3d& apex, double apex_snap) {
  // Vertex 0 is the apex. Each piece finds it again from its own planes;
  // where two sets are nearly parallel those planes meet at a grazing
  // angle and the pieces' apexes scatter by more than the merge distance
  // (1.7e-8 m on a 16 m wedge with sets 0.02 deg apart): the joints' faces
  // did not join and the wedge "could not be built" (issue 40).
  std::vector<Eigen::Vector3d> vertices{apex};
  const double merge = kWedgeVertexMergeRel * size;
  auto vertex_of = [&](const Eigen::Vector3d& x) {
    if ((x - apex).norm() <= apex_snap) return 0;
    for (std::size_t i = 0; i < vertices.size(); ++i)
      if ((vertices[i] - x).norm() <= merge) return static_cast<int>(i);
    vertices.push_back(x);
    return static_cast<int>(vertices.size()) - 1;
  };
  std::map<int, std::vector<PieceFace>> by_plane;
  for (const auto& piece : pieces)
    for (const auto& f : piece.faces()) {
      const blocks::BlockPlane& bp = piece.planes()[f.plane];
      if (bp.index <= -2) continue;  // a plane between pieces (or a touching end one)
      PieceFace pf;
      pf.plane_key = bp.index;
      pf.input.index = bp.index;
      pf.input.name = bp.name;
      pf.input.kind = bp.kind;
      pf.input.reference_normal = bp.plane.normal;
      for (int v : f.loop) {
        const int g = vertex_of(piece.vertices()[v]);
        if (pf.input.loop.empty() || pf.input.loop.back() != g) pf.input.loop.push_back(g);
      }
      while (pf.input.loop.size() > 1 && pf.input.loop.front() == pf.input.loop.back())
        pf.input.loop.pop_back();
      if (pf.input.loop.size() >= 3) by_plane[bp.index].push_back(std::move(pf));
    }
  std::vector<blocks::FaceInput> faces;
  for (auto& [key, group] : by_plane) {
    (void)key;
    if (group.size() == 1) {
      faces.push_back(group.front().input);
      continue;
    }
    // Directed edges of all loops; an edge met in both senses is inside.
    std::vector<std::pair<int, int>> edges;
    for (const auto& pf : group)
      for (std::size_t i = 0; i < pf.input.loop.size(); ++i)
        edges.emplace_back(pf.input.loop[i], pf.input.loop[(i + 1) % pf.input.loop.size()]);
    std::vector<std::pair<int, int>> outer;
    for (const auto& e : edges)
      if (std::find(edges.begin(), edges.end(), std::make_pair(e.second, e.first)) == edges.end())
        outer.push_back(e);
    std::map<int, int> next;
    bool simple = !outer.empty();
    for (const auto& e : outer)
      if (!next.emplace(e.first, e.second).second) simple = false;
    std::vector<int> loop;
    if (simple) {
      int v = outer.front().first;
      for (std::size_t n = 0; n <= outer.size(); ++n) {
        loop.push_back(v);
        auto it = next.find(v);
        if (it == next.end()) {
          simple = false;
          break;
        }
        v = it->second;
        if (v == outer.front().first) break;
      }
      simple = simple && loop.size() == outer.size();
    }
    if (!simple) {
      for (const auto& pf : group) faces.push_back(pf.input);
      continue;
    }
    blocks::FaceInput merged = group.front().input;
    merged.loop = loop;
    faces.push_back(merged);
  }
  // A vertex left on two faces only lies inside an edge (where a pyramid
  // edge crossed a plane between pieces): it is dropped from both loops.
  std::vector<int> uses(vertices.size(), 0);
  for (const auto& f : faces)
    for (int v : f.loop) ++uses[v];
  for (auto& f : faces)
    f.loop.erase(std::remove_if(f.loop.begin(), f.loop.end(), [&](int v) { return uses[v] <= 2; }),
                 f.loop.end());
  std::vector<int> remap(vertices.size(), -1);
  std::vector<Eigen::Vector3d> kept;
  for (auto& f : faces)
    for (int& v : f.loop) {
      if (remap[v] < 0) {
        remap[v] = static_cast<int>(kept.size());
        kept.push_back(vertices[v]);
      }
      v = remap[v];
    }
  return blocks::build_block_from_faces(id, std::move(kept), faces, datum);
}

}  // namespace

PyramidSector pyramid_sector(const std::vector<Eigen::Vector3d>& edges, const TunnelFrame& frame) {
  PyramidSector s;
  s.span = kPi;
  std::vector<double> angles;
  for (const auto& e : edges) {
    const Eigen::Vector2d p(e.dot(frame.right), e.dot(frame.up));
    if (p.norm() < kWedgeAlongAxisSine * e.norm()) return s;  // runs along the axis
    angles.push_back(std::atan2(p.y(), p.x()));
  }
  if (angles.size() < 2) return s;
  std::sort(angles.begin(), angles.end());
  double gap = -1;
  std::size_t after = 0;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double next = i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * kPi;
    if (next - angles[i] > gap) {
      gap = next - angles[i];
      after = i;
    }
  }
  s.span = 2 * kPi - gap;
  const double start = angles[(after + 1) % angles.size()], end = angles[after];
  s.d1 = {std::cos(start), std::sin(start)};
  s.d2 = {std::cos(end), std::sin(end)};
  s.margin = (kPi - s.span) / 2;
  if (std::abs(s.margin) <= kWedgeHalfPlaneRad) s.margin = 0;  // a half-plane but for rounding
  s.pointed = s.margin > 0;
  return s;
}

Eigen::Vector2d largest_apex(const SectionPolygon& section, const PyramidSector& sector) {
  // Inward normals of the sector's two edges; each edge's line supports the
  // section from outside.
  const Eigen::Vector2d n1(-sector.d1.y(), sector.d1.x()), n2(sector.d2.y(), -sector.d2.x());
  double c1 = std::numeric_limits<double>::infinity(), c2 = c1;
  for (const auto& v : section.vertices) {
    c1 = std::min(c1, n1.dot(v.p));
    c2 = std::min(c2, n2.dot(v.p));
  }
  Eigen::Matrix2d m;
  m << n1.x(), n1.y(), n2.x(), n2.y();
  return m.inverse() * Eigen::Vector2d(c1, c2);
}

std::vector<BasePiece> visible_base(const SectionPolygon& section, const PyramidSector& sector,
                                    const Eigen::Vector2d& q) {
  const Eigen::Vector2d n1(-sector.d1.y(), sector.d1.x()), n2(sector.d2.y(), -sector.d2.x());
  double size = 0;
  for (const auto& v : section.vertices) size = std::max(size, (v.p - q).norm());
  std::vector<std::pair<double, BasePiece>> pieces;
  for (std::size_t i = 0; i < section.size(); ++i) {
    const Eigen::Vector2d a = section.at(i), b = section.at(i + 1);
    if (section.outward_normal(i).dot(q - a) <= 0) continue;  // faces away from the apex
    double t0 = 0, t1 = 1;
    for (const Eigen::Vector2d& n : {n1, n2}) {
      // n . (a + t (b - a) - q) >= 0
      const double f0 = n.dot(a - q), df = n.dot(b - a);
      if (std::abs(df) < 1e-300) {
        if (f0 < 0) t1 = -1;
        continue;
      }
      const double t = -f0 / df;
      if (df > 0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
    if (!(t1 > t0) || (t1 - t0) * (b - a).norm() <= kWedgeVertexMergeRel * size) continue;
    BasePiece p{a + t0 * (b - a), a + t1 * (b - a), i};
    // A piece seen edge-on from the apex (its line through the apex) spans
    // no angle: it bounds nothing.
    const double turn = cross2(p.a - q, p.b - q);
    if (std::abs(turn) <= kWedgeVertexMergeRel * (p.a - q).norm() * (p.b - q).norm()) continue;
    if (turn < 0) std::swap(p.a, p.b);  // a on the d1 side, b on the d2 side
    const Eigen::Vector2d mid = 0.5 * (p.a + p.b) - q;
    pieces.emplace_back(std::atan2(cross2(sector.d1, mid), sector.d1.dot(mid)), p);
  }
  std::sort(pieces.begin(), pieces.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<BasePiece> out;
  for (auto& [angle, p] : pieces) out.push_back(p);
  return out;
}

blocks::Polyhedron perimeter_wedge_block(const std::string& id, const TunnelFrame& frame,
                                         const Eigen::Vector3d& datum,
                                         const std::vector<WedgePlane>& joints,
                                         const SectionPolygon& section,
                                         const std::vector<BasePiece>& base,
                                         const Eigen::Vector2d& q, double w, int first_free_index) {
  const Eigen::Vector3d apex = frame.origin + to3(frame, q) + w * frame.along;
  double size = 0;
  for (const auto& v : section.vertices) size = std::max(size, (v.p - q).norm());
  std::vector<blocks::Polyhedron> pieces;
  for (std::size_t k = 0; k < base.size(); ++k) {
    const BasePiece& p = base[k];
    std::vector<blocks::HalfSpaceInput> hs;
    for (const auto& j : joints)
      hs.push_back(halfspace(j.index, j.id, blocks::PlaneKind::Joint, j.inward(), apex));
    const Eigen::Vector2d nu = section.outward_normal(p.edge);
    hs.push_back(halfspace(first_free_index + static_cast<int>(p.edge), plane_name('E', p.edge + 1),
                           blocks::PlaneKind::FreeFace, to3(frame, nu),
                           frame.origin + to3(frame, p.a)));
    // The planes through the apex and the axis at the piece's two ends.
    // The wedge's own two ends (the sector's edges) are bounded by the
    // joints already: a plane there adds nothing, and where a joint
    // contains the axis it is that joint's plane again, which the
    // construction met as two planes 1e-9 deg apart (issue 40).
    for (int end = 0; end < 2; ++end) {
      if ((k == 0 && end == 0) || (k + 1 == base.size() && end == 1)) continue;
      const Eigen::Vector2d here = (end == 0 ? p.a : p.b) - q;
      const Eigen::Vector2d there = (end == 0 ? p.b : p.a) - q;
      Eigen::Vector2d r(-here.y(), here.x());
      if (r.dot(there) < 0) r = -r;
      const int radial = static_cast<int>(k) + end;  // chain point index
      hs.push_back(halfspace(-2 - radial, plane_name('R', static_cast<std::size_t>(radial)),
                             blocks::PlaneKind::Joint, to3(frame, r), apex));
    }
    blocks::ConvexConstruction c =
        blocks::build_convex_block(id + ".piece" + std::to_string(k), hs, datum);
    if (c.outcome != blocks::ConvexOutcome::Bounded)
      throw std::runtime_error("wedge " + id + ": piece over edge E" + std::to_string(p.edge + 1) +
                               " is not a bounded solid");
    pieces.push_back(std::move(*c.polyhedron));
  }
  if (pieces.empty()) throw std::runtime_error("wedge " + id + ": the apex sees no excavation");
  // The apex's corners agree to far better than kWedgeApexSnapRel; the
  // wedge's other corners lie on the excavation, at least the apex's
  // distance from it away (a quarter of it is kept clear).
  const double apex_snap = std::min(kWedgeApexSnapRel * size, 0.25 * section.distance(q));
  return join_pieces(id, datum, pieces, size, apex, apex_snap);
}

std::vector<Eigen::Vector2d> face_unit_triangle(const std::vector<Eigen::Vector3d>& edges,
                                                const TunnelFrame& frame) {
  std::vector<Eigen::Vector2d> t;
  for (const auto& e : edges) {
    const double k = -e.dot(frame.along);
    t.emplace_back(e.dot(frame.right) / k, e.dot(frame.up) / k);
  }
  return t;
}

namespace {

// Sutherland-Hodgman: the part of a convex polygon with n . x <= c.
std::vector<Eigen::Vector2d> clip(const std::vector<Eigen::Vector2d>& poly,
                                  const Eigen::Vector2d& n, double c) {
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& a = poly[i];
    const Eigen::Vector2d& b = poly[(i + 1) % poly.size()];
    const double fa = n.dot(a) - c, fb = n.dot(b) - c;
    if (fa <= 0) out.push_back(a);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) out.push_back(a + fa / (fa - fb) * (b - a));
  }
  return out;
}

double area(const std::vector<Eigen::Vector2d>& poly) {
  double a = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) a += cross2(poly[i], poly[(i + 1) % poly.size()]);
  return 0.5 * a;
}

// The apex positions t with t + s T_i inside the section for every i.
std::vector<Eigen::Vector2d> feasible_offsets(const SectionPolygon& section,
                                              const std::vector<Eigen::Vector2d>& tri, double s) {
  std::vector<Eigen::Vector2d> region;
  for (const auto& v : section.vertices) region.push_back(v.p - s * tri[0]);
  for (std::size_t i = 1; i < tri.size() && !region.empty(); ++i)
    for (std::size_t e = 0; e < section.size() && !region.empty(); ++e) {
      const Eigen::Vector2d n = section.outward_normal(e);
      region = clip(region, n, n.dot(section.at(e) - s * tri[i]));
    }
  return region;
}

}  // namespace

FaceFit largest_face_triangle(const SectionPolygon& section,
                              const std::vector<Eigen::Vector2d>& tri) {
  double diameter = 0, side = 0;
  for (const auto& a : section.vertices)
    for (const auto& b : section.vertices) diameter = std::max(diameter, (a.p - b.p).norm());
  for (const auto& a : tri)
    for (const auto& b : tri) side = std::max(side, (a - b).norm());
  FaceFit fit;
  if (!(side > 0)) return fit;
  double lo = 0, hi = 1.01 * diameter / side;
  while (hi - lo > kWedgeScaleRel * hi) {
    const double mid = 0.5 * (lo + hi);
    const auto region = feasible_offsets(section, tri, mid);
    (region.size() >= 3 && area(region) > 0 ? lo : hi) = mid;
  }
  const auto region = feasible_offsets(section, tri, lo);
  fit.scale = lo;
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : region) c += p;
  fit.offset = region.empty() ? c : Eigen::Vector2d(c / static_cast<double>(region.size()));
  return fit;
}

blocks::Polyhedron face_wedge_block(const std::string& id, const TunnelFrame& frame,
                                    const Eigen::Vector3d& datum,
                                    const std::vector<WedgePlane>& joints, const FaceFit& fit,
                                    int face_index) {
  const Eigen::Vector3d apex = frame.origin + to3(frame, fit.offset) + fit.scale * frame.along;
  std::vector<blocks::HalfSpaceInput> hs;
  for (const auto& j : joints)
    hs.push_back(halfspace(j.index, j.id, blocks::PlaneKind::Joint, j.inward(), apex));
  hs.push_back(
      halfspace(face_index, "face", blocks::PlaneKind::FreeFace, frame.along, frame.origin));
  blocks::ConvexConstruction c = blocks::build_convex_block(id, hs, datum);
  if (c.outcome != blocks::ConvexOutcome::Bounded)
    throw std::runtime_error("face wedge " + id + " is not a bounded solid");
  return std::move(*c.polyhedron);
}

}  // namespace rockface::tunnel

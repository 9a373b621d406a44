#include "core/blocks/polyhedron.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <Eigen/Geometry>

#include "core/blocks/tolerances.h"
#include "core/common/error.h"
#include "core/common/number_format.h"

namespace rockface::blocks {

namespace {

std::string face_name(const std::vector<BlockPlane>& planes, const std::vector<FaceLoop>& faces,
                      int f) {
  std::string s = "face " + std::to_string(f);
  const int p = faces[f].plane;
  if (p >= 0 && p < static_cast<int>(planes.size()) && !planes[p].name.empty())
    s += " (" + planes[p].name + ")";
  return s;
}

std::string metres(double v) {
  return format_significant(v, 3, " m");
}

}  // namespace

Polyhedron Polyhedron::assemble(std::string id, const Eigen::Vector3d& datum,
                                std::vector<BlockPlane> planes,
                                std::vector<Eigen::Vector3d> vertices,
                                const std::vector<FaceLoop>& faces, double planarity_tolerance) {
  const std::string where = "block " + id;
  const int nv = static_cast<int>(vertices.size());
  const int np = static_cast<int>(planes.size());
  if (faces.size() < 4)
    throw InputError(where,
                     "a closed block needs at least 4 faces, got " + std::to_string(faces.size()));
  for (int v = 0; v < nv; ++v)
    if (!vertices[v].allFinite())
      throw InputError(where, "vertex " + std::to_string(v) + " has a non-finite coordinate");

  Polyhedron P;
  P.id_ = std::move(id);
  P.datum_ = datum;

  // Indices and loops first: nothing else can be checked with a bad index.
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    const auto& fl = faces[f];
    if (fl.plane < 0 || fl.plane >= np)
      throw InputError(where, "face " + std::to_string(f) + ": plane index " +
                                  std::to_string(fl.plane) + " is out of range (" +
                                  std::to_string(np) + " planes)");
    const int n = static_cast<int>(fl.loop.size());
    for (int k = 0; k < n; ++k)
      if (fl.loop[k] < 0 || fl.loop[k] >= nv)
        throw InputError(where, face_name(planes, faces, f) + ": loop[" + std::to_string(k) +
                                    "] = vertex " + std::to_string(fl.loop[k]) +
                                    " is out of range (" + std::to_string(nv) + " vertices)");
    if (n < 3)
      throw InputError(where, face_name(planes, faces, f) + ": a loop needs at least 3 vertices");
    for (int k = 0; k < n; ++k) {
      if (fl.loop[k] == fl.loop[(k + 1) % n])
        throw InputError(where, face_name(planes, faces, f) + ": vertex " +
                                    std::to_string(fl.loop[k]) + " repeats at loop[" +
                                    std::to_string(k) + "] and the next position");
      for (int m = k + 1; m < n; ++m)
        if (fl.loop[k] == fl.loop[m])
          throw InputError(where, face_name(planes, faces, f) + ": vertex " +
                                      std::to_string(fl.loop[k]) +
                                      " occurs twice in the loop (a face has one boundary, no "
                                      "holes or pinches)");
    }
  }

  // Half-edges, and each directed edge used once.
  std::map<std::pair<int, int>, int> directed;
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    Face face;
    face.plane = faces[f].plane;
    face.loop = faces[f].loop;
    const int n = static_cast<int>(face.loop.size());
    const int first = static_cast<int>(P.half_edges_.size());
    face.half_edge = first;
    for (int k = 0; k < n; ++k) {
      HalfEdge h;
      h.origin = face.loop[k];
      h.face = f;
      h.next = first + (k + 1) % n;
      h.prev = first + (k + n - 1) % n;
      const auto key = std::make_pair(face.loop[k], face.loop[(k + 1) % n]);
      auto [it, inserted] = directed.emplace(key, first + k);
      if (!inserted) {
        const int other = P.half_edges_[it->second].face;
        throw InputError(where, "edge " + std::to_string(key.first) + " -> " +
                                    std::to_string(key.second) + " runs the same way in " +
                                    face_name(planes, faces, other) + " and " +
                                    face_name(planes, faces, f) +
                                    ": inconsistent orientation (every loop must run "
                                    "counter-clockwise seen from outside) or more than two "
                                    "faces on one edge");
      }
      P.half_edges_.push_back(h);
    }
    P.faces_.push_back(std::move(face));
  }

  // Twins: a closed surface has every edge in both directions.
  for (int h = 0; h < static_cast<int>(P.half_edges_.size()); ++h) {
    HalfEdge& he = P.half_edges_[h];
    const int a = he.origin, b = P.half_edges_[he.next].origin;
    auto it = directed.find({b, a});
    if (it == directed.end())
      throw InputError(where, "not closed: edge " + std::to_string(a) + " - " + std::to_string(b) +
                                  " of " + face_name(planes, faces, he.face) +
                                  " has no neighbouring face running " + std::to_string(b) +
                                  " -> " + std::to_string(a));
    he.twin = it->second;
  }
  for (int h = 0; h < static_cast<int>(P.half_edges_.size()); ++h) {
    HalfEdge& he = P.half_edges_[h];
    if (he.edge >= 0) continue;
    Edge e;
    e.v0 = he.origin;
    e.v1 = P.half_edges_[he.next].origin;
    e.half_edge = h;
    e.left = he.face;
    e.right = P.half_edges_[he.twin].face;
    he.edge = static_cast<int>(P.edges_.size());
    P.half_edges_[he.twin].edge = he.edge;
    P.edges_.push_back(e);
  }

  // Every vertex one manifold corner: its faces form a single fan.
  P.vertex_half_edge_.assign(nv, -1);
  std::vector<int> outgoing(nv, 0);
  for (int h = 0; h < static_cast<int>(P.half_edges_.size()); ++h) {
    const int v = P.half_edges_[h].origin;
    if (P.vertex_half_edge_[v] < 0) P.vertex_half_edge_[v] = h;
    ++outgoing[v];
  }
  for (int v = 0; v < nv; ++v) {
    if (P.vertex_half_edge_[v] < 0)
      throw InputError(where, "vertex " + std::to_string(v) + " belongs to no face");
    int count = 0;
    int h = P.vertex_half_edge_[v];
    do {
      ++count;
      h = P.half_edges_[P.half_edges_[h].prev].twin;
    } while (h != P.vertex_half_edge_[v] && count <= outgoing[v]);
    if (count != outgoing[v])
      throw InputError(where, "vertex " + std::to_string(v) +
                                  " is not a single corner: its faces form more than one fan "
                                  "(two blocks touching at a point?)");
  }

  const int euler = nv - static_cast<int>(P.edges_.size()) + static_cast<int>(P.faces_.size());
  if (euler != 2)
    throw InputError(where, "Euler-Poincare characteristic V - E + F = " + std::to_string(nv) +
                                " - " + std::to_string(P.edges_.size()) + " + " +
                                std::to_string(P.faces_.size()) + " = " + std::to_string(euler) +
                                ", not 2: the surface has a hole through it or is in pieces");

  Eigen::Vector3d lo = vertices[0], hi = vertices[0];
  for (const auto& x : vertices) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  P.size_ = (hi - lo).norm();
  if (!(P.size_ > 0)) throw InputError(where, "all vertices coincide");

  // Planarity: every corner on its face's plane.
  const double tol = planarity_tolerance >= 0 ? planarity_tolerance : kFacePlanarityRel * P.size_;
  for (int f = 0; f < static_cast<int>(P.faces_.size()); ++f) {
    const auto& pl = planes[P.faces_[f].plane].plane;
    for (int v : P.faces_[f].loop) {
      const double d = std::abs(pl.signed_distance(vertices[v]));
      if (!(d <= tol))
        throw InputError(where, face_name(planes, faces, f) + " is not planar: vertex " +
                                    std::to_string(v) + " is " + metres(d) +
                                    " off the face's plane (tolerance " + metres(tol) + ")");
    }
  }

  // Orientation: each loop counter-clockwise about its outward normal, and
  // together they enclose a positive volume.
  double volume6 = 0;
  const Eigen::Vector3d& o = vertices[0];
  for (int f = 0; f < static_cast<int>(P.faces_.size()); ++f) {
    const auto& loop = P.faces_[f].loop;
    Eigen::Vector3d area2 = Eigen::Vector3d::Zero();
    const Eigen::Vector3d& a = vertices[loop[0]];
    for (size_t k = 1; k + 1 < loop.size(); ++k)
      area2 += (vertices[loop[k]] - a).cross(vertices[loop[k + 1]] - a);
    volume6 += (a - o).dot(area2);
    const Eigen::Vector3d out = planes[P.faces_[f].plane].outward_normal();
    if (!(area2.dot(out) > 0))
      throw InputError(where, face_name(planes, faces, f) +
                                  ": the loop runs clockwise seen from outside the block (its "
                                  "plane's half-space code says the block lies on the other side)");
  }
  if (!(volume6 > 0))
    throw InputError(where,
                     "the loops enclose no positive volume: they run clockwise seen from "
                     "outside");

  P.planes_ = std::move(planes);
  P.vertices_ = std::move(vertices);
  return P;
}

int Polyhedron::half_edge_between(int a, int b) const {
  for (int h : outgoing_half_edges(a))
    if (target(h) == b) return h;
  return -1;
}

std::vector<int> Polyhedron::face_half_edges(int f) const {
  std::vector<int> out;
  const int first = faces_[f].half_edge;
  int h = first;
  do {
    out.push_back(h);
    h = half_edges_[h].next;
  } while (h != first);
  return out;
}

std::vector<int> Polyhedron::face_edges(int f) const {
  std::vector<int> out;
  for (int h : face_half_edges(f)) out.push_back(half_edges_[h].edge);
  return out;
}

std::vector<int> Polyhedron::adjacent_faces(int f) const {
  std::vector<int> out;
  for (int h : face_half_edges(f)) out.push_back(half_edges_[half_edges_[h].twin].face);
  return out;
}

std::vector<int> Polyhedron::outgoing_half_edges(int v) const {
  std::vector<int> out;
  const int first = vertex_half_edge_[v];
  int h = first;
  do {
    out.push_back(h);
    h = half_edges_[half_edges_[h].prev].twin;
  } while (h != first);
  return out;
}

std::vector<int> Polyhedron::faces_around_vertex(int v) const {
  std::vector<int> out;
  for (int h : outgoing_half_edges(v)) out.push_back(half_edges_[h].face);
  return out;
}

std::vector<int> Polyhedron::edges_around_vertex(int v) const {
  std::vector<int> out;
  for (int h : outgoing_half_edges(v)) out.push_back(half_edges_[h].edge);
  return out;
}

std::vector<int> Polyhedron::planes_at_vertex(int v) const {
  std::vector<int> out;
  for (int f : faces_around_vertex(v)) {
    const int p = faces_[f].plane;
    if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
  }
  return out;
}

std::vector<int> Polyhedron::faces_on_plane(int p) const {
  std::vector<int> out;
  for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
    if (faces_[f].plane == p) out.push_back(f);
  return out;
}

Eigen::Vector3d Polyhedron::edge_direction(int e) const {
  return (vertices_[edges_[e].v1] - vertices_[edges_[e].v0]).normalized();
}

bool Polyhedron::edge_is_reflex(int e) const {
  const Edge& ed = edges_[e];
  if (faces_[ed.left].plane == faces_[ed.right].plane) return false;  // flat
  // Convex edge: (n_left x n_right) . d > 0 with d running v0 -> v1 in the
  // left face (counter-clockwise loops, outward normals).
  const Eigen::Vector3d nl = face_outward_normal(ed.left), nr = face_outward_normal(ed.right);
  return nl.cross(nr).dot(edge_direction(e)) < -kReflexSine;
}

}  // namespace rockface::blocks

#include "core/kinematics/rotation_input.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/blocks/polyhedron.h"
#include "core/common/error.h"

namespace rockface::kinematics {

namespace {

std::string where(const RotationInput& in, const std::string& what) {
  return "block " + (in.block.empty() ? std::string("?") : in.block) + ": " + what;
}

}  // namespace

bool RotationTopology::has_joint(const RotationInput& in, int v) const {
  return std::any_of(vertex_planes[v].begin(), vertex_planes[v].end(),
                     [&](int p) { return in.planes[p].joint; });
}

bool RotationTopology::has_free_face(const RotationInput& in, int v) const {
  return std::any_of(vertex_planes[v].begin(), vertex_planes[v].end(),
                     [&](int p) { return !in.planes[p].joint; });
}

RotationTopology rotation_topology(const RotationInput& in) {
  const int nv = static_cast<int>(in.vertices.size());
  const int np = static_cast<int>(in.planes.size());
  if (nv < 4) throw InputError(where(in, "vertices"), "a block needs at least 4 corners");
  if (in.faces.size() < 4) throw InputError(where(in, "faces"), "a block needs at least 4 faces");
  for (int p = 0; p < np; ++p) {
    const double len = in.planes[p].inward_normal.norm();
    if (!std::isfinite(len) || std::abs(len - 1) > 1e-6)
      throw InputError(where(in, "plane " + in.planes[p].name),
                       "block-side normal is not a unit vector");
  }
  for (const auto& x : in.vertices)
    if (!x.allFinite()) throw InputError(where(in, "vertices"), "a corner is not finite");

  RotationTopology t;
  t.vertex_planes.resize(nv);
  for (auto& planes : t.vertex_planes) planes.reserve(4);  // most corners: 3 planes
  // Directed edges (a, b, plane of the face it belongs to); each undirected
  // edge must appear once in each direction (closed, consistently oriented).
  // A sorted list, not a map: a block has a few dozen edges.
  struct Directed {
    int a, b, plane, face;
  };
  std::vector<Directed> directed;
  size_t corners = 0;
  for (const auto& face : in.faces) corners += face.loop.size();
  directed.reserve(corners);
  for (size_t f = 0; f < in.faces.size(); ++f) {
    const auto& face = in.faces[f];
    // Named only when an error is thrown (the names cost more than the checks).
    auto face_name = [](size_t k) { return "face " + std::to_string(k); };
    if (face.plane < 0 || face.plane >= np)
      throw InputError(where(in, face_name(f)), "plane index out of range");
    if (face.loop.size() < 3)
      throw InputError(where(in, face_name(f)), "loop has fewer than 3 corners");
    for (size_t k = 0; k < face.loop.size(); ++k) {
      const int a = face.loop[k];
      const int b = face.loop[(k + 1) % face.loop.size()];
      if (a < 0 || a >= nv || b < 0 || b >= nv)
        throw InputError(where(in, face_name(f)), "vertex index out of range");
      if (a == b) throw InputError(where(in, face_name(f)), "loop repeats a corner");
      directed.push_back({a, b, face.plane, static_cast<int>(f)});
      auto& vp = t.vertex_planes[a];
      if (std::find(vp.begin(), vp.end(), face.plane) == vp.end()) vp.push_back(face.plane);
    }
  }
  auto key = [](const Directed& d) { return std::make_pair(d.a, d.b); };
  // Stable: of two uses of one directed edge, the later face is named.
  std::stable_sort(directed.begin(), directed.end(),
                   [&](const Directed& x, const Directed& y) { return key(x) < key(y); });
  for (size_t k = 1; k < directed.size(); ++k)
    if (key(directed[k]) == key(directed[k - 1]))
      throw InputError(where(in, "face " + std::to_string(directed[k].face)),
                       "edge " + std::to_string(directed[k].a) + "-" +
                           std::to_string(directed[k].b) + " is used twice in the same direction");
  for (const auto& d : directed) {
    const auto twin = std::lower_bound(
        directed.begin(), directed.end(), std::make_pair(d.b, d.a),
        [&](const Directed& x, const std::pair<int, int>& k) { return key(x) < k; });
    if (twin == directed.end() || key(*twin) != std::make_pair(d.b, d.a))
      throw InputError(where(in, "edge " + std::to_string(d.a) + "-" + std::to_string(d.b)),
                       "has a face on one side only (the block is not closed)");
    if (d.a < d.b) t.edges.push_back(RotationEdge{{d.a, d.b}, {d.plane, twin->plane}});
  }
  for (int v = 0; v < nv; ++v) {
    if (t.vertex_planes[v].empty())
      throw InputError(where(in, "vertex " + std::to_string(v)), "belongs to no face");
    std::sort(t.vertex_planes[v].begin(), t.vertex_planes[v].end());
  }
  Eigen::Vector3d lo = in.vertices[0], hi = in.vertices[0];
  for (const auto& x : in.vertices) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
    t.centroid += x;
  }
  t.centroid /= nv;
  t.size = (hi - lo).norm();
  return t;
}

RotationInput rotation_input(const blocks::Polyhedron& block) {
  RotationInput in;
  in.block = block.id();
  in.planes.reserve(block.planes().size());
  for (const auto& p : block.planes())
    in.planes.push_back({p.name, p.kind == blocks::PlaneKind::Joint, p.inward_normal()});
  in.vertices = block.vertices();
  in.faces.reserve(block.faces().size());
  for (const auto& f : block.faces()) in.faces.push_back({f.plane, f.loop});
  return in;
}

}  // namespace rockface::kinematics

#include "core/kinematics/block_analysis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>

#include "core/geometry/parallel_planes.h"
#include "core/geometry/tolerances.h"

namespace rockface::kinematics {

namespace {

// JP cap EP shut (> 0) or open (< 0) by that angle; with `parallel`
// (pairs of the joints then the free faces of the one EP, taken as
// parallel) within their plane.
Finiteness decide_finiteness(geometry::Cone jp, std::vector<geometry::Cone> eps, double uncertainty,
                             const std::vector<std::pair<int, int>>& parallel = {}) {
  Finiteness f;
  f.joint_pyramid = std::move(jp);
  // No free face: the excavation pyramid is the whole space.
  if (eps.empty()) eps.emplace_back();
  f.excavation_pyramids = std::move(eps);
  double shut = 0;
  if (parallel.empty()) {
    shut = geometry::intersection_with_union_empty(f.joint_pyramid, f.excavation_pyramids).margin;
  } else {
    std::vector<Eigen::Vector3d> all = f.joint_pyramid.normals();
    for (const auto& n : f.excavation_pyramids.front().normals()) all.push_back(n);
    double tolerance = std::max(uncertainty, geometry::kParallelRoundingRad);
    for (const auto& [i, j] : parallel)
      tolerance = std::max(tolerance, std::acos(std::clamp(-all[i].dot(all[j]), -1.0, 1.0)));
    const geometry::ParallelReduction r = geometry::parallel_reduction(all, parallel, tolerance);
    f.parallel_angle = r.widest;
    shut = -geometry::margin_with_parallel_planes(all, r).angle;
  }
  f.jp_ep_margin = -shut;
  f.finite = geometry::decide(shut, uncertainty);
  decide_removability(f, shut, uncertainty);
  return f;
}

// The convex parts are the maximal sets of free planes with no reflex edge
// between two of them: maximal independent sets of the "reflex edge" graph,
// found by Bron-Kerbosch with pivoting on its complement. Their number can
// grow exponentially only on contrived surfaces; beyond this many the free
// faces are taken as one convex part, which gives a smaller EP and so errs
// towards "finite" (a block flagged for a closer look, never one missed).
constexpr size_t kMaxConvexParts = 4096;

// Bron-Kerbosch with pivoting: every maximal clique of `adjacent` that
// extends r by vertices of p and none of x. Stops once `out` is full.
void maximal_cliques(const std::vector<std::vector<bool>>& adjacent, std::vector<int>& r,
                     std::vector<int> p, std::vector<int> x, std::vector<std::vector<int>>& out) {
  if (out.size() > kMaxConvexParts) return;
  if (p.empty()) {
    if (x.empty()) out.push_back(r);
    return;
  }
  // Pivot: the vertex of p or x with most neighbours in p.
  int pivot = p.front();
  size_t best = 0;
  for (const auto* set : {&p, &x})
    for (int u : *set) {
      size_t n = 0;
      for (int v : p) n += adjacent[u][v] ? 1 : 0;
      if (n >= best) {
        best = n;
        pivot = u;
      }
    }
  const std::vector<int> candidates = p;
  for (int v : candidates) {
    if (adjacent[pivot][v]) continue;
    std::vector<int> p2, x2;
    for (int u : p)
      if (adjacent[v][u]) p2.push_back(u);
    for (int u : x)
      if (adjacent[v][u]) x2.push_back(u);
    r.push_back(v);
    maximal_cliques(adjacent, r, std::move(p2), std::move(x2), out);
    r.pop_back();
    p.erase(std::find(p.begin(), p.end(), v));
    x.push_back(v);
  }
}

}  // namespace

void decide_removability(Finiteness& f, double shut_margin, double uncertainty) {
  // Up to ~20 joints: the active sets are cheaper from 7 on (see cone.h).
  f.jp_margin = geometry::active_set_margin(f.joint_pyramid, 6).angle;
  // Joints on both sides of planes parallel within the uncertainty: JP is
  // decided within their plane, whatever the hair of an angle between them
  // (which way it opens is beyond what was measured). A block that can
  // come out does so by sliding between them: marginal, as the cone has no
  // width across them.
  const double tolerance = std::max(uncertainty, geometry::kParallelRoundingRad);
  const std::vector<Eigen::Vector3d>& joints = f.joint_pyramid.normals();
  const std::vector<std::pair<int, int>> pairs = geometry::opposite_pairs(joints, tolerance);
  f.jp_between_parallel = !pairs.empty();
  if (!f.jp_between_parallel) {
    f.removable = geometry::decide(std::min(f.jp_margin, shut_margin), uncertainty);
    return;
  }
  f.jp_in_plane_margin = geometry::margin_with_parallel_planes(
                             joints, geometry::parallel_reduction(joints, pairs, tolerance))
                             .angle;
  f.removable = geometry::decide(std::min(f.jp_in_plane_margin, shut_margin), uncertainty);
  if (f.removable.value) f.removable.marginal = true;
}

Finiteness halfspace_finiteness(const std::vector<Eigen::Vector3d>& joint_inward_normals,
                                const std::vector<Eigen::Vector3d>& free_inward_normals,
                                double uncertainty,
                                const std::vector<std::pair<int, int>>& parallel) {
  std::vector<geometry::Cone> eps;
  if (!free_inward_normals.empty()) eps.emplace_back(free_inward_normals);
  return decide_finiteness(geometry::Cone(joint_inward_normals), std::move(eps), uncertainty,
                           parallel);
}

Finiteness block_finiteness(const blocks::Polyhedron& block, double uncertainty) {
  const auto& planes = block.planes();
  const int np = static_cast<int>(planes.size());
  geometry::Cone jp;
  for (const auto& p : planes)
    if (p.kind == blocks::PlaneKind::Joint) jp.add(p.inward_normal());

  // Convex parts of the free surface: two free planes meeting at a reflex
  // edge of the block (the rock wraps around the block there) cannot belong
  // to one convex part; every maximal set of free planes without such a pair
  // is a part, and its EP the intersection of its rock-side half-spaces. A
  // convex block has one part, all its free faces (adjacent or not).
  std::vector<int> free;
  for (int p = 0; p < np; ++p)
    if (planes[p].kind == blocks::PlaneKind::FreeFace) free.push_back(p);
  const int nf = static_cast<int>(free.size());
  // Compatible: no reflex edge between the two free planes.
  std::vector<std::vector<bool>> compatible(nf, std::vector<bool>(nf, true));
  bool any_conflict = false;
  for (int e = 0; e < static_cast<int>(block.edges().size()); ++e) {
    if (!block.edge_is_reflex(e)) continue;
    const int a = block.faces()[block.edges()[e].left].plane;
    const int b = block.faces()[block.edges()[e].right].plane;
    const auto ia = std::find(free.begin(), free.end(), a) - free.begin();
    const auto ib = std::find(free.begin(), free.end(), b) - free.begin();
    if (ia == nf || ib == nf || ia == ib) continue;
    compatible[ia][ib] = compatible[ib][ia] = false;
    any_conflict = true;
  }
  for (int k = 0; k < nf; ++k) compatible[k][k] = false;  // no self-loops for the clique search
  std::vector<std::vector<int>> parts;
  if (any_conflict) {
    std::vector<int> r, all(nf);
    std::iota(all.begin(), all.end(), 0);
    maximal_cliques(compatible, r, all, {}, parts);
  }
  if (!any_conflict || parts.size() > kMaxConvexParts) parts.assign(1, {});
  std::vector<geometry::Cone> eps;
  if (nf > 0)
    for (const auto& part : parts) {
      geometry::Cone ep;
      if (part.empty()) {
        for (int p : free) ep.add(planes[p].inward_normal());
      } else {
        for (int k : part) ep.add(planes[free[k]].inward_normal());
      }
      eps.push_back(std::move(ep));
    }
  return decide_finiteness(std::move(jp), std::move(eps), uncertainty);
}

std::vector<ContactPlane> block_contacts(const blocks::Polyhedron& block,
                                         const blocks::MassProperties& mass,
                                         const std::vector<JointStrength>& strengths) {
  std::vector<ContactPlane> contacts;
  for (int p = 0; p < static_cast<int>(block.planes().size()); ++p) {
    const auto& bp = block.planes()[p];
    if (bp.kind != blocks::PlaneKind::Joint) continue;
    ContactPlane c;
    c.plane = p;
    c.block_normal = bp.inward_normal();
    if (p < static_cast<int>(strengths.size())) {
      c.friction = strengths[p].friction;
      c.cohesion_force = strengths[p].cohesion * mass.plane_areas[p];
    }
    contacts.push_back(c);
  }
  return contacts;
}

BlockAnalysis analyse_block(const blocks::Polyhedron& block, const BlockAnalysisInput& input) {
  BlockAnalysis out;
  out.mass = blocks::mass_properties(block, input.density);
  out.finiteness = block_finiteness(block, input.uncertainty);

  // Loads pressing on faces (water), per plane: the part of the resultant
  // that can open a joint.
  Eigen::Vector3d face_loads = Eigen::Vector3d::Zero();
  std::vector<int> loaded_planes;
  if (input.effects)
    for (const auto& effect : *input.effects) {
      EffectLoad l = effect->load(block, out.mass);
      out.notes.insert(out.notes.end(), l.notes.begin(), l.notes.end());
      if (!l.acts) continue;
      out.force += l.force;
      out.moment += l.moment;
      if (std::find(out.effects_used.begin(), out.effects_used.end(), effect->name()) ==
          out.effects_used.end())
        out.effects_used.push_back(effect->name());
      for (const FaceLoad& fl : l.faces) {
        face_loads += fl.force;
        if (std::find(loaded_planes.begin(), loaded_planes.end(), fl.plane) == loaded_planes.end())
          loaded_planes.push_back(fl.plane);
      }
    }

  // Modes only for blocks that can come out (or might, within the
  // uncertainty): a keyed or infinite block has none.
  const auto& rem = out.finiteness.removable;
  if (!(rem.value || rem.marginal)) return out;
  const std::vector<ContactPlane> contacts = block_contacts(block, out.mass, input.strengths);
  out.mode = sliding_mode(out.force, contacts, input.uncertainty);
  out.fos = out.mode->fos;

  // A joint the other loads press the block onto, but that the pressure on
  // it pushes open, is no longer in contact: the mode above already leaves
  // it out (its normal force would be tensile), and it is named here.
  if (!loaded_planes.empty()) {
    const SlidingMode dry = sliding_mode(out.force - face_loads, contacts, input.uncertainty);
    for (int p : dry.planes) {
      const bool loaded =
          std::find(loaded_planes.begin(), loaded_planes.end(), p) != loaded_planes.end();
      const bool still =
          std::find(out.mode->planes.begin(), out.mode->planes.end(), p) != out.mode->planes.end();
      if (loaded && !still) {
        out.opened_planes.push_back(p);
        out.notes.push_back("face " + block.planes()[p].name +
                            " opens under water pressure: its friction and cohesion do not count");
      }
    }
  }
  if (out.mode->type == ModeType::Sliding && !out.fos) {
    for (int p : out.mode->planes)
      if (p < static_cast<int>(block.planes().size()) &&
          (p >= static_cast<int>(input.strengths.size()) || !input.strengths[p].friction))
        out.notes.push_back("no friction angle for " + block.planes()[p].name +
                            ": no factor of safety");
  }
  return out;
}

}  // namespace rockface::kinematics

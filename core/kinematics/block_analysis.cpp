#include "core/kinematics/block_analysis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace rockface::kinematics {

namespace {

Finiteness decide_finiteness(geometry::Cone jp, std::vector<geometry::Cone> eps,
                             double uncertainty) {
  Finiteness f;
  f.joint_pyramid = std::move(jp);
  // No free face: the excavation pyramid is the whole space.
  if (eps.empty()) eps.emplace_back();
  f.excavation_pyramids = std::move(eps);
  f.jp_margin = f.joint_pyramid.margin().angle;
  const geometry::UnionEmptiness u =
      geometry::intersection_with_union_empty(f.joint_pyramid, f.excavation_pyramids);
  f.jp_ep_margin = -u.margin;
  f.finite = geometry::decide(u.margin, uncertainty);
  f.removable = geometry::decide(std::min(f.jp_margin, u.margin), uncertainty);
  return f;
}

// Enumerating the convex parts of the free surface visits every subset of
// the free planes; beyond this many (never seen on a real block) the free
// faces are taken as one convex part.
constexpr int kMaxFreePlanesForParts = 16;

}  // namespace

Finiteness halfspace_finiteness(const std::vector<Eigen::Vector3d>& joint_inward_normals,
                                const std::vector<Eigen::Vector3d>& free_inward_normals,
                                double uncertainty) {
  std::vector<geometry::Cone> eps;
  if (!free_inward_normals.empty()) eps.emplace_back(free_inward_normals);
  return decide_finiteness(geometry::Cone(joint_inward_normals), std::move(eps), uncertainty);
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
  std::vector<unsigned> conflict(nf, 0);  // bit k: conflicts with free[k]
  for (int e = 0; e < static_cast<int>(block.edges().size()); ++e) {
    if (!block.edge_is_reflex(e)) continue;
    const int a = block.faces()[block.edges()[e].left].plane;
    const int b = block.faces()[block.edges()[e].right].plane;
    const auto ia = std::find(free.begin(), free.end(), a) - free.begin();
    const auto ib = std::find(free.begin(), free.end(), b) - free.begin();
    if (ia == nf || ib == nf || ia == ib) continue;
    conflict[ia] |= 1u << ib;
    conflict[ib] |= 1u << ia;
  }
  std::vector<geometry::Cone> eps;
  const bool any_conflict =
      std::any_of(conflict.begin(), conflict.end(), [](unsigned c) { return c; });
  if (!any_conflict || nf > kMaxFreePlanesForParts) {
    if (nf > 0) {
      geometry::Cone ep;
      for (int p : free) ep.add(planes[p].inward_normal());
      eps.push_back(std::move(ep));
    }
  } else {
    auto independent = [&](unsigned set) {
      for (int k = 0; k < nf; ++k)
        if ((set >> k & 1u) && (conflict[k] & set)) return false;
      return true;
    };
    for (unsigned set = 1; set < (1u << nf); ++set) {
      if (!independent(set)) continue;
      bool maximal = true;
      for (int k = 0; k < nf && maximal; ++k)
        if (!(set >> k & 1u) && independent(set | 1u << k)) maximal = false;
      if (!maximal) continue;
      geometry::Cone ep;
      for (int k = 0; k < nf; ++k)
        if (set >> k & 1u) ep.add(planes[free[k]].inward_normal());
      eps.push_back(std::move(ep));
    }
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

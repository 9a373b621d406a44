#include "core/mechanics/block_loads.h"

#include <algorithm>

#include <Eigen/Geometry>

#include "core/kinematics/effects/effect_force.h"

namespace rockface::mechanics {

namespace {

bool follows_block(const kinematics::Effect& e) {
  if (e.name() == "water") return true;  // pressure stays normal to its face
  if (const auto* f = dynamic_cast<const kinematics::ForceEffect*>(&e))
    return f->frame() == kinematics::ForceFrame::Block;
  return false;
}

}  // namespace

BlockLoads block_loads(const blocks::Polyhedron& block, const blocks::MassProperties& mass,
                       const kinematics::Effects& effects) {
  BlockLoads out;
  for (const auto& effect : effects) {
    const kinematics::EffectLoad l = effect->load(block, mass);
    out.notes.insert(out.notes.end(), l.notes.begin(), l.notes.end());
    if (!l.acts) continue;
    if (std::find(out.effects_used.begin(), out.effects_used.end(), effect->name()) ==
        out.effects_used.end())
      out.effects_used.push_back(effect->name());
    out.force += l.force;
    const bool follower = follows_block(*effect);
    Eigen::Vector3d rest_force = l.force, rest_moment = l.moment;
    for (const kinematics::FaceLoad& fl : l.faces) {
      RigidLoad r;
      r.effect = effect->name();
      r.force = fl.force;
      r.arm = fl.point - mass.centroid;
      r.follower = follower;
      out.loads.push_back(r);
      rest_force -= fl.force;
      rest_moment -= r.arm.cross(fl.force);
    }
    // What is not given face by face: one force on its line of action
    // (the point of the line nearest the centroid, arm = F x M / |F|^2),
    // and the part of the moment no arm can carry as a couple.
    const double f2 = rest_force.squaredNorm();
    const double scale = l.force.norm() + l.moment.norm() / std::max(block.size(), 1e-300);
    if (!(f2 > 0) && !(rest_moment.norm() > 1e-14 * scale * std::max(block.size(), 1.0))) continue;
    RigidLoad r;
    r.effect = effect->name();
    r.follower = follower;
    if (f2 > 0) {
      r.force = rest_force;
      r.arm = rest_force.cross(rest_moment) / f2;
      r.couple = rest_moment - r.arm.cross(rest_force);
    } else {
      r.couple = rest_moment;
    }
    out.loads.push_back(r);
  }
  return out;
}

InsituTraction insitu_traction(const Eigen::Matrix3d& stress, const Eigen::Vector3d& n) {
  // The rock across the joint pushes on the block's face, whose outward
  // normal is -n: traction -sigma (-n) = sigma n with compression positive.
  const Eigen::Vector3d t = stress * n;
  InsituTraction out;
  out.normal = n.dot(t);
  out.shear = t - out.normal * n;
  return out;
}

}  // namespace rockface::mechanics

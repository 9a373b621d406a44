#pragma once
// The equations of motion of one rigid block on its joints after failure:
// Newton-Euler for the centroid and the rotation (a unit quaternion),
//   m a = F + sum of contact forces,
//   I w' = M - w x (I w) + sum of contact moments   (I turned with the block),
// with gravity and the scene's effects as loads (block_loads.h: fixed in
// space or following the block's rotation), and the joint contacts
// (joint_contacts.h) as unilateral constraints.
//
// The contact forces are found by inverse dynamics at every evaluation: a
// closed contact whose point does not move away from the rock gets a
// normal force N >= 0 such that it does not accelerate into the rock, and
// N = 0 where it would accelerate away (it opens: the normal force would
// have turned tensile); a mixed linear complementarity problem
// (mixed_lcp.h). Coulomb friction acts while a contact slides: mu N
// against its slip velocity, mu = tan of the joint's friction angle.
// Contacts at rest slip (as a whole) where kinetic friction against the way
// they would move does not turn them back, and stick otherwise. Cohesion is not used: a
// block that has failed has broken its joints' cohesion, and sliding does
// not restore it.
//
// Drift: the integration satisfies the contact constraints at the level of
// accelerations only; project() puts the block back on the contacts that
// carry load (positions within kDriftBoundRel x L, velocities along their
// normals to zero) and renormalises the quaternion after every accepted
// step. The same projection of velocities with N >= 0 impulses is a
// perfectly plastic impact where a contact closes.
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/blocks/mass_properties.h"
#include "core/blocks/polyhedron.h"
#include "core/mechanics/block_loads.h"
#include "core/mechanics/dynamics/joint_contacts.h"

namespace rockface::mechanics {

struct BlockVelocity {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();  // of the centroid, m/s
  Eigen::Vector3d w = Eigen::Vector3d::Zero();  // angular velocity, rad/s, global axes
};

struct ContactSolution {
  std::vector<JointContact> contacts;     // the closed contacts that do not open
  std::vector<double> normal;             // N >= 0 on each
  std::vector<Eigen::Vector3d> friction;  // N, friction force on the block at each
  std::vector<bool> slipping;
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();          // of the centroid
  Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();  // global axes
  bool converged = true;
};

struct AppliedLoads {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // about the current centroid
  double power = 0;                                  // W, their rate of work
};

class BlockMotion {
 public:
  // friction_deg: per polyhedron plane, the friction angle while sliding.
  BlockMotion(const blocks::Polyhedron& block, const blocks::MassProperties& mass, BlockLoads loads,
              const std::vector<double>& friction_deg);

  ContactSolution solve(const BlockPose& pose, const BlockVelocity& velocity) const;
  AppliedLoads applied(const BlockPose& pose, const BlockVelocity& velocity) const;
  Eigen::Matrix3d inertia(const BlockPose& pose) const;  // about the centroid, global axes

  struct Projection {
    double drift_before = 0;  // m, largest gap of a loaded contact or penetration, before
    double drift_after = 0;   // m, after
    double impact_speed = 0;  // m/s, largest closing speed removed (an impact when large)
  };
  Projection project(BlockPose& pose, BlockVelocity& velocity) const;

  double kinetic_translational(const BlockVelocity& v) const;
  double kinetic_rotational(const BlockPose& pose, const BlockVelocity& v) const;

  const JointContacts& geometry() const { return geometry_; }
  double mass() const { return mass_; }
  double length() const { return geometry_.length(); }
  double gravity() const { return gravity_; }             // |g| (m/s^2), or the loads' per mass
  double load_scale() const { return mass_ * gravity_; }  // N
  const Eigen::Vector3d& centroid() const { return geometry_.centroid(); }
  const BlockLoads& loads() const { return loads_; }

 private:
  JointContacts geometry_;
  BlockLoads loads_;
  double mass_ = 0, gravity_ = 9.81;
  Eigen::Matrix3d inertia0_;
};

}  // namespace rockface::mechanics

#pragma once
// Blocks and effects shared by the equilibrium-path tests and benchmark:
// a slab on a plane (plane failure), a symmetric wedge and a tall column,
// each placeable anywhere (a rigid motion of the whole scene) and at
// survey coordinates (a datum).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/blocks/construction.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/effects/effect_force.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "core/mechanics/joint_law.h"

namespace rockface::mechanics::testing {

// A rigid motion of the whole scene: x -> rotation x + shift; datum: the
// origin the polyhedron's coordinates are taken from.
struct Placement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  Eigen::Vector3d point(const Eigen::Vector3d& x) const { return rotation * x + shift; }
  Eigen::Vector3d vector(const Eigen::Vector3d& v) const { return rotation * v; }
};

inline Eigen::Vector3d normal_deg(double dip, double dipdir) {
  return geometry::plane_normal_deg(dip, dipdir);
}

// A half-space from its inward normal and a point (absolute), placed.
inline blocks::HalfSpaceInput bounding(int index, const std::string& name, blocks::PlaneKind kind,
                                       const Eigen::Vector3d& inward, const Eigen::Vector3d& point,
                                       const Placement& at) {
  const Eigen::Vector3d n = at.vector(inward).normalized();
  blocks::HalfSpaceInput h;
  h.index = index;
  h.name = name;
  h.kind = kind;
  h.plane.normal = n.z() < 0 || (n.z() == 0 && n(0) + n.y() < 0) ? Eigen::Vector3d(-n) : n;
  h.plane.offset = h.plane.normal.dot(at.point(point) - at.datum);
  h.side = h.plane.normal.dot(n) > 0 ? geometry::HalfSpace::Upper : geometry::HalfSpace::Lower;
  return h;
}

inline blocks::Polyhedron bounded(const std::string& id,
                                  const std::vector<blocks::HalfSpaceInput>& h,
                                  const Placement& at) {
  auto c = blocks::build_convex_block(id, h, at.datum);
  if (c.outcome != blocks::ConvexOutcome::Bounded) throw std::runtime_error(id + ": not bounded");
  return *c.polyhedron;
}

// Slab of length a down the dip, width b, thickness t on a joint dipping
// psi towards dipdir; every other face free. Its base centre is base_centre().
struct Slab {
  double psi = 35, dipdir = 120, a = 4, b = 3, t = 1.5;
  Eigen::Vector3d o{3, -2, 1};
  Eigen::Vector3d n() const { return normal_deg(psi, dipdir); }
  Eigen::Vector3d d() const {
    return geometry::line_direction({deg_to_rad(dipdir), deg_to_rad(psi)});
  }
  Eigen::Vector3d s() const { return n().cross(d()); }
  blocks::Polyhedron block(const Placement& at = {}) const {
    using blocks::PlaneKind;
    return bounded("slab",
                   {bounding(0, "J1", PlaneKind::Joint, n(), o, at),
                    bounding(1, "top", PlaneKind::FreeFace, -n(), o + t * n(), at),
                    bounding(2, "up", PlaneKind::FreeFace, d(), o, at),
                    bounding(3, "down", PlaneKind::FreeFace, -d(), o + a * d(), at),
                    bounding(4, "left", PlaneKind::FreeFace, s(), o, at),
                    bounding(5, "right", PlaneKind::FreeFace, -s(), o + b * s(), at)},
                   at);
  }
  // A point of the slab at fractions (down the dip, across, up the thickness).
  Eigen::Vector3d at(double fa, double fb, double ft) const {
    return o + fa * a * d() + fb * b * s() + ft * t * n();
  }
};

// The symmetric wedge of the limit-equilibrium tests: joints dipping 60
// towards 135 and 225, a 75-degree face towards 180, a flat top at 10 m.
inline blocks::Polyhedron wedge(const Placement& at = {}) {
  using blocks::PlaneKind;
  const Eigen::Vector3d o = Eigen::Vector3d::Zero();
  return bounded("wedge",
                 {bounding(0, "J1", PlaneKind::Joint, normal_deg(60, 135), o, at),
                  bounding(1, "J2", PlaneKind::Joint, normal_deg(60, 225), o, at),
                  bounding(2, "F", PlaneKind::FreeFace, -normal_deg(75, 180), o, at),
                  bounding(3, "T", PlaneKind::FreeFace, -normal_deg(0, 0), {0, 0, 10}, at)},
                 at);
}

inline kinematics::Effects gravity(const Placement& at = {}) {
  kinematics::Effects e;
  e.push_back(std::make_unique<kinematics::GravityEffect>(at.vector({0, 0, -9.81})));
  return e;
}

// Rigid-plastic Coulomb joints: very stiff, no dilation, Mohr-Coulomb.
inline JointLawParameters coulomb(double phi_deg, double cohesion = 0, double kn = 1e12) {
  JointLawParameters p;
  p.model = JointModel::Coulomb;
  p.friction = deg_to_rad(phi_deg);
  p.cohesion = cohesion;
  p.normal_stiffness = kn;
  return p;
}

inline JointLawParameters barton(double jrc, double kn) {
  JointLawParameters p;
  p.model = JointModel::BartonBandis;
  p.jrc = jrc;
  p.jcs = 100e6;
  p.phi_b = deg_to_rad(30);
  p.normal_stiffness = kn;
  return p;
}

// The same law on every joint plane of the block.
inline std::vector<std::shared_ptr<const JointLaw>> laws(const blocks::Polyhedron& p,
                                                         const JointLawParameters& params) {
  std::shared_ptr<const JointLaw> law = make_joint_law(params);
  std::vector<std::shared_ptr<const JointLaw>> out(p.planes().size());
  for (size_t i = 0; i < out.size(); ++i)
    if (p.planes()[i].kind == blocks::PlaneKind::Joint) out[i] = law;
  return out;
}

}  // namespace rockface::mechanics::testing

#include "core/mechanics/dynamics/block_motion.h"

#include <algorithm>
#include <cmath>

#include "core/mechanics/block_equilibrium.h"
#include "core/mechanics/contact_points.h"
#include "core/mechanics/dynamics/mixed_lcp.h"
#include "core/mechanics/dynamics/tolerances.h"

namespace rockface::mechanics {

namespace {

using Row = Eigen::Matrix<double, 1, 6>;

Row jacobian_row(const Eigen::Vector3d& dir, const Eigen::Vector3d& arm) {
  Row j;
  j << dir.transpose(), arm.cross(dir).transpose();
  return j;
}

// The generalised inverse mass: diag(1/m, I^-1).
Eigen::Matrix<double, 6, 6> inverse_mass(double m, const Eigen::Matrix3d& inertia) {
  Eigen::Matrix<double, 6, 6> out = Eigen::Matrix<double, 6, 6>::Zero();
  out.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() / m;
  out.bottomRightCorner<3, 3>() = inertia.inverse();
  return out;
}

// The smallest mass-weighted correction (translation, rotation) that
// brings each row's value to zero (rows held both ways) or to >= 0
// (unilateral rows): one complementarity problem, for the positions' gaps
// and for the velocities' normal speeds alike.
Eigen::Matrix<double, 6, 1> mass_weighted_correction(const std::vector<Row>& rows,
                                                     const std::vector<double>& values,
                                                     const std::vector<bool>& unilateral,
                                                     const Eigen::Matrix<double, 6, 6>& minv,
                                                     double force_tol, double value_tol) {
  const int n = static_cast<int>(rows.size());
  Eigen::MatrixXd j(n, 6);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    j.row(i) = rows[i];
    b(i) = values[i];
  }
  const MixedLcpResult r = solve_mixed_lcp(j * minv * j.transpose(), b, unilateral, force_tol,
                                           value_tol, kLcpIterations);
  return minv * j.transpose() * r.z;
}

}  // namespace

BlockMotion::BlockMotion(const blocks::Polyhedron& block, const blocks::MassProperties& mass,
                         BlockLoads loads, const std::vector<double>& friction_deg)
    : geometry_(block, mass.centroid, friction_deg),
      loads_(std::move(loads)),
      mass_(mass.mass),
      inertia0_(mass.inertia) {
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for (const RigidLoad& l : loads_.loads)
    if (l.effect == "gravity") g += l.force;
  gravity_ = g.norm() / mass_;
  if (!(gravity_ > 0)) gravity_ = loads_.force.norm() / mass_;
  if (!(gravity_ > 0)) gravity_ = 1.0;
}

Eigen::Matrix3d BlockMotion::inertia(const BlockPose& pose) const {
  const Eigen::Matrix3d r = pose.q.toRotationMatrix();
  return r * inertia0_ * r.transpose();
}

AppliedLoads BlockMotion::applied(const BlockPose& pose, const BlockVelocity& vel) const {
  AppliedLoads out;
  for (const RigidLoad& l : loads_.loads) {
    const Eigen::Vector3d arm = pose.q * l.arm;
    const Eigen::Vector3d f = l.follower ? Eigen::Vector3d(pose.q * l.force) : l.force;
    const Eigen::Vector3d c = l.follower ? Eigen::Vector3d(pose.q * l.couple) : l.couple;
    out.force += f;
    out.moment += arm.cross(f) + c;
    out.power += f.dot(vel.v + vel.w.cross(arm)) + c.dot(vel.w);
  }
  return out;
}

double BlockMotion::kinetic_translational(const BlockVelocity& v) const {
  return 0.5 * mass_ * v.v.squaredNorm();
}

double BlockMotion::kinetic_rotational(const BlockPose& pose, const BlockVelocity& v) const {
  return 0.5 * v.w.dot(inertia(pose) * v.w);
}

ContactSolution BlockMotion::solve(const BlockPose& pose, const BlockVelocity& vel) const {
  ContactSolution out;
  const double length = geometry_.length();
  const double rest = kRestSpeedRel * std::sqrt(gravity_ * length);
  const Eigen::Vector3d centre = geometry_.centroid() + pose.u;
  const Eigen::Matrix3d inertia_now = inertia(pose);
  const Eigen::Matrix<double, 6, 6> minv = inverse_mass(mass_, inertia_now);
  const AppliedLoads loads = applied(pose, vel);
  Eigen::Matrix<double, 6, 1> f;
  f << loads.force, loads.moment - vel.w.cross(inertia_now * vel.w);

  // Closed contacts that are not moving away from the rock.
  struct Item {
    JointContact c;
    Eigen::Vector3d arm, t1, t2, slip;
    double mu = 0, bias = 0;
    bool stuck = false;
    bool from_rest = false;  // slips from rest: its direction is found, not given
  };
  std::vector<Item> items;
  for (const JointContact& c : geometry_.contacts(pose, kContactGapRel * length)) {
    Item it;
    it.c = c;
    it.arm = c.point - centre;
    const Eigen::Vector3d vp = vel.v + vel.w.cross(it.arm);
    const double separating = c.normal.dot(vp);
    if (separating > rest) continue;
    it.mu = geometry_.surfaces()[c.surface].friction;
    const Eigen::Vector3d vt = vp - separating * c.normal;
    joint_frame(c.normal, it.t1, it.t2);
    it.slip = Eigen::Vector3d::Zero();
    if (vt.norm() > rest)
      it.slip = vt.normalized();
    else
      it.from_rest = it.mu > 0;  // at rest: sticks or slips, found below
    // d2(gap)/dt2 beyond J nu': the centripetal acceleration of the point,
    // and for a point under a turning face the turning of the face's normal.
    const Eigen::Vector3d centripetal = vel.w.cross(vel.w.cross(it.arm));
    it.bias = c.normal.dot(centripetal);
    if (!c.on_fixed_plane()) it.bias += 2.0 * vel.w.cross(c.normal).dot(vp);
    items.push_back(it);
  }

  // One solution of the contact problem with the items' current states:
  // sliding contacts with friction mu N against their slip direction (none
  // while the direction is still unknown), sticking ones with tangential
  // rows held at zero acceleration.
  Eigen::VectorXd z;
  Eigen::Matrix<double, 6, 1> gen_force = f;
  auto solve_once = [&] {
    std::vector<Row> g_rows, h_rows;
    std::vector<double> bias;
    std::vector<bool> unilateral;
    for (const Item& it : items) {
      const Row jn = jacobian_row(it.c.normal, it.arm);
      g_rows.push_back(jn);
      h_rows.push_back(
          it.stuck || it.slip.isZero() ? jn : Row(jn - it.mu * jacobian_row(it.slip, it.arm)));
      bias.push_back(it.bias);
      unilateral.push_back(true);
    }
    for (const Item& it : items)
      if (it.stuck)
        for (const Eigen::Vector3d& t : {it.t1, it.t2}) {
          const Row jt = jacobian_row(t, it.arm);
          g_rows.push_back(jt);
          h_rows.push_back(jt);
          bias.push_back(t.dot(vel.w.cross(vel.w.cross(it.arm))));
          unilateral.push_back(false);
        }
    const int n = static_cast<int>(g_rows.size());
    Eigen::MatrixXd g(n, 6), h(n, 6);
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) {
      g.row(i) = g_rows[i];
      h.row(i) = h_rows[i];
      b(i) = bias[i];
    }
    const Eigen::MatrixXd w = g * minv * h.transpose();
    const Eigen::VectorXd q = g * (minv * f) + b;
    const MixedLcpResult r = solve_mixed_lcp(w, q, unilateral, kLcpRel * load_scale(),
                                             kLcpRel * gravity_, kLcpIterations);
    out.converged = r.converged;
    z = r.z;
    gen_force = f + h.transpose() * z;
  };
  // The tangential acceleration of an item's point in the current solution.
  auto tangential = [&](const Item& it) {
    const Eigen::Matrix<double, 6, 1> a = minv * gen_force;
    const Eigen::Vector3d ap =
        a.head<3>() + a.tail<3>().cross(it.arm) + vel.w.cross(vel.w.cross(it.arm));
    return Eigen::Vector3d(ap - ap.dot(it.c.normal) * it.c.normal);
  };
  // Contacts at rest: the block sticks or slips as a whole. They are
  // first let go without friction to see which way they would move; then
  // they slip with mu N against that way, refined to the way they then
  // accelerate, as long as friction does not turn them back. Where it
  // would (kinetic friction exceeds what drives them) they stick, and the
  // friction they need, within mu N, holds them. This is the consistent
  // choice of the two, and it is the same just above and just below the
  // rest speed, so that a block at its limit does not chatter.
  solve_once();
  bool any_at_rest = false;
  for (const Item& it : items) any_at_rest = any_at_rest || it.from_rest;
  if (any_at_rest) {
    bool sticks = false;
    for (Item& it : items)
      if (it.from_rest) {
        const Eigen::Vector3d at = tangential(it);
        if (at.norm() <= kLcpRel * gravity_)
          sticks = true;  // nothing drives it along its plane
        else
          it.slip = at.normalized();
      }
    for (int round = 0; round < kStickSlipRounds && !sticks; ++round) {
      solve_once();
      bool changed = false;
      for (Item& it : items) {
        if (!it.from_rest) continue;
        const Eigen::Vector3d at = tangential(it);
        if (at.dot(it.slip) <= kLcpRel * gravity_) {
          sticks = true;  // friction would turn it back
          break;
        }
        const Eigen::Vector3d dir = at.normalized();
        if ((dir - it.slip).norm() > 1e-12) changed = true;
        it.slip = dir;
      }
      if (!changed) break;
    }
    if (sticks) {
      for (Item& it : items)
        if (it.from_rest) {
          it.stuck = true;
          it.slip = Eigen::Vector3d::Zero();
        }
      solve_once();
    }
  }
  const Eigen::Matrix<double, 6, 1> acc = minv * gen_force;
  out.acceleration = acc.head<3>();
  out.angular_acceleration = acc.tail<3>();
  int k = static_cast<int>(items.size());
  for (size_t i = 0; i < items.size(); ++i) {
    const Item& it = items[i];
    out.contacts.push_back(it.c);
    out.normal.push_back(std::max(z(i), 0.0));
    out.slipping.push_back(!it.stuck);
    if (it.stuck) {
      out.friction.push_back(z(k) * it.t1 + z(k + 1) * it.t2);
      k += 2;
    } else {
      out.friction.push_back(-it.mu * std::max(z(i), 0.0) * it.slip);
    }
  }
  return out;
}

BlockMotion::Projection BlockMotion::project(BlockPose& pose, BlockVelocity& vel) const {
  Projection out;
  const double length = geometry_.length();
  const double bound = kDriftBoundRel * length;
  const double rest = kRestSpeedRel * std::sqrt(gravity_ * length);
  pose.q.normalize();
  // The contacts that carry load now are held closed (both ways); the other
  // closed ones must not penetrate.
  const ContactSolution loaded = solve(pose, vel);
  auto carries = [&](const JointContact& c) {
    for (size_t i = 0; i < loaded.contacts.size(); ++i)
      if (loaded.normal[i] > kLoadedForceRel * load_scale() &&
          (loaded.contacts[i].point - c.point).norm() <= kContactGapRel * length &&
          loaded.contacts[i].surface == c.surface)
        return true;
    return false;
  };
  for (int pass = 0; pass < 4; ++pass) {
    const Eigen::Vector3d centre = geometry_.centroid() + pose.u;
    const std::vector<JointContact> closed = geometry_.contacts(pose, kContactGapRel * length);
    std::vector<Row> rows;
    std::vector<double> gaps;
    std::vector<bool> unilateral;
    double drift = 0;
    for (const JointContact& c : closed) {
      const bool hold = carries(c);
      if (!hold && c.gap >= 0) continue;
      drift = std::max(drift, hold ? std::abs(c.gap) : -c.gap);
      rows.push_back(jacobian_row(c.normal, c.point - centre));
      gaps.push_back(c.gap);
      unilateral.push_back(!hold);
    }
    if (pass == 0) out.drift_before = drift;
    out.drift_after = drift;
    if (drift <= 0.01 * bound || rows.empty()) break;
    const Eigen::Matrix<double, 6, 1> delta =
        mass_weighted_correction(rows, gaps, unilateral, inverse_mass(mass_, inertia(pose)),
                                 1e-14 * mass_ * length, 1e-3 * bound);
    pose.u += delta.head<3>();
    pose.q = (rotation_quaternion(delta.tail<3>()) * pose.q).normalized();
  }
  // Velocities: loaded contacts move along their planes; closed contacts
  // moving into the rock stop (impulses >= 0: a plastic impact).
  {
    const Eigen::Vector3d centre = geometry_.centroid() + pose.u;
    std::vector<Row> rows;
    std::vector<double> speeds;
    std::vector<bool> unilateral;
    for (const JointContact& c : geometry_.contacts(pose, kContactGapRel * length)) {
      const Eigen::Vector3d arm = c.point - centre;
      const double s = c.normal.dot(vel.v + vel.w.cross(arm));
      const bool hold = carries(c);
      if (!hold && s >= -rest) continue;
      if (!hold) out.impact_speed = std::max(out.impact_speed, -s);
      rows.push_back(jacobian_row(c.normal, arm));
      speeds.push_back(s);
      unilateral.push_back(!hold);
    }
    if (!rows.empty()) {
      const Eigen::Matrix<double, 6, 1> dv =
          mass_weighted_correction(rows, speeds, unilateral, inverse_mass(mass_, inertia(pose)),
                                   1e-14 * mass_ * rest, 1e-3 * rest);
      vel.v += dv.head<3>();
      vel.w += dv.tail<3>();
    }
  }
  return out;
}

}  // namespace rockface::mechanics

#include "core/mechanics/block_equilibrium.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/mechanics/tolerances.h"

namespace rockface::mechanics {

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v(0), -v.y(), v(0), 0;
  return s;
}

}  // namespace

Eigen::Quaterniond rotation_quaternion(const Eigen::Vector3d& w) {
  const double angle = w.norm();
  if (!(angle > 0)) return Eigen::Quaterniond::Identity();
  // sin(angle / 2) / angle stays accurate down to angle = 0.
  const double half = 0.5 * angle;
  const double s = angle < 1e-4 ? 0.5 * (1.0 - half * half / 6.0) : std::sin(half) / angle;
  return Eigen::Quaterniond(std::cos(half), s * w(0), s * w.y(), s * w.z());
}

Eigen::Matrix3d rotation_left_jacobian(const Eigen::Vector3d& w) {
  const double a = w.norm();
  const Eigen::Matrix3d k = skew(w);
  // (1 - cos a) / a^2 and (a - sin a) / a^3, by their series at small angles.
  double c1 = 0.5 - a * a / 24.0, c2 = 1.0 / 6.0 - a * a / 120.0;
  if (a > 1e-3) {
    c1 = (1.0 - std::cos(a)) / (a * a);
    c2 = (a - std::sin(a)) / (a * a * a);
  }
  return Eigen::Matrix3d::Identity() + c1 * k + c2 * k * k;
}

Eigen::Vector3d rotation_offset(const Eigen::Quaterniond& q, const Eigen::Vector3d& r) {
  const Eigen::Vector3d v = q.vec();
  const Eigen::Vector3d vr = v.cross(r);
  return 2.0 * q.w() * vr + 2.0 * v.cross(vr);
}

BlockEquilibrium::BlockEquilibrium(const blocks::Polyhedron& block,
                                   const blocks::MassProperties& mass,
                                   std::vector<ContactPoint> contacts,
                                   std::vector<std::shared_ptr<const JointLaw>> plane_laws,
                                   BlockLoads loads,
                                   const std::optional<Eigen::Matrix3d>& insitu_stress)
    : contacts_(std::move(contacts)),
      plane_laws_(std::move(plane_laws)),
      loads_(std::move(loads)),
      centroid_(mass.centroid),
      mass_(mass.mass),
      inertia_(mass.inertia) {
  for (const auto& v : block.vertices()) vertex_arms_.push_back(v - centroid_);
  length_ = std::max(block.size(), 1e-300);
  double normal_stiffness = 0, joint_area = 0, insitu = 0, slip_scale = 0;
  for (const ContactPoint& c : contacts_) {
    if (c.plane < 0 || c.plane >= static_cast<int>(plane_laws_.size()) || !plane_laws_[c.plane])
      throw InputError("joints." + block.planes()[c.plane].name,
                       "no joint law for this joint face of block " + block.id());
    const JointLaw* law = plane_laws_[c.plane].get();
    laws_.push_back(law);
    arms_.push_back(c.position - centroid_);
    double c0 = 0;
    Eigen::Vector2d s0 = Eigen::Vector2d::Zero();
    if (insitu_stress) {
      const InsituTraction t = insitu_traction(*insitu_stress, c.normal);
      c0 = t.normal / law->normal_stiffness();
      // The spring's stress acts on the block against its shear: a shear
      // offset of -traction / ks gives the in-situ traction at rest.
      s0 = -Eigen::Vector2d(t.shear.dot(c.t1), t.shear.dot(c.t2)) / law->shear_stiffness();
      insitu = std::max(insitu, insitu_stress->cwiseAbs().maxCoeff());
    }
    closure0_.push_back(c0);
    shear0_.push_back(s0);
    normal_stiffness += law->normal_stiffness() * c.area;
    slip_scale = std::max(slip_scale, law->slip_scale());
    joint_area += c.area;
  }
  committed_.assign(contacts_.size(), JointState{});
  // The load the residual is measured against: the largest of the
  // resultant, any single load, and the in-situ stress over the joints.
  double load = loads_.force.norm();
  for (const RigidLoad& l : loads_.loads)
    load = std::max({load, l.force.norm(), l.couple.norm() / length_});
  load = std::max(load, insitu * joint_area);
  load_scale_ = load > 0 ? load : 1.0;
  displacement_scale_ = normal_stiffness > 0 ? load_scale_ / normal_stiffness : length_ * 1e-6;
  // A law whose strength develops over a slip far beyond the elastic
  // displacement (a stiff rough joint: 1e-8 m elastic, 1e-3 m to the peak)
  // would take 1e5 elastic units of path: steps are scaled to a hundredth
  // of that slip instead.
  displacement_scale_ = std::max(displacement_scale_, slip_scale * kSlipScaleFraction);
  slip_scale_ = slip_scale;
}

Vector6 BlockEquilibrium::unbalance(const Vector6& x, double load_factor, double divisor,
                                    std::vector<JointResponse>* responses,
                                    UnbalanceDerivatives* derivatives) const {
  const Eigen::Vector3d u = x.head<3>();
  const Eigen::Quaterniond q = rotation_quaternion(x.tail<3>());
  const Eigen::Matrix3d jl = derivatives ? rotation_left_jacobian(x.tail<3>()) : Eigen::Matrix3d();
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  if (responses) responses->resize(contacts_.size());
  if (derivatives) *derivatives = UnbalanceDerivatives{};
  for (size_t k = 0; k < contacts_.size(); ++k) {
    const ContactPoint& c = contacts_[k];
    const Eigen::Vector3d turn = rotation_offset(q, arms_[k]);
    const Eigen::Vector3d d = u + turn;
    const double closure = -d.dot(c.normal) + load_factor * closure0_[k];
    const Eigen::Vector2d shear =
        Eigen::Vector2d(d.dot(c.t1), d.dot(c.t2)) + load_factor * shear0_[k];
    JointResponse r = laws_[k]->respond(committed_[k], closure, shear, divisor);
    const Eigen::Vector3d f =
        c.area * (r.normal_stress * c.normal - r.shear_stress(0) * c.t1 - r.shear_stress(1) * c.t2);
    const Eigen::Vector3d arm = arms_[k] + turn;
    force += f;
    moment += arm.cross(f);
    if (derivatives && !r.tangent.isZero(0.0)) {
      // (closure, shear) = G d + load_factor (closure0, shear0); f = area H
      // (sigma, tau), H = -G^T; d(arm) / dx = [0, -[arm]x J_l].
      Eigen::Matrix3d g;
      g << -c.normal.transpose(), c.t1.transpose(), c.t2.transpose();
      Eigen::Matrix<double, 3, 6> d_arm = Eigen::Matrix<double, 3, 6>::Zero();
      d_arm.rightCols<3>() = -skew(arm) * jl;
      Eigen::Matrix<double, 3, 6> d_d = d_arm;
      d_d.leftCols<3>() = Eigen::Matrix3d::Identity();
      const Eigen::Matrix3d h = -c.area * g.transpose();
      const Eigen::Matrix<double, 3, 6> df = h * r.tangent * g * d_d;
      const Eigen::Vector3d df_load =
          h * r.tangent * Eigen::Vector3d(closure0_[k], shear0_[k](0), shear0_[k](1));
      const Eigen::Vector3d df_div = h * r.divisor_rate;
      derivatives->motion.topRows<3>() += df;
      derivatives->motion.bottomRows<3>() += skew(arm) * df - skew(f) * d_arm;
      derivatives->load_factor.head<3>() += df_load;
      derivatives->load_factor.tail<3>() += arm.cross(df_load);
      derivatives->divisor.head<3>() += df_div;
      derivatives->divisor.tail<3>() += arm.cross(df_div);
    }
    if (responses) (*responses)[k] = std::move(r);
  }
  for (const RigidLoad& l : loads_.loads) {
    const Eigen::Vector3d arm = l.arm + rotation_offset(q, l.arm);
    const Eigen::Vector3d unit_force = l.follower ? q * l.force : l.force;
    const Eigen::Vector3d unit_couple = l.follower ? q * l.couple : l.couple;
    const Eigen::Vector3d f = load_factor * unit_force;
    force += f;
    moment += arm.cross(f) + load_factor * unit_couple;
    if (derivatives) {
      const Eigen::Matrix3d d_arm = -skew(arm) * jl;
      derivatives->motion.bottomRightCorner<3, 3>() -= skew(f) * d_arm;
      if (l.follower) {
        const Eigen::Matrix3d df = -load_factor * skew(unit_force) * jl;
        derivatives->motion.topRightCorner<3, 3>() += df;
        derivatives->motion.bottomRightCorner<3, 3>() +=
            skew(arm) * df - load_factor * skew(unit_couple) * jl;
      }
      derivatives->load_factor.head<3>() += unit_force;
      derivatives->load_factor.tail<3>() += arm.cross(unit_force) + unit_couple;
    }
  }
  Vector6 out;
  out << force, moment;
  return out;
}

void BlockEquilibrium::commit(const Vector6& x, double load_factor, double divisor) {
  std::vector<JointResponse> responses;
  unbalance(x, load_factor, divisor, &responses);
  for (size_t k = 0; k < responses.size(); ++k) committed_[k] = responses[k].state;
}

Matrix6 BlockEquilibrium::elastic_stiffness() const {
  Matrix6 k = Matrix6::Zero();
  for (size_t i = 0; i < contacts_.size(); ++i) {
    const ContactPoint& c = contacts_[i];
    const Eigen::Matrix3d nn = c.normal * c.normal.transpose();
    const Eigen::Matrix3d d =
        c.area * (laws_[i]->normal_stiffness() * nn +
                  laws_[i]->shear_stiffness() * (Eigen::Matrix3d::Identity() - nn));
    Eigen::Matrix<double, 3, 6> b;
    b << Eigen::Matrix3d::Identity(), -skew(arms_[i]);
    Eigen::Matrix<double, 6, 3> bt;
    bt << Eigen::Matrix3d::Identity(), skew(arms_[i]);
    k += bt * d * b;
  }
  return k;
}

Matrix6 BlockEquilibrium::mass_matrix() const {
  Matrix6 m = Matrix6::Zero();
  m.topLeftCorner<3, 3>() = mass_ * Eigen::Matrix3d::Identity();
  m.bottomRightCorner<3, 3>() = inertia_;
  return m;
}

}  // namespace rockface::mechanics

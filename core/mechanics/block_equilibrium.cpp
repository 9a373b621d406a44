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
}

Vector6 BlockEquilibrium::unbalance(const Vector6& x, double load_factor, double divisor,
                                    std::vector<JointResponse>* responses) const {
  const Eigen::Vector3d u = x.head<3>();
  const Eigen::Quaterniond q = rotation_quaternion(x.tail<3>());
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  if (responses) responses->resize(contacts_.size());
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
    force += f;
    moment += (arms_[k] + turn).cross(f);
    if (responses) (*responses)[k] = std::move(r);
  }
  for (const RigidLoad& l : loads_.loads) {
    const Eigen::Vector3d arm = l.arm + rotation_offset(q, l.arm);
    const Eigen::Vector3d f = load_factor * (l.follower ? q * l.force : l.force);
    force += f;
    moment += arm.cross(f) + load_factor * (l.follower ? q * l.couple : l.couple);
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

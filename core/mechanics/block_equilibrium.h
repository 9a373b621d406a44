#pragma once
// One rigid block on its joints: contact points with the joint law, loads
// from the scene's effects, in-situ stress as the joints' initial state.
// The block's motion is x = (u, theta): the translation of its centroid and
// its rotation vector; the rotation itself is a unit quaternion (Euler
// parameters), so large rotations stay exact. A material point at r from
// the centroid moves by u + (R - I) r.
//
// Each contact is a normal and a shear spring in series with the joint's
// slip and dilation (joint_law.h): the relative displacement of the block
// against the fixed rock at the contact gives closure (along minus the
// block-side normal) and shear (in the joint frame); the law's tractions
// act on the block at the contact's displaced position.
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/blocks/mass_properties.h"
#include "core/blocks/polyhedron.h"
#include "core/mechanics/block_loads.h"
#include "core/mechanics/contact_points.h"
#include "core/mechanics/joint_law.h"

namespace rockface::mechanics {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

// The unit quaternion of a rotation vector (angle x unit axis).
Eigen::Quaterniond rotation_quaternion(const Eigen::Vector3d& rotation_vector);
// The left Jacobian of the rotation vector: R(w + dw) = Exp(J_l(w) dw) R(w)
// to first order, so d(R r)/dw = -[R r]x J_l(w).
Eigen::Matrix3d rotation_left_jacobian(const Eigen::Vector3d& rotation_vector);
// (R - I) r for the rotation q, without the cancellation of R r - r at
// tiny angles: 2 w (v x r) + 2 v x (v x r), q = (w, v).
Eigen::Vector3d rotation_offset(const Eigen::Quaterniond& q, const Eigen::Vector3d& r);

// The derivatives of BlockEquilibrium::unbalance, from the joint laws'
// consistent tangents and the exact kinematics of the rotation.
struct UnbalanceDerivatives {
  Matrix6 motion = Matrix6::Zero();       // d unbalance / dx
  Vector6 load_factor = Vector6::Zero();  // d unbalance / d load_factor
  Vector6 divisor = Vector6::Zero();      // d unbalance / d divisor
};

class BlockEquilibrium {
 public:
  // plane_laws: one per polyhedron plane; every plane carrying contacts
  // needs one (InputError naming the plane otherwise).
  BlockEquilibrium(const blocks::Polyhedron& block, const blocks::MassProperties& mass,
                   std::vector<ContactPoint> contacts,
                   std::vector<std::shared_ptr<const JointLaw>> plane_laws, BlockLoads loads,
                   const std::optional<Eigen::Matrix3d>& insitu_stress);

  // Force and moment (about the displaced centroid) on the block in the
  // motion x, loads and in-situ stress times load_factor, shear strengths
  // divided by divisor, from the committed joint states. Zero in
  // equilibrium.
  // derivatives: filled when given.
  Vector6 unbalance(const Vector6& x, double load_factor, double divisor,
                    std::vector<JointResponse>* responses = nullptr,
                    UnbalanceDerivatives* derivatives = nullptr) const;
  // Accepts the motion: the joints' states move on.
  void commit(const Vector6& x, double load_factor, double divisor);

  // K = -d unbalance / dx at x = 0 with every contact closed and sticking.
  Matrix6 elastic_stiffness() const;
  // diag(m, m, m, I_centroid).
  Matrix6 mass_matrix() const;

  double load_scale() const { return load_scale_; }                  // N
  double length() const { return length_; }                          // m
  double displacement_scale() const { return displacement_scale_; }  // m, the path's unit
  double slip_scale() const { return slip_scale_; }  // m, the largest of the laws' (0: none)
  const std::vector<ContactPoint>& contacts() const { return contacts_; }
  const std::vector<JointState>& committed() const { return committed_; }
  const BlockLoads& loads() const { return loads_; }
  const Eigen::Vector3d& centroid() const { return centroid_; }  // datum-relative
  // Vertices relative to the centroid (initial position).
  const std::vector<Eigen::Vector3d>& vertex_arms() const { return vertex_arms_; }

 private:
  std::vector<ContactPoint> contacts_;
  std::vector<Eigen::Vector3d> arms_;  // contact position - centroid
  std::vector<const JointLaw*> laws_;  // per contact
  std::vector<std::shared_ptr<const JointLaw>> plane_laws_;
  std::vector<double> closure0_;         // in-situ closure of each contact, m
  std::vector<Eigen::Vector2d> shear0_;  // in-situ shear offset, m (joint frame)
  std::vector<JointState> committed_;
  BlockLoads loads_;
  Eigen::Vector3d centroid_;
  double mass_ = 0;
  Eigen::Matrix3d inertia_;
  std::vector<Eigen::Vector3d> vertex_arms_;
  double load_scale_ = 1, length_ = 1, displacement_scale_ = 1, slip_scale_ = 0;
};

}  // namespace rockface::mechanics

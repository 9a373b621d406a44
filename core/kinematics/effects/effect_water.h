#pragma once
// Water pressure on the joint faces of a block. The phreatic surface is a
// plane; the pressure at a point is unit_weight x the height of the
// phreatic plane above it (measured vertically), and zero above the plane.
// On each wetted joint face the pressure is integrated exactly: the face
// polygon is clipped at the phreatic plane and the linear pressure is
// integrated over the wetted triangles, giving the force (along the face's
// block-side normal: water pushes the block off the joint) and its centre
// of pressure. Free faces are open to the air and carry no water.
#include <vector>

#include "core/kinematics/effects/effect.h"

namespace rockface::kinematics {

class WaterEffect final : public Effect {
 public:
  // phreatic_point: absolute; phreatic_normal: upward unit normal of the
  // phreatic plane (not vertical: a vertical plane has no height above a
  // point, which is an InputError). joints: caller plane indices of the
  // joints carrying water; empty = every joint.
  WaterEffect(double unit_weight, const Eigen::Vector3d& phreatic_point,
              const Eigen::Vector3d& phreatic_normal, std::vector<int> joints = {});
  std::string name() const override { return "water"; }
  EffectLoad load(const blocks::Polyhedron& block,
                  const blocks::MassProperties& mass) const override;

  // Pressure (Pa) at an absolute point.
  double pressure_at(const Eigen::Vector3d& absolute_point) const;

 private:
  bool carries_water(const blocks::BlockPlane& plane) const;

  double unit_weight_;
  Eigen::Vector3d point_;
  Eigen::Vector3d normal_;
  std::vector<int> joints_;
};

}  // namespace rockface::kinematics

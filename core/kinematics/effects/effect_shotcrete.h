#pragma once
// A shotcrete lining over a block's free faces (UnWedge's shotcrete
// support): to come out, the block must punch through the lining along the
// outline of its exposed faces. The lining resists with its shear strength
// times its thickness times that outline's length (the edges where a free
// face meets a joint face), acting against the block's failure direction.
// The resistance is a capacity, not a load that pushes: the caller gives the
// direction the block would move in without it (the translational mode of
// the unsupported block), and the force acts opposite to it, at the centroid
// of the exposed faces. A block with no free face (inside the rock mass) has
// no lining and the effect says so.
#include "core/kinematics/effects/effect.h"

namespace rockface::kinematics {

// Length (m) of the outline of the block's free faces: the edges between a
// free face and a joint face.
double free_face_outline(const blocks::Polyhedron& block);

class ShotcreteEffect final : public Effect {
 public:
  // thickness m (> 0), shear_strength Pa (> 0); failure_direction: the
  // direction the unsupported block moves in (need not be unit, not zero).
  // Throws InputError naming `label` for a bad value.
  ShotcreteEffect(std::string label, double thickness, double shear_strength,
                  const Eigen::Vector3d& failure_direction);
  std::string name() const override { return "shotcrete"; }
  EffectLoad load(const blocks::Polyhedron& block,
                  const blocks::MassProperties& mass) const override;
  // The capacity in newtons for a given outline length.
  double capacity(double outline_m) const { return thickness_ * shear_strength_ * outline_m; }

 private:
  std::string label_;
  double thickness_, shear_strength_;
  Eigen::Vector3d direction_;
};

}  // namespace rockface::kinematics

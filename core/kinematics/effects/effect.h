#pragma once
// One effect acting on a block (DESIGN.md, "Effects"): gravity, water
// pressure, seismic acceleration, applied forces, bolts. Each is a small
// module behind this interface, and an analysis assembles exactly the
// effects its scene lists.
//
// An effect gives the force on the block and its moment about the block's
// centroid, in the block's current (here: initial) position, and may give a
// stiffness contribution for the mechanics that will follow (zero for loads
// that do not depend on the block's displacement). Points given to effects
// are absolute; effects subtract the block's datum themselves.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/mass_properties.h"
#include "core/blocks/polyhedron.h"

namespace rockface::kinematics {

// A force one effect puts on one face (water pressure): its resultant, where
// it acts and its component along the face's block-side normal (> 0 pushes
// the block away from the face).
struct FaceLoad {
  int face = -1;
  int plane = -1;  // index into the polyhedron's planes()
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // datum-relative centre of pressure
  double normal = 0;                                // N along the block-side normal
};

struct EffectLoad {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // N m, about the block's centroid
  std::vector<FaceLoad> faces;                       // per-face parts, where the effect has them
  bool acts = false;               // false: listed, but nothing of it reaches this block
  std::vector<std::string> notes;  // e.g. why it does not act
};

class Effect {
 public:
  virtual ~Effect() = default;
  // The name of SCENE.md's effects list ("gravity", "water", ...).
  virtual std::string name() const = 0;
  virtual EffectLoad load(const blocks::Polyhedron& block,
                          const blocks::MassProperties& mass) const = 0;
  // d(force, moment) / d(translation, rotation) about the centroid, 6x6.
  // Zero for loads fixed in space; followers and springs override it.
  virtual Eigen::Matrix<double, 6, 6> stiffness(const blocks::Polyhedron& block,
                                                const blocks::MassProperties& mass) const {
    (void)block;
    (void)mass;
    return Eigen::Matrix<double, 6, 6>::Zero();
  }
};

using Effects = std::vector<std::unique_ptr<Effect>>;

}  // namespace rockface::kinematics

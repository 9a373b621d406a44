#pragma once
// The scene's effects (core/kinematics/effects/effect_*.h) as loads on a rigid
// block that moves and turns: each load is a force at a point fixed in the
// block, either fixed in direction (gravity, seismic, bolts, "space"
// forces) or following the block's rotation (water pressure on a joint
// face, "block" forces). Pure couples stay fixed in space.
//
// In-situ stress is not a load but the initial state of the joints: on a
// joint face with block-side normal n the rock pushes the block with the
// traction sigma n (compression positive), which the contacts carry from
// the start (an initial normal closure and shear offset of their springs).
// Excavating the free faces removes their share of the self-equilibrated
// traction: the imbalance that remains is what the excavation loads the
// block with.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/mass_properties.h"
#include "core/blocks/polyhedron.h"
#include "core/kinematics/effects/effect.h"

namespace rockface::mechanics {

struct RigidLoad {
  std::string effect;                                // "gravity", "water", ...
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N, in the initial position
  Eigen::Vector3d arm = Eigen::Vector3d::Zero();     // point of action - centroid (initial)
  Eigen::Vector3d couple = Eigen::Vector3d::Zero();  // N m, a moment without a force
  bool follower = false;                             // turns with the block
};

struct BlockLoads {
  std::vector<RigidLoad> loads;
  std::vector<std::string> effects_used;            // names of the effects that act on the block
  std::vector<std::string> notes;                   // why a listed effect does not act
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // resultant in the initial position, N
};

BlockLoads block_loads(const blocks::Polyhedron& block, const blocks::MassProperties& mass,
                       const kinematics::Effects& effects);

// Initial tractions of the in-situ stress on a joint contact with
// block-side normal n: normal stress (Pa, compression positive) and the
// shear traction the rock puts on the block (Pa, global frame).
struct InsituTraction {
  double normal = 0;
  Eigen::Vector3d shear = Eigen::Vector3d::Zero();
};
InsituTraction insitu_traction(const Eigen::Matrix3d& stress, const Eigen::Vector3d& n);

}  // namespace rockface::mechanics

#pragma once
// What the dynamics tests share: friction per plane, the slab's run and
// the closed forms they are checked against.
#include <cmath>
#include <string>
#include <vector>

#include "core/blocks/mass_properties.h"
#include "core/mechanics/dynamics/block_dynamics.h"
#include "tests/support/mechanics_blocks.h"

namespace rockface::mechanics::testing {

inline constexpr double kG = 9.81;

// The same friction angle (degrees) on every joint plane of the block.
inline std::vector<double> friction_on_joints(const blocks::Polyhedron& p, double phi_deg) {
  std::vector<double> out(p.planes().size(), 0.0);
  for (size_t i = 0; i < out.size(); ++i)
    if (p.planes()[i].kind == blocks::PlaneKind::Joint) out[i] = phi_deg;
  return out;
}

inline BlockDynamics run(const blocks::Polyhedron& block, double phi_deg,
                         const kinematics::Effects& effects, DynamicsOptions o) {
  const blocks::MassProperties mass = blocks::mass_properties(block, 2700);
  return simulate_block_motion(block, mass, effects, friction_on_joints(block, phi_deg), o);
}

inline DynamicsOptions options(double duration, double sample) {
  DynamicsOptions o = dynamics_options(Preset::standard);
  o.duration = duration;
  o.sample = sample;
  return o;
}

inline const MotionEvent* find_event(const BlockDynamics& d, const std::string& kind) {
  for (const MotionEvent& e : d.events)
    if (e.kind == kind) return &e;
  return nullptr;
}

}  // namespace rockface::mechanics::testing

#pragma once
// A direct shear test on the joint law: the laboratory path the law's
// curves are checked against. The shear displacement follows a given
// sequence (monotone or cyclic); the normal displacement adjusts so that
// the normal stress is constant (CNL) or grows with the joint's opening
// against a spring (CNS: sigma_n = sigma_n0 + K x opening).
#include <vector>

#include "core/mechanics/joint_law.h"

namespace rockface::mechanics {

struct ShearTestBoundary {
  double normal_stress = 1e6;   // sigma_n0, Pa
  double normal_stiffness = 0;  // K of the CNS spring, Pa/m; 0: constant normal load
};

struct ShearTestPoint {
  double shear = 0;          // imposed shear displacement, m
  double shear_stress = 0;   // Pa (signed along the shear axis)
  double normal_stress = 0;  // Pa
  double opening = 0;        // normal displacement of the upper half, m (> 0: dilates)
  JointStage stage = JointStage::Elastic;
  JointState state;
};

// One point per imposed displacement, along the joint's first axis.
// Throws rockface::Error if the normal stress cannot be held (the joint
// opens under a tensile boundary).
std::vector<ShearTestPoint> shear_test(const JointLaw& law, const ShearTestBoundary& boundary,
                                       const std::vector<double>& shear_path);

}  // namespace rockface::mechanics

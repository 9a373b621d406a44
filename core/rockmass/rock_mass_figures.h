#pragma once
// The rock mass of one visit in figures, assembled: the face window, the
// traces given to sets, spacing, persistence, scanline RQD, Jv, block
// sizes, and RMR89 and Q with the measured lines filled from them and the
// rest from the form.
#include <optional>
#include <string>
#include <vector>

#include "core/rockmass/block_sizes.h"
#include "core/rockmass/classification_form.h"
#include "core/rockmass/persistence.h"
#include "core/rockmass/q_system.h"
#include "core/rockmass/rmr89.h"
#include "core/rockmass/scanline_rqd.h"
#include "core/rockmass/volumetric_joint_count.h"

namespace rockface::rockmass {

// A set's class against the drive (core/tunnel/strike_vs_drive.h, computed
// by the caller: this part may not include core/tunnel).
struct SetAgainstDrive {
  std::string label;
  OrientationClass cls = OrientationClass::fair;
  std::string words;  // "strike parallel to the axis, dip 45-90: very unfavourable"
  double margin_deg = 0;
  bool marginal = false;
};

struct RockMassInput {
  std::vector<FaceTrace> traces;
  std::vector<SetInput> sets;
  std::vector<Eigen::Vector3d> outline_points;  // the window's; empty: the traces' points
  std::vector<FaceBlock> blocks;                // finite blocks of the face
  std::vector<SetAgainstDrive> drive;           // empty: no tunnel / visit not placed
  std::optional<double> tunnel_span_m;          // the design profile's width
  ClassificationForm form;
};

struct RockMassFigures {
  FaceWindow window;
  SetTraces assigned;
  std::vector<SetSpacing> spacings;
  std::vector<SetPersistence> persistence;
  ScanlineRqd scanlines;
  VolumetricJointCount jv;
  BlockSizes blocks;
  int sets = 0;
  bool random_joints = false;
  MeasuredForRmr measured_rmr;
  MeasuredForQ measured_q;
  std::vector<SetAgainstDrive> drive;
  ClassificationForm form;  // as used (the tunnel's span filled where not entered)
  Rmr89 rmr;
  QSystem q;
  std::vector<std::string> notes;
};

// Throws InputError naming the field for a form value out of range, and
// ("face", ...) when there is nothing to make a window of.
RockMassFigures rock_mass_figures(const RockMassInput& input);

}  // namespace rockface::rockmass

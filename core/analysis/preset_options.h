#pragma once
// Every knob that trades accuracy for time, put together per preset in one
// place (DESIGN.md "Accuracy costs time", issue 37). Each component keeps its
// own options and its own mapping from the preset beside it (the reason to
// change a knob lives there, next to the code it tunes); this struct gathers
// them so that a caller takes a preset's options from here, and a reader
// sees in one list what `fast`, `standard` and `precise` switch. What each
// knob costs and gains is measured in tools/bench and written in
// docs/accuracy-cost.md.
#include "core/common/preset.h"
#include "core/measure/facets/facet_options.h"
#include "core/measure/proposals/trace_proposals.h"
#include "core/mechanics/dynamics/block_dynamics.h"
#include "core/mechanics/equilibrium_path.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "core/tunnel/profile_deviation.h"

namespace rockface::analysis {

struct PresetOptions {
  Preset preset = Preset::standard;
  // Two-view reconstruction: feature count and image scale, dense image
  // scale and disparity search, mesh lattice (reconstruction/preset.h).
  photogrammetry::ReconstructionPreset reconstruction;
  // Facets found on the 3D image (facets/facet_options.h) and the traces
  // proposed on the photograph (proposals/trace_proposals.h).
  measure::FacetOptions facets;
  measure::ProposalOptions proposals;
  // Random starts of the remote-axis rotation search (remote_axis.h).
  int remote_axis_starts = 64;
  // Equilibrium path: contact points per joint face and continuation step
  // (equilibrium_path.h); the motion after failure: the stepper's error
  // control and largest step (dynamics/block_dynamics.h).
  mechanics::MechanicsOptions mechanics;
  mechanics::DynamicsOptions dynamics;
  // The tunnel: over / underbreak sections and rays (profile_deviation.h),
  // the chords of the profile's arcs in the wedge search (wedge_analysis.h).
  tunnel::DeviationOptions deviation;
  double wedge_sagitta_m = 0.002;
};

// Each component's options of `preset`, as the component's own mapping
// gives them.
PresetOptions preset_options(Preset preset);

}  // namespace rockface::analysis

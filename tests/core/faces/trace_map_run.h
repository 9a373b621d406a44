#pragma once
// The whole trace-map pipeline for the faces tests: surface, network, loops
// and blocks under gravity alone.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "core/common/progress.h"
#include "core/faces/free_surface.h"
#include "core/faces/surface_loops.h"
#include "core/faces/trace_blocks.h"
#include "core/faces/trace_network.h"
#include "core/kinematics/effects/effect_gravity.h"

namespace rockface::faces::testing {

struct TraceMapRun {
  std::size_t surface_patches = 0;  // after non-convex patches are split
  std::vector<TraceBlock> blocks;
  std::vector<std::string> notes;  // the network's
};

// network_uncertainty: radians below which two trace planes count as one;
// block_uncertainty: radians behind the block verdicts.
inline TraceMapRun run_trace_map(const std::vector<PatchInput>& patches,
                                 const std::vector<TraceInput>& traces, double snap,
                                 double network_uncertainty, double block_uncertainty) {
  const FreeSurface surface = FreeSurface::build(patches, snap);
  const TraceNetwork net = TraceNetwork::build(surface, traces, {snap, network_uncertainty});
  const SurfaceLoops loops = SurfaceLoops::find(net, surface);
  kinematics::Effects effects;
  effects.push_back(std::make_unique<kinematics::GravityEffect>(Eigen::Vector3d(0, 0, -9.81)));
  TraceBlockOptions options;
  options.snap_tolerance = snap;
  options.orientation_uncertainty = block_uncertainty;
  options.effects = &effects;
  NoProgress progress;
  return {surface.patches().size(), trace_blocks(surface, net, loops, options, progress),
          net.notes()};
}

}  // namespace rockface::faces::testing

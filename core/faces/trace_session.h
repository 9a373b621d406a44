#pragma once
// Incremental analysis of a trace map (issue 17): the UI edits one trace at
// a time (adds it, moves it) and wants the verdicts again at once.
//
// The trace network and its loops are rebuilt from all traces (snapping,
// crossings and Lu's rule are global, and cheap next to the blocks); the
// blocks are recomputed only for the regions whose inputs changed. A
// region's block depends only on its loops (their corners, the joint planes
// of their stretches with strengths and uncertainties, the patches under
// them and the angles at their corners), its faces and the patches it
// covers, given the surface and the options, which a session keeps fixed.
// Those inputs, written exactly (the bits of every number), are the region's key:
// a region whose key the last update had reuses that block (with the
// region index, trace indices and plane groups of the new map), all others
// are computed. So update() returns exactly what trace_blocks() returns for
// the same traces (tests/core/faces/trace_session_test.cpp).
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/common/progress.h"
#include "core/faces/free_surface.h"
#include "core/faces/surface_loops.h"
#include "core/faces/trace_blocks.h"
#include "core/faces/trace_network.h"

namespace rockface::faces {

class TraceSession {
 public:
  // The surface is built here once (FreeSurface::build, which throws
  // InputError for a bad patch). options.effects must outlive the session.
  TraceSession(const std::vector<PatchInput>& patches, const NetworkOptions& network_options,
               const TraceBlockOptions& options);

  // The blocks of these traces (all of them, after an edit), in the order
  // of trace_blocks(). Checks progress between recomputed regions.
  const std::vector<TraceBlock>& update(const std::vector<TraceInput>& traces, Progress& progress);

  const std::vector<TraceBlock>& blocks() const { return blocks_; }
  const FreeSurface& surface() const { return surface_; }
  const TraceNetwork& network() const { return network_; }
  const SurfaceLoops& loops() const { return loops_; }
  // Regions computed and reused by the last update.
  int recomputed() const { return recomputed_; }
  int reused() const { return reused_; }

 private:
  FreeSurface surface_;
  NetworkOptions network_options_;
  TraceBlockOptions options_;
  TraceNetwork network_;
  SurfaceLoops loops_;
  // Region key -> index into blocks_, -1 for a region without a block. The
  // next update moves the blocks it reuses out of blocks_ (a block holds its
  // polyhedron and analysis: copying 1,600 of them per edit cost more than
  // the two regions an edit recomputes).
  std::unordered_map<std::string, int> cache_;
  std::vector<TraceBlock> blocks_;
  int recomputed_ = 0, reused_ = 0;
};

// The key of region r (see above).
std::string trace_region_key(const TraceNetwork& network, const SurfaceLoops& loops, int r);

}  // namespace rockface::faces

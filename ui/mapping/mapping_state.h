#pragma once
// The Mapping screen's own state: the trace being marked, the joint it goes
// to, the blocks of the map, the proposals, the face outline and the compass.
#include <string>

#include "ui/mapping/compass_entry.h"
#include "ui/mapping/face_outline.h"
#include "ui/mapping/map_blocks.h"
#include "ui/mapping/proposals_view.h"
#include "ui/mapping/trace_marker.h"

namespace rockface::ui {

struct MappingState {
  TraceMarker marker;        // the trace being marked
  std::string joint_label;   // joint (set) the next trace is assigned to; empty: none
  MapBlocksState blocks;     // the blocks the saved traces cut out, updated after each edit
  ProposalsState proposals;  // trace proposals to accept, correct or reject (issue 25)
  // Issue 27: "Outline the face": taps mark the mapped face's corners
  // instead of a trace while `outlining`.
  FaceOutline outline;
  bool outlining = false;
  // Issue 27: a compass reading for the trace being marked or a saved one.
  CompassEntry compass;
};

}  // namespace rockface::ui

#pragma once
// Pieces of one joint trace measured on different pairs' 3D images (in the
// face frame) joined into one trace: its plane fitted to all pieces'
// samples, its length along the joined points, and its censoring from its
// own ends, not from where one piece hands over to the next.
#include <string>
#include <vector>

#include "core/measure/pick_measurement.h"
#include "core/measure/plane_measurement.h"
#include "core/photogrammetry/surface/trace_pieces.h"

namespace rockface::measure {

// The measured traces as pieces in the face frame: their measured points,
// each on the pair of its photograph (the first pair for 3D points).
std::vector<photogrammetry::TracePiece> trace_pieces(const MeasuredPicks& measured);

// Of `faces` (join_trace_pieces of pieces named by the traces of
// `measured`), the ones whose pieces lie on different pairs, each with the
// plane fitted to all its pieces' measured samples and its length.
std::vector<JoinedTrace> joined_traces(std::vector<photogrammetry::FaceTrace> faces,
                                       const MeasuredPicks& measured,
                                       const MeasureSettings& settings);

// "T1: one trace across the pairs' photographs (T1, T4)".
std::string joined_note(const JoinedTrace& joined);

}  // namespace rockface::measure

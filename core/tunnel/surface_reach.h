#pragma once
// A visit's excavated surface read along the tunnel: its rock as places on
// the alignment, and how far that rock reaches along the drive.
#include <optional>
#include <vector>

#include "core/tunnel/alignment.h"
#include "core/tunnel/profile_deviation.h"

namespace rockface::tunnel {

// The surface's rock placed along the tunnel: every k-th vertex that is rock
// (20,000 places give the percentiles below to well under a millimetre).
// Reads the per-vertex mask only (empty = all rock).
std::vector<AlignmentPlace> rock_places(const Alignment& alignment, const SurfaceInput& surface);

// How far the rock reaches along the drive: the 2nd percentile of chainage
// in the drive direction (the rear of the walls the cameras saw) and the
// 99th (the face), so that a few stray points count for nothing. Nothing
// when there is no rock.
// `first` is the rock's rearmost chainage itself: the round is measured
// from there, every cross-section that meets the surface (issue 38: from
// the 2nd percentile, part of a break both photographs saw was left out).
struct SurfaceReach {
  double rear = 0, front = 0;  // chainages
  double first = 0;
};
std::optional<SurfaceReach> surface_reach(const Alignment& alignment,
                                          const std::vector<AlignmentPlace>& places);

}  // namespace rockface::tunnel

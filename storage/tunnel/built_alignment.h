#pragma once
// The tunnel's alignment built from a surveyor's table, kept for the
// process so that a table is built once per datum. A replay used one table
// six times (the table's check when read, the scene's check, the typed
// pole, the rendered round, the project's check, the placement): a table of
// 10^6 rows took ~1 s of CPU each time (issue 41). The last alignment built
// is kept with the stations, radii and datum it was built from, and served
// again only when they are the same numbers (exactly: the same table read
// again or copied), so nothing stale is ever returned; another table or
// another datum is built and replaces it.
//
// Kept here, not in the table or the record that carry the stations: those
// types are in nearly every file's includes (through the project store and
// the scene), and one entry serves every copy of them.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/alignment.h"

namespace rockface::storage {

// The alignment of these stations (radii empty for a polyline) relative to
// datum, in the drive direction: the kept one when it was built from the
// same stations, radii and datum (the drive only orients the frames, and is
// set on the copy returned), else built and kept. Throws what
// tunnel::Alignment's builders throw (nothing is kept then). Thread-safe.
tunnel::Alignment built_alignment(const std::vector<tunnel::AlignmentStation>& stations,
                                  const std::vector<double>& radii, bool polyline,
                                  tunnel::Drive drive, const Eigen::Vector3d& datum);

// How many alignments built_alignment() has built in this process (what the
// tests count).
std::size_t alignment_builds();

}  // namespace rockface::storage

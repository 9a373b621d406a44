#pragma once
// The alignment built from a surveyor's table, kept with the table so that
// it is built once per datum. A replay used the one table six times (the
// scene's check, the typed pole, the rendered round, the project's check,
// the placement): a table of 10^6 rows took ~1 s of CPU each time (issue
// 41). Copies of a table or a tunnel record share one BuiltAlignment; a
// table changed after the build, or another datum, is built again (the
// kept alignment holds the stations it was built from and is compared with
// them), so nothing stale is ever returned.
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/alignment.h"

namespace rockface::storage {

class BuiltAlignment {
 public:
  // The alignment of these stations (radii empty for a polyline) relative
  // to datum, in the drive direction; built (and kept) unless the kept one
  // was built from the same stations, radii and datum. Throws what
  // tunnel::Alignment's builders throw.
  tunnel::Alignment get(const std::vector<tunnel::AlignmentStation>& stations,
                        const std::vector<double>& radii, bool polyline, tunnel::Drive drive,
                        const Eigen::Vector3d& datum);
  // How many times an alignment was built here (what tests count).
  std::size_t builds() const;

 private:
  mutable std::mutex mutex_;
  std::optional<tunnel::Alignment> kept_;
  std::size_t builds_ = 0;
};

}  // namespace rockface::storage

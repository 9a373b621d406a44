#include "storage/tunnel/tunnel_records.h"

#include "storage/tunnel/built_alignment.h"

namespace rockface::storage {

// Built once per table and datum for the process (built_alignment.h): a
// replay asks for it five times.
tunnel::Alignment TunnelRecord::alignment(const Eigen::Vector3d& datum) const {
  return built_alignment(stations, radii, polyline, drive, datum);
}

}  // namespace rockface::storage

#include "storage/tunnel/tunnel_records.h"

namespace rockface::storage {

tunnel::Alignment TunnelRecord::alignment(const Eigen::Vector3d& datum) const {
  return built->get(stations, radii, polyline, drive, datum);
}

}  // namespace rockface::storage

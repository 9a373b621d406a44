#include "storage/tunnel/built_alignment.h"

namespace rockface::storage {

namespace {

bool same_stations(const std::vector<tunnel::AlignmentStation>& a,
                   const std::vector<tunnel::AlignmentStation>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].chainage != b[i].chainage || a[i].survey != b[i].survey) return false;
  return true;
}

}  // namespace

tunnel::Alignment BuiltAlignment::get(const std::vector<tunnel::AlignmentStation>& stations,
                                      const std::vector<double>& radii, bool polyline,
                                      tunnel::Drive drive, const Eigen::Vector3d& datum) {
  std::lock_guard<std::mutex> lock(mutex_);
  // The kept one is this table's when it was built from the same numbers
  // (exactly: the table is the same text read again or copied). The drive
  // only orients its frames, so it is set on the copy.
  const bool same = kept_ && kept_->is_polyline() == polyline && kept_->datum() == datum &&
                    (polyline || kept_->radii() == radii) &&
                    same_stations(kept_->stations(), stations);
  if (!same) {
    kept_.reset();
    kept_ = polyline ? tunnel::Alignment::from_polyline(stations, datum, drive)
                     : tunnel::Alignment::from_elements(stations, radii, datum, drive);
    ++builds_;
  }
  tunnel::Alignment out = *kept_;
  out.set_drive(drive);
  return out;
}

std::size_t BuiltAlignment::builds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return builds_;
}

}  // namespace rockface::storage

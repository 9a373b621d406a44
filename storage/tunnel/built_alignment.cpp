#include "storage/tunnel/built_alignment.h"

#include <memory>
#include <mutex>

namespace rockface::storage {

namespace {

bool same_stations(const std::vector<tunnel::AlignmentStation>& a,
                   const std::vector<tunnel::AlignmentStation>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].chainage != b[i].chainage || a[i].survey != b[i].survey) return false;
  return true;
}

// The one alignment kept. A shared pointer, so that the copy handed out is
// made after the lock is released while a new build may replace it.
struct KeptAlignment {
  std::mutex mutex;
  std::shared_ptr<const tunnel::Alignment> alignment;
  std::size_t builds = 0;
};

KeptAlignment& kept() {
  static KeptAlignment k;
  return k;
}

}  // namespace

tunnel::Alignment built_alignment(const std::vector<tunnel::AlignmentStation>& stations,
                                  const std::vector<double>& radii, bool polyline,
                                  tunnel::Drive drive, const Eigen::Vector3d& datum) {
  KeptAlignment& k = kept();
  std::shared_ptr<const tunnel::Alignment> a;
  {
    std::lock_guard<std::mutex> lock(k.mutex);
    const tunnel::Alignment* was = k.alignment.get();
    const bool same = was && was->is_polyline() == polyline && was->datum() == datum &&
                      (polyline || was->radii() == radii) &&
                      same_stations(was->stations(), stations);
    if (!same) {
      k.alignment.reset();  // the old one's memory is freed before the new one is built
      k.alignment = std::make_shared<const tunnel::Alignment>(
          polyline ? tunnel::Alignment::from_polyline(stations, datum, drive)
                   : tunnel::Alignment::from_elements(stations, radii, datum, drive));
      ++k.builds;
    }
    a = k.alignment;
  }
  tunnel::Alignment out = *a;
  out.set_drive(drive);
  return out;
}

std::size_t alignment_builds() {
  KeptAlignment& k = kept();
  std::lock_guard<std::mutex> lock(k.mutex);
  return k.builds;
}

}  // namespace rockface::storage

#include "core/tunnel/tunnel_relative.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/common/error.h"

namespace rockface::tunnel {

PlaneInTunnel plane_in_tunnel(const Alignment& alignment, const Eigen::Vector3d& point,
                              const Eigen::Vector3d& normal, double uncertainty_deg) {
  if (!point.allFinite()) throw InputError("point", "must be finite coordinates");
  PlaneInTunnel out;
  out.place = alignment.place(point);
  out.strike = strike_vs_drive(normal, alignment.tangent_at(out.place.chainage), uncertainty_deg);
  return out;
}

FacePlace face_place(const Alignment& alignment, std::span<const Eigen::Vector3d> points) {
  if (points.empty()) throw InputError("points", "no surface points to place");
  std::vector<double> along;  // chainage in the drive's sense
  along.reserve(points.size());
  const double sense = alignment.drive() == Drive::ascending ? 1.0 : -1.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  FacePlace f;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite())
      throw InputError("points[" + std::to_string(i) + "]", "must be finite coordinates");
    const AlignmentPlace p = alignment.place(points[i]);
    f.inside = f.inside && p.inside();
    along.push_back(sense * p.chainage);
    centroid += points[i];
  }
  centroid /= static_cast<double>(points.size());
  std::sort(along.begin(), along.end());
  const std::size_t k =
      std::min(along.size() - 1, static_cast<std::size_t>(std::floor(0.98 * (along.size() - 1))));
  f.face_chainage = sense * along[k];
  f.chainage_min = std::min(sense * along.front(), sense * along.back());
  f.chainage_max = std::max(sense * along.front(), sense * along.back());
  const TunnelFrame frame = alignment.frame_at(f.face_chainage);
  f.offset = (centroid - frame.origin).dot(frame.right);
  f.height = (centroid - frame.origin).dot(frame.up);
  return f;
}

Eigen::Vector3d shift_to_chainage(const Alignment& alignment, const Eigen::Vector3d& face_point,
                                  double chainage, double offset, double height) {
  if (!std::isfinite(chainage)) throw InputError("chainage", "must be a finite number");
  if (!alignment.contains(chainage))
    throw InputError("chainage", "chainage " + std::to_string(chainage) +
                                     " lies outside the alignment (" +
                                     std::to_string(alignment.first_chainage()) + " to " +
                                     std::to_string(alignment.last_chainage()) + ")");
  return alignment.frame_at(chainage).to_local(offset, height) - face_point;
}

}  // namespace rockface::tunnel

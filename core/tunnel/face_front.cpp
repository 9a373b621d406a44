#include "core/tunnel/face_front.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/tunnel/mesh_raycast.h"

namespace rockface::tunnel {

namespace {
// 12 directions x 3 radii + the centre: 37 rays, enough for a robust
// median over a face that is rough by decimetres.
constexpr int kDirections = 12;
constexpr double kRadii[] = {0.25, 0.5, 0.7};
// How far ahead a ray looks for the face (m of chainage).
constexpr double kReachM = 30.0;
}  // namespace

std::optional<FaceFront> face_front(const Alignment& alignment, const DesignProfile& profile,
                                    const SurfaceInput& surface, double from_chainage) {
  const MeshRaycaster caster(surface.vertices, surface.triangles);
  const TunnelFrame frame = alignment.frame_at(from_chainage);
  const double sense = alignment.drive() == Drive::ascending ? 1.0 : -1.0;
  std::vector<Eigen::Vector2d> starts{profile.ray_centre()};
  for (int k = 0; k < kDirections; ++k) {
    const double angle = 2 * std::numbers::pi * k / kDirections;
    const ProfileHit hit = profile.ray_hit(angle);
    for (double f : kRadii)
      starts.push_back(profile.ray_centre() + f * (hit.point - profile.ray_centre()));
  }
  FaceFront out;
  std::vector<double> chainages;
  for (const auto& q : starts) {
    ++out.rays;
    const Eigen::Vector3d origin = frame.to_local(q.x(), q.y());
    const auto hit = caster.first_hit(origin, frame.along, 0.0, kReachM);
    if (!hit) continue;
    const std::size_t tri = hit->triangle;
    bool rock = true;
    if (!surface.not_rock_vertex.empty())
      for (int corner : surface.triangles[tri]) rock = rock && !surface.not_rock_vertex[corner];
    if (!rock) continue;  // the range pole stands in front of the face
    chainages.push_back(alignment.place(origin + hit->t * frame.along).chainage);
  }
  out.hits = static_cast<int>(chainages.size());
  if (chainages.empty()) return std::nullopt;
  std::sort(chainages.begin(), chainages.end(),
            [&](double a, double b) { return sense * a < sense * b; });
  out.nearest_chainage = chainages.front();
  out.median_chainage = chainages[chainages.size() / 2];
  return out;
}

}  // namespace rockface::tunnel

#include "firmware-app/import/round_meshing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/photogrammetry/surface/cloud_noise.h"

namespace rockface::app {

namespace {

// Within 0.7 to 1.6 times the design radius: a wall, roof or invert point
// with up to 60 % of the radius of overbreak or 30 % of underbreak; nearer
// the axis is the face (or something standing in the round).
constexpr double kWallInner = 0.7, kWallOuter = 1.6;
// 75 %: a round of a few metres is mostly wall (a 4 m round of a 5 m
// tunnel: 63 m^2 of walls for 20 m^2 of face); a face seen with a little of
// its walls has half of its disc's points beyond 0.7 of the radius at most.
constexpr double kRoundWallShare = 0.75;
// The band of the outline's start meshed again past its end to close the
// seam: 0.5 m is tens of point spacings of any scan worth meshing.
constexpr double kSeamBandM = 0.5;
// The cells the walls' scatter is measured in: 10 cm or 4 point spacings,
// tens of points each, small beside a break's bump (a metre or more).
constexpr double kNoiseCellM = 0.1, kNoiseCellSpacings = 4;

}  // namespace

std::optional<RoundMesh> mesh_round(const std::vector<Eigen::Vector3d>& points,
                                    const tunnel::Alignment& alignment,
                                    const tunnel::DesignProfile& profile) {
  const Eigen::Vector2d centre = profile.ray_centre();
  const double perimeter = profile.perimeter();
  std::vector<int> walls, face;
  std::vector<Eigen::Vector2d> developed;  // of walls
  constexpr int kBins = 36;
  std::array<bool, kBins> covered{};
  double lo_c = std::numeric_limits<double>::infinity(), hi_c = -lo_c;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const tunnel::AlignmentPlace place = alignment.place(points[i]);
    const Eigen::Vector2d d = Eigen::Vector2d(place.offset, place.height) - centre;
    const double angle = std::atan2(d.y(), d.x());
    const tunnel::ProfileHit hit = profile.ray_hit(angle);
    const double ratio = d.norm() / hit.distance;
    if (ratio >= kWallInner && ratio <= kWallOuter) {
      walls.push_back(static_cast<int>(i));
      developed.emplace_back(place.chainage, hit.s);
      const int bin =
          std::clamp(static_cast<int>((angle + M_PI) / (2 * M_PI) * kBins), 0, kBins - 1);
      covered[static_cast<std::size_t>(bin)] = true;
      lo_c = std::min(lo_c, place.chainage);
      hi_c = std::max(hi_c, place.chainage);
    } else {
      face.push_back(static_cast<int>(i));
    }
  }
  const auto around = std::count(covered.begin(), covered.end(), true);
  if (static_cast<double>(walls.size()) < kRoundWallShare * static_cast<double>(points.size()) ||
      around < kBins / 2 || hi_c - lo_c < 1.0)
    return std::nullopt;

  RoundMesh out;
  out.wall_points = walls.size();
  out.face_points = face.size();
  // The seam: the walls within kSeamBandM of the outline's start again past
  // its end; a triangle is kept when its centroid lies in
  // [band / 2, perimeter + band / 2), so the seam's triangles come once,
  // from where the band has neighbours on both sides.
  const double band = std::min(kSeamBandM, perimeter / 4);
  std::vector<Eigen::Vector3d> wall_xyz;
  std::vector<Eigen::Vector2d> wall_uv;
  std::vector<int> original;  // wall mesh vertex -> cloud index
  wall_xyz.reserve(walls.size());
  for (std::size_t k = 0; k < walls.size(); ++k) {
    wall_xyz.push_back(points[static_cast<std::size_t>(walls[k])]);
    wall_uv.push_back(developed[k]);
    original.push_back(walls[k]);
  }
  for (std::size_t k = 0; k < walls.size(); ++k)
    if (developed[k].y() < band) {
      wall_xyz.push_back(points[static_cast<std::size_t>(walls[k])]);
      wall_uv.emplace_back(developed[k].x(), developed[k].y() + perimeter);
      original.push_back(walls[k]);
    }
  developed = {};
  photogrammetry::CloudMesh wall_mesh = photogrammetry::mesh_point_cloud_on(wall_xyz, wall_uv);
  out.median_spacing = wall_mesh.median_spacing;
  out.noise_sigma_m = photogrammetry::cloud_noise_sigma(
      wall_xyz, wall_uv, std::max(kNoiseCellM, kNoiseCellSpacings * out.median_spacing));
  // Every triangle counter-clockwise in (chainage, s) faces one side of the
  // walls (the developed view is a continuous map): the side the majority of
  // a sample faces, against the axis, is flipped for all.
  double toward_axis = 0;
  const std::size_t stride = std::max<std::size_t>(1, wall_mesh.triangles.size() / 1000);
  std::vector<std::array<int, 3>> kept;
  kept.reserve(wall_mesh.triangles.size());
  for (std::size_t t = 0; t < wall_mesh.triangles.size(); ++t) {
    const auto& tri = wall_mesh.triangles[t];
    const double s = (wall_uv[static_cast<std::size_t>(tri[0])].y() +
                      wall_uv[static_cast<std::size_t>(tri[1])].y() +
                      wall_uv[static_cast<std::size_t>(tri[2])].y()) /
                     3;
    if (s < band / 2 || s >= perimeter + band / 2) continue;
    const std::array<int, 3> mapped{original[static_cast<std::size_t>(tri[0])],
                                    original[static_cast<std::size_t>(tri[1])],
                                    original[static_cast<std::size_t>(tri[2])]};
    if (t % stride == 0) {
      const Eigen::Vector3d& a = points[static_cast<std::size_t>(mapped[0])];
      const Eigen::Vector3d n = (points[static_cast<std::size_t>(mapped[1])] - a)
                                    .cross(points[static_cast<std::size_t>(mapped[2])] - a);
      const double c = (wall_uv[static_cast<std::size_t>(tri[0])].x() +
                        wall_uv[static_cast<std::size_t>(tri[1])].x() +
                        wall_uv[static_cast<std::size_t>(tri[2])].x()) /
                       3;
      const Eigen::Vector3d axis = alignment.frame_at(c).to_local(centre.x(), centre.y());
      toward_axis += n.normalized().dot((axis - a).normalized());
    }
    kept.push_back(mapped);
  }
  if (toward_axis < 0)
    for (auto& t : kept) std::swap(t[1], t[2]);
  wall_xyz = {};
  wall_uv = {};

  // The face's end of the round and the direction back along the drive.
  const double sense = alignment.drive() == tunnel::Drive::ascending ? 1.0 : -1.0;
  const double front = sense > 0 ? hi_c : lo_c;
  const tunnel::TunnelFrame at_front = alignment.frame_at(front);
  out.toward_viewer = -at_front.along;
  out.view_centre = at_front.to_local(centre.x(), centre.y());
  std::string face_words = "no face";
  if (face.size() >= 3) {
    std::vector<Eigen::Vector3d> face_xyz;
    face_xyz.reserve(face.size());
    for (int i : face) face_xyz.push_back(points[static_cast<std::size_t>(i)]);
    try {
      const photogrammetry::CloudMesh face_mesh = photogrammetry::mesh_point_cloud(face_xyz);
      const bool flip = face_mesh.normal.dot(out.toward_viewer) < 0;
      for (const auto& t : face_mesh.triangles) {
        std::array<int, 3> mapped{face[static_cast<std::size_t>(t[0])],
                                  face[static_cast<std::size_t>(t[1])],
                                  face[static_cast<std::size_t>(t[2])]};
        if (flip) std::swap(mapped[1], mapped[2]);
        kept.push_back(mapped);
      }
      out.view_centre = face_mesh.centroid;
      face_words = "the face over its best plane";
    } catch (const InputError&) {
      face_words = "the points inside the outline on a line: left out";
    }
  }
  out.triangles = std::move(kept);
  std::vector<bool> used(points.size(), false);
  for (const auto& t : out.triangles)
    for (int i : t) used[static_cast<std::size_t>(i)] = true;
  out.unused_points = static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
  out.words = "a round: its walls meshed on the tunnel's developed view (" +
              std::to_string(out.wall_points) + " points), " + face_words + " (" +
              std::to_string(out.face_points) + " points)";
  return out;
}

}  // namespace rockface::app

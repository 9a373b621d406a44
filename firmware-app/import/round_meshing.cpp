#include "firmware-app/import/round_meshing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

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
// The outline's sectors a round's walls are counted around in.
constexpr int kOutlineSectors = 36;

// Which points are the round's walls (within kWallInner..kWallOuter of the
// design outline along their ray), their developed coordinates, and how far
// around and along the drive they reach.
struct WallPoints {
  std::vector<bool> is_wall;
  std::vector<Eigen::Vector2d> developed;  // (chainage, s) of each wall point
  std::size_t count = 0;
  long around = 0;  // of the outline's sectors, those with a wall point
  double lo_c = std::numeric_limits<double>::infinity(), hi_c = -lo_c;
};

WallPoints find_wall_points(const std::vector<Eigen::Vector3d>& points,
                            const tunnel::Alignment& alignment,
                            const tunnel::DesignProfile& profile, const Eigen::Vector2d& centre) {
  WallPoints w;
  w.is_wall.assign(points.size(), false);
  w.developed.resize(points.size());
  constexpr int kBins = kOutlineSectors;
  std::array<bool, kBins> covered{};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const tunnel::AlignmentPlace place = alignment.place(points[i]);
    const Eigen::Vector2d d = Eigen::Vector2d(place.offset, place.height) - centre;
    const double angle = std::atan2(d.y(), d.x());
    const tunnel::ProfileHit hit = profile.ray_hit(angle);
    const double ratio = d.norm() / hit.distance;
    if (ratio >= kWallInner && ratio <= kWallOuter) {
      w.is_wall[i] = true;
      ++w.count;
      w.developed[i] = {place.chainage, hit.s};
      const int bin =
          std::clamp(static_cast<int>((angle + M_PI) / (2 * M_PI) * kBins), 0, kBins - 1);
      covered[static_cast<std::size_t>(bin)] = true;
      w.lo_c = std::min(w.lo_c, place.chainage);
      w.hi_c = std::max(w.hi_c, place.chainage);
    }
  }
  w.around = std::count(covered.begin(), covered.end(), true);
  return w;
}

// A round: mostly walls, around at least half the outline, over a metre of
// the drive.
bool is_a_round(const WallPoints& w, std::size_t points) {
  return !(static_cast<double>(w.count) < kRoundWallShare * static_cast<double>(points) ||
           w.around < kOutlineSectors / 2 || w.hi_c - w.lo_c < 1.0);
}

// Walls first, the face after them: the cloud's points, colours and
// developed coordinates swapped together.
void put_walls_first(std::vector<Eigen::Vector3d>& points,
                     std::vector<std::array<std::uint8_t, 3>>& colours, WallPoints& w) {
  for (std::size_t i = 0, j = points.size(); i < j;) {
    if (w.is_wall[i]) {
      ++i;
      continue;
    }
    --j;
    if (!w.is_wall[j]) continue;
    std::swap(points[i], points[j]);
    if (!colours.empty()) std::swap(colours[i], colours[j]);
    std::swap(w.developed[i], w.developed[j]);
    w.is_wall[i] = true;
    w.is_wall[j] = false;
    ++i;
  }
}

// The developed coordinates of the walls alone (the cloud's first
// `wall_count` points), with room for the seam: the walls within `band` of
// the outline's start again past its end, appended as second places of
// those points (cloud_meshing.h's repeated points; no copy of a point).
// Returns each second place's point. `developed`, sized for the whole cloud
// while the walls were found, is replaced by a vector of the walls' size.
std::vector<int> developed_with_seam(std::vector<Eigen::Vector2d>& developed,
                                     std::size_t wall_count, double band, double perimeter) {
  std::vector<int> band_source;
  for (std::size_t k = 0; k < wall_count; ++k)
    if (developed[k].y() < band) band_source.push_back(static_cast<int>(k));
  std::vector<Eigen::Vector2d> walls;
  walls.reserve(wall_count + band_source.size());
  walls.assign(developed.begin(), developed.begin() + static_cast<std::ptrdiff_t>(wall_count));
  developed = {};  // the whole cloud's size freed before the meshing
  for (int k : band_source)
    walls.emplace_back(walls[static_cast<std::size_t>(k)].x(),
                       walls[static_cast<std::size_t>(k)].y() + perimeter);
  developed = std::move(walls);
  return band_source;
}

// The walls' triangles kept (their centroid in [band / 2, perimeter +
// band / 2), so the seam's come once), mapped to the cloud's indices in
// place (no second list) and turned to face the axis. Every triangle
// counter-clockwise in (chainage, s) faces one side of the walls (the
// developed view is a continuous map): the side the majority of a sample
// faces, against the axis, is flipped for all.
std::vector<std::array<int, 3>> keep_wall_triangles(
    std::vector<std::array<int, 3>> kept, const std::vector<Eigen::Vector3d>& points,
    const std::vector<Eigen::Vector2d>& developed, std::size_t wall_count,
    const std::vector<int>& band_source, double band, double perimeter,
    const tunnel::Alignment& alignment, const Eigen::Vector2d& centre) {
  const auto cloud_index = [&](int v) {
    return static_cast<std::size_t>(v) < wall_count
               ? v
               : band_source[static_cast<std::size_t>(v) - wall_count];
  };
  double toward_axis = 0;
  const std::size_t stride = std::max<std::size_t>(1, kept.size() / 1000);
  std::size_t kept_count = 0;
  for (std::size_t t = 0; t < kept.size(); ++t) {
    const std::array<int, 3> tri = kept[t];
    const auto uv = [&](int k) { return developed[static_cast<std::size_t>(tri[k])]; };
    const double s = (uv(0).y() + uv(1).y() + uv(2).y()) / 3;
    if (s < band / 2 || s >= perimeter + band / 2) continue;
    const std::array<int, 3> mapped{cloud_index(tri[0]), cloud_index(tri[1]), cloud_index(tri[2])};
    if (t % stride == 0) {
      const Eigen::Vector3d& a = points[static_cast<std::size_t>(mapped[0])];
      const Eigen::Vector3d n = (points[static_cast<std::size_t>(mapped[1])] - a)
                                    .cross(points[static_cast<std::size_t>(mapped[2])] - a);
      const double c = (uv(0).x() + uv(1).x() + uv(2).x()) / 3;
      const Eigen::Vector3d axis = alignment.frame_at(c).to_local(centre.x(), centre.y());
      toward_axis += n.normalized().dot((axis - a).normalized());
    }
    kept[kept_count++] = mapped;
  }
  kept.resize(kept_count);
  if (toward_axis < 0)
    for (auto& t : kept) std::swap(t[1], t[2]);
  return kept;
}

// The face's points (after the walls' in the cloud) meshed over their best
// plane, facing the viewer, appended to `triangles`; the view's centre
// moved to the face's. Returns the face's meshing in words.
std::string add_face_triangles(std::span<const Eigen::Vector3d> face_xyz, std::size_t wall_count,
                               RoundMesh& out, std::vector<std::array<int, 3>>& triangles) {
  if (face_xyz.size() < 3) return "no face";
  try {
    const photogrammetry::CloudMesh face_mesh = photogrammetry::mesh_point_cloud(face_xyz);
    const bool flip = face_mesh.normal.dot(out.toward_viewer) < 0;
    triangles.reserve(triangles.size() + face_mesh.triangles.size());
    const int first = static_cast<int>(wall_count);  // the face's points follow the walls
    for (const auto& t : face_mesh.triangles) {
      std::array<int, 3> mapped{first + t[0], first + t[1], first + t[2]};
      if (flip) std::swap(mapped[1], mapped[2]);
      triangles.push_back(mapped);
    }
    out.view_centre = face_mesh.centroid;
    return "the face over its best plane";
  } catch (const InputError&) {
    return "the points inside the outline on a line: left out";
  }
}

std::size_t points_in_no_triangle(std::size_t points,
                                  const std::vector<std::array<int, 3>>& triangles) {
  std::vector<bool> used(points, false);
  for (const auto& t : triangles)
    for (int i : t) used[static_cast<std::size_t>(i)] = true;
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
}

}  // namespace

std::optional<RoundMesh> mesh_round(std::vector<Eigen::Vector3d>& points,
                                    std::vector<std::array<std::uint8_t, 3>>& colours,
                                    const tunnel::Alignment& alignment,
                                    const tunnel::DesignProfile& profile) {
  if (!colours.empty() && colours.size() != points.size())
    throw Error("mesh_round: " + std::to_string(colours.size()) + " colours for " +
                std::to_string(points.size()) + " points");
  const Eigen::Vector2d centre = profile.ray_centre();
  const double perimeter = profile.perimeter();
  // Memory (issue 43: a 10-million-point round must fit the tablet): the
  // walls are meshed on the cloud's own vectors, reordered in place (walls
  // first), never on a copy of them; what is done with is freed before the
  // next step's vectors are made.
  WallPoints walls = find_wall_points(points, alignment, profile, centre);
  if (!is_a_round(walls, points.size())) return std::nullopt;
  put_walls_first(points, colours, walls);
  walls.is_wall = {};
  const std::size_t wall_count = walls.count;
  std::vector<Eigen::Vector2d>& developed = walls.developed;
  RoundMesh out;
  out.wall_points = wall_count;
  out.face_points = points.size() - wall_count;
  // The walls are meshed where they lie, the cloud's first wall_count
  // points (the face's after them, not copied aside), their seam by second
  // places of the points at the outline's start.
  const double band = std::min(kSeamBandM, perimeter / 4);
  std::vector<int> band_source = developed_with_seam(developed, wall_count, band, perimeter);
  const std::span<const Eigen::Vector3d> wall_xyz(points.data(), wall_count);
  photogrammetry::CloudMesh wall_mesh =
      photogrammetry::mesh_point_cloud_on(wall_xyz, developed, band_source);
  out.median_spacing = wall_mesh.median_spacing;
  std::vector<std::array<int, 3>> kept =
      keep_wall_triangles(std::move(wall_mesh.triangles), points, developed, wall_count,
                          band_source, band, perimeter, alignment, centre);
  band_source = {};
  // The walls' scatter on their developed view (their own places only: the
  // seam's second places would pair with the face's points).
  developed.resize(wall_count);
  out.noise_sigma_m = photogrammetry::cloud_noise_sigma(
      points, developed, std::max(kNoiseCellM, kNoiseCellSpacings * out.median_spacing));
  developed = {};

  // The face's end of the round and the direction back along the drive.
  const double sense = alignment.drive() == tunnel::Drive::ascending ? 1.0 : -1.0;
  const double front = sense > 0 ? walls.hi_c : walls.lo_c;
  const tunnel::TunnelFrame at_front = alignment.frame_at(front);
  out.toward_viewer = -at_front.along;
  out.view_centre = at_front.to_local(centre.x(), centre.y());
  const std::string face_words = add_face_triangles(
      std::span<const Eigen::Vector3d>(points).subspan(wall_count), wall_count, out, kept);
  out.triangles = std::move(kept);
  out.unused_points = points_in_no_triangle(points.size(), out.triangles);
  out.words = "a round: its walls meshed on the tunnel's developed view (" +
              std::to_string(out.wall_points) + " points), " + face_words + " (" +
              std::to_string(out.face_points) + " points)";
  return out;
}

}  // namespace rockface::app

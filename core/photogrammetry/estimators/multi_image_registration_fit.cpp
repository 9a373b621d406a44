#include "core/photogrammetry/estimators/multi_image_registration_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <opencv2/surface_matching.hpp>

namespace rockface::photogrammetry {

std::vector<Eigen::Vector3d> vertex_normals(const SurfaceMesh& mesh) {
  std::vector<Eigen::Vector3d> n(mesh.size(), Eigen::Vector3d::Zero());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[1]] - mesh.vertices[t[0]];
    const Eigen::Vector3d b = mesh.vertices[t[2]] - mesh.vertices[t[0]];
    const Eigen::Vector3d c = a.cross(b);
    for (int k : t) n[k] += c;
  }
  for (auto& v : n)
    if (v.norm() > 0) v.normalize();
  return n;
}

SurfaceSample sample_surface(const SurfaceMesh& mesh, const std::vector<Eigen::Vector3d>& normals,
                             const Similarity& to_face, std::size_t max_points) {
  SurfaceSample s;
  const std::size_t stride =
      std::max<std::size_t>(1, mesh.size() / std::max<std::size_t>(1, max_points));
  for (std::size_t i = 0; i < mesh.size(); i += stride) {
    if (normals[i].squaredNorm() == 0) continue;
    s.points.push_back(to_face.apply(mesh.vertices[i]));
    s.normals.push_back(to_face.R * normals[i]);
  }
  return s;
}

SurfaceSample moved(const SurfaceSample& sample, const Similarity& rigid) {
  SurfaceSample s;
  s.points.reserve(sample.points.size());
  s.normals.reserve(sample.normals.size());
  for (const auto& p : sample.points) s.points.push_back(rigid.apply(p));
  for (const auto& n : sample.normals) s.normals.push_back(rigid.R * n);
  return s;
}

namespace {

// Cells per axis a key holds (21 bits each of 64).
constexpr std::int64_t kCellRange = std::int64_t{1} << 21;

}  // namespace

NearestWithin::NearestWithin(const std::vector<Eigen::Vector3d>& points, double radius)
    : points_(&points), radius_(radius), origin_(Eigen::Vector3d::Zero()) {
  if (points.empty() || !(radius > 0)) return;
  origin_ = points.front();
  for (const auto& p : points) origin_ = origin_.cwiseMin(p);
  // One cell margin, so that a query just below the lowest point has cells.
  origin_ -= Eigen::Vector3d::Constant(radius);
  sorted_.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    sorted_.emplace_back(key(points[i]), static_cast<int>(i));
  std::sort(sorted_.begin(), sorted_.end());
}

std::uint64_t NearestWithin::key(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d c = (p - origin_) / radius_;
  const std::int64_t x = static_cast<std::int64_t>(std::floor(c.x()));
  const std::int64_t y = static_cast<std::int64_t>(std::floor(c.y()));
  const std::int64_t z = static_cast<std::int64_t>(std::floor(c.z()));
  if (x < 0 || y < 0 || z < 0 || x >= kCellRange || y >= kCellRange || z >= kCellRange)
    return std::numeric_limits<std::uint64_t>::max();  // no point has this key
  return (static_cast<std::uint64_t>(x) << 42) | (static_cast<std::uint64_t>(y) << 21) |
         static_cast<std::uint64_t>(z);
}

std::pair<int, double> NearestWithin::nearest(const Eigen::Vector3d& q) const {
  double best = radius_ * radius_;
  int found = -1;
  if (sorted_.empty()) return {found, radius_};
  const Eigen::Vector3d c = (q - origin_) / radius_;
  const std::int64_t cx = static_cast<std::int64_t>(std::floor(c.x()));
  const std::int64_t cy = static_cast<std::int64_t>(std::floor(c.y()));
  const std::int64_t cz = static_cast<std::int64_t>(std::floor(c.z()));
  // The three cells along z of one (x, y) column have consecutive keys (z
  // is the key's low part), so one search finds all three: 9 searches, not
  // 27, and the points visited in the same order.
  const std::int64_t z0 = std::max<std::int64_t>(cz - 1, 0);
  const std::int64_t z1 = std::min<std::int64_t>(cz + 1, kCellRange - 1);
  if (z0 > z1) return {found, radius_};
  for (std::int64_t x = cx - 1; x <= cx + 1; ++x) {
    if (x < 0 || x >= kCellRange) continue;
    for (std::int64_t y = cy - 1; y <= cy + 1; ++y) {
      if (y < 0 || y >= kCellRange) continue;
      const std::uint64_t column =
          (static_cast<std::uint64_t>(x) << 42) | (static_cast<std::uint64_t>(y) << 21);
      const std::uint64_t from = column | static_cast<std::uint64_t>(z0);
      const std::uint64_t to = column | static_cast<std::uint64_t>(z1);
      auto it = std::lower_bound(sorted_.begin(), sorted_.end(),
                                 std::make_pair(from, std::numeric_limits<int>::min()));
      for (; it != sorted_.end() && it->first <= to; ++it) {
        const double d2 = ((*points_)[static_cast<std::size_t>(it->second)] - q).squaredNorm();
        if (d2 < best || (d2 == best && found >= 0 && it->second < found)) {
          best = d2;
          found = it->second;
        }
      }
    }
  }
  return {found, std::sqrt(best)};
}

namespace {

Similarity from_umeyama(const Eigen::Matrix3Xd& src, const Eigen::Matrix3Xd& dst) {
  const Eigen::Matrix4d T = Eigen::umeyama(src, dst, true);
  const Eigen::Matrix3d sR = T.topLeftCorner<3, 3>();
  Similarity s;
  s.scale = std::cbrt(sR.determinant());
  s.R = sR / s.scale;
  s.t = T.topRightCorner<3, 1>();
  return s;
}

// Samples needed for an all-inlier 3-point sample with probability 0.9999
// at an inlier ratio w.
double samples_needed(double w) {
  const double w3 = w * w * w;
  if (w3 >= 1) return 1;
  if (w3 <= 0) return std::numeric_limits<double>::infinity();
  return std::log(1e-4) / std::log(1 - w3);
}

}  // namespace

TieFit fit_tie_points(const TiePoints& tie, double inlier_m, int max_samples, std::uint64_t seed) {
  TieFit best;
  const int n = static_cast<int>(tie.slave.size());
  if (n < 3) return best;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> pick(0, n - 1);
  auto consensus = [&](const Similarity& s) {
    std::vector<int> in;
    for (int k = 0; k < n; ++k)
      if ((s.apply(tie.slave[k]) - tie.reference[k]).norm() < inlier_m) in.push_back(k);
    return in;
  };
  double needed = std::numeric_limits<double>::infinity();
  for (int it = 0; it < max_samples && it < needed; ++it) {
    ++best.samples;
    const int a = pick(rng), b = pick(rng), c = pick(rng);
    if (a == b || b == c || a == c) continue;
    Eigen::Matrix3d src, dst;
    src << tie.slave[a], tie.slave[b], tie.slave[c];
    dst << tie.reference[a], tie.reference[b], tie.reference[c];
    // A sliver sample fixes no rotation about its long side.
    const double area = (dst.col(1) - dst.col(0)).cross(dst.col(2) - dst.col(0)).norm();
    if (area < 4 * inlier_m * inlier_m) continue;
    const Similarity s = from_umeyama(src, dst);
    if (!(s.scale > 0) || !std::isfinite(s.scale)) continue;
    std::vector<int> in = consensus(s);
    if (in.size() > best.inliers.size()) {
      const int samples = best.samples;
      best = {s, std::move(in), samples};
      needed = samples_needed(static_cast<double>(best.inliers.size()) / n);
    }
  }
  // Refit on the consensus twice (the refit may gain or lose border points).
  for (int round = 0; round < 2 && best.inliers.size() >= 3; ++round) {
    Eigen::Matrix3Xd src(3, best.inliers.size()), dst(3, best.inliers.size());
    for (std::size_t k = 0; k < best.inliers.size(); ++k) {
      src.col(k) = tie.slave[best.inliers[k]];
      dst.col(k) = tie.reference[best.inliers[k]];
    }
    best.slave_to_face = from_umeyama(src, dst);
    std::vector<int> in = consensus(best.slave_to_face);
    if (in.size() < 3) break;
    best.inliers = std::move(in);
  }
  return best;
}

OverlapFit overlap(const SurfaceSample& slave, const SurfaceSample& reference,
                   const NearestWithin& near) {
  OverlapFit o;
  double sum2 = 0;
  for (std::size_t i = 0; i < slave.points.size(); ++i) {
    const auto [j, d] = near.nearest(slave.points[i]);
    if (j < 0) continue;
    const auto r = static_cast<std::size_t>(j);
    const double e = (slave.points[i] - reference.points[r]).dot(reference.normals[r]);
    sum2 += e * e;
    o.slave.push_back(static_cast<int>(i));
    o.reference.push_back(j);
  }
  if (!o.slave.empty()) o.rms = std::sqrt(sum2 / static_cast<double>(o.slave.size()));
  return o;
}

namespace {

cv::Mat point_cloud(const SurfaceSample& s, const std::vector<int>& rows) {
  cv::Mat pc(static_cast<int>(rows.size()), 6, CV_32F);
  for (int r = 0; r < pc.rows; ++r) {
    const auto i = static_cast<std::size_t>(rows[static_cast<std::size_t>(r)]);
    for (int k = 0; k < 3; ++k) {
      pc.at<float>(r, k) = static_cast<float>(s.points[i](k));
      pc.at<float>(r, 3 + k) = static_cast<float>(s.normals[i](k));
    }
  }
  return pc;
}

std::vector<int> unique_sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace

Similarity icp_refinement(const SurfaceSample& slave, const SurfaceSample& reference,
                          const OverlapFit& o, int iterations, int levels) {
  const cv::Mat src = point_cloud(slave, o.slave);
  const cv::Mat dst = point_cloud(reference, unique_sorted(o.reference));
  cv::ppf_match_3d::ICP icp(iterations, 0.005f, 2.5f, levels);
  double residual = 0;
  cv::Matx44d pose;
  icp.registerModelToScene(src, dst, residual, pose);
  Similarity rigid;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rigid.R(r, c) = pose(r, c);
    rigid.t(r) = pose(r, 3);
  }
  return rigid;
}

}  // namespace rockface::photogrammetry

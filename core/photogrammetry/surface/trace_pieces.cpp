#include "core/photogrammetry/surface/trace_pieces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Eigenvalues>

#include "core/common/units.h"

namespace rockface::photogrammetry {

namespace {

// Unit direction of largest spread (the trace's run), fitted twice: the
// second time without the points far off the first line, so that a single
// blunder of dense matching (at a fold of the face, a frame edge) does not
// turn it.
Eigen::Vector3d principal_direction(const std::vector<Eigen::Vector3d>& points) {
  auto fit = [](const std::vector<Eigen::Vector3d>& pts) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : pts) mean += p;
    mean /= static_cast<double>(pts.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    return std::pair{mean, Eigen::Vector3d(eig.eigenvectors().col(2))};
  };
  const auto [mean, d] = fit(points);
  std::vector<double> off;
  for (const auto& p : points) off.push_back(((p - mean) - d * d.dot(p - mean)).norm());
  std::vector<double> sorted = off;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double keep = 3 * sorted[sorted.size() / 2];
  std::vector<Eigen::Vector3d> inliers;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (off[i] <= keep) inliers.push_back(points[i]);
  return inliers.size() >= 2 ? fit(inliers).second : d;
}

double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                              const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Smallest distance between two polylines (vertex to segment both ways).
double polyline_distance(const std::vector<Eigen::Vector3d>& a,
                         const std::vector<Eigen::Vector3d>& b) {
  double best = std::numeric_limits<double>::infinity();
  auto one_way = [&](const auto& from, const auto& to) {
    for (const auto& p : from)
      for (std::size_t k = 0; k + 1 < to.size(); ++k)
        best = std::min(best, point_segment_distance(p, to[k], to[k + 1]));
  };
  one_way(a, b);
  one_way(b, a);
  return best;
}

}  // namespace

std::vector<FaceTrace> join_trace_pieces(const std::vector<TracePiece>& pieces,
                                         const FaceTraceOptions& options) {
  std::vector<Eigen::Vector3d> direction(pieces.size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (pieces[i].points.size() >= 2) direction[i] = principal_direction(pieces[i].points);

  // Join pieces that continue each other: different images, same (or
  // unassigned) joint, close and running the same way. A few pieces per
  // visit: pairwise is fine.
  std::vector<std::size_t> group(pieces.size());
  std::iota(group.begin(), group.end(), 0);
  auto root = [&](std::size_t i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  const double cos_max = std::cos(deg_to_rad(options.max_angle_deg));
  for (std::size_t a = 0; a < pieces.size(); ++a)
    for (std::size_t b = a + 1; b < pieces.size(); ++b) {
      if (pieces[a].image == pieces[b].image) continue;
      if (pieces[a].points.size() < 2 || pieces[b].points.size() < 2) continue;
      const auto& ja = pieces[a].joint;
      const auto& jb = pieces[b].joint;
      if (!ja.empty() && !jb.empty() && ja != jb) continue;
      if (std::abs(direction[a].dot(direction[b])) < cos_max) continue;
      if (polyline_distance(pieces[a].points, pieces[b].points) > options.join_distance) continue;
      group[root(b)] = root(a);
    }

  std::vector<FaceTrace> out;
  std::vector<int> trace_of(pieces.size(), -1);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const std::size_t r = root(i);
    if (trace_of[r] < 0) {
      trace_of[r] = static_cast<int>(out.size());
      out.push_back({pieces[i].label, {}, {}, {}, {}});
    }
    FaceTrace& t = out[trace_of[r]];
    if (t.joint.empty()) t.joint = pieces[i].joint;
    t.points.insert(t.points.end(), pieces[i].points.begin(), pieces[i].points.end());
    t.pieces.push_back(pieces[i].label);
    t.images.push_back(pieces[i].image);
  }
  // A joint trace is a plane cut by the surface: it runs one way, so the
  // points of joined pieces are ordered along that run.
  for (auto& t : out) {
    if (t.pieces.size() < 2) continue;
    const Eigen::Vector3d d = principal_direction(t.points);
    std::stable_sort(t.points.begin(), t.points.end(),
                     [&](const auto& p, const auto& q) { return p.dot(d) < q.dot(d); });
  }
  return out;
}

}  // namespace rockface::photogrammetry

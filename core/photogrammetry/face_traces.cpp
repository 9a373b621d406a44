#include "core/photogrammetry/face_traces.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/photogrammetry/pixel_lookup.h"

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

struct Piece {
  const ImageTrace* trace = nullptr;
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector3d direction;
};

}  // namespace

std::vector<FaceTrace> traces_in_face_frame(const std::vector<FaceImage>& images,
                                            const FaceRegistration& face,
                                            const std::vector<ImageTrace>& traces,
                                            const FaceTraceOptions& options) {
  std::vector<PixelLookup> lookups;
  for (const auto& image : images) lookups.emplace_back(image.mesh);

  std::vector<Piece> pieces;
  for (const auto& t : traces) {
    if (t.image < 0 || static_cast<std::size_t>(t.image) >= images.size())
      throw InputError("trace " + t.label,
                       "names image " + std::to_string(t.image) + ", which is not given");
    Piece piece;
    piece.trace = &t;
    for (const auto& px : t.pixels) {
      const int v = lookups[t.image].nearest(px);
      if (v >= 0)
        piece.points.push_back(
            face.images[t.image].to_face.apply(images[t.image].mesh.vertices[v]));
    }
    if (piece.points.size() < 2) continue;  // off the reconstructed surface
    piece.direction = principal_direction(piece.points);
    pieces.push_back(std::move(piece));
  }

  // Join pieces that continue each other: same (or unassigned) joint, close
  // and running the same way. A few pieces per visit: pairwise is fine.
  std::vector<std::size_t> group(pieces.size());
  std::iota(group.begin(), group.end(), 0);
  auto root = [&](std::size_t i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  const double cos_max = std::cos(deg_to_rad(options.max_angle_deg));
  for (std::size_t a = 0; a < pieces.size(); ++a)
    for (std::size_t b = a + 1; b < pieces.size(); ++b) {
      const auto& ja = pieces[a].trace->joint;
      const auto& jb = pieces[b].trace->joint;
      if (!ja.empty() && !jb.empty() && ja != jb) continue;
      if (std::abs(pieces[a].direction.dot(pieces[b].direction)) < cos_max) continue;
      if (polyline_distance(pieces[a].points, pieces[b].points) > options.join_distance) continue;
      group[root(b)] = root(a);
    }

  std::vector<FaceTrace> out;
  std::vector<int> trace_of(pieces.size(), -1);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const std::size_t r = root(i);
    if (trace_of[r] < 0) {
      trace_of[r] = static_cast<int>(out.size());
      out.push_back({pieces[i].trace->label, {}, {}, {}});
    }
    FaceTrace& t = out[trace_of[r]];
    if (t.joint.empty()) t.joint = pieces[i].trace->joint;
    t.points.insert(t.points.end(), pieces[i].points.begin(), pieces[i].points.end());
    t.pieces.push_back(pieces[i].trace->label);
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

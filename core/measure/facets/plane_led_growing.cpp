#include "core/measure/facets/plane_led_growing.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace rockface::measure {

namespace {

// Running sums of points for a best-fit plane (principal axes).
struct PointSums {
  double count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();

  void add(const Eigen::Vector3d& p) {
    count += 1;
    sum += p;
    outer += p * p.transpose();
  }
};

struct FittedPlane {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d spread = Eigen::Vector3d::Zero();  // RMS along the axes, smallest first
  double distance(const Eigen::Vector3d& p) const { return std::abs(normal.dot(p - centroid)); }
};

FittedPlane fitted(const PointSums& s) {
  FittedPlane f;
  f.centroid = s.sum / s.count;
  const Eigen::Matrix3d cov = s.outer / s.count - f.centroid * f.centroid.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  f.spread = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  f.normal = eig.eigenvectors().col(0);
  return f;
}

}  // namespace

std::vector<std::vector<int>> plane_led_regions(const photogrammetry::SurfaceMesh& mesh,
                                                const TriangleGraph& graph,
                                                const std::vector<char>& taken,
                                                const std::vector<int>& seeds,
                                                const PlaneLedOptions& options) {
  std::vector<std::vector<int>> regions;
  const std::size_t n = graph.size();
  // 0: free; 1: tried in a seed patch that failed (may still join a
  // region); 2: in a region or taken.
  std::vector<char> state(n, 0);
  for (std::size_t t = 0; t < n; ++t)
    if (taken[t] || !graph.usable(t)) state[t] = 2;
  std::vector<int> vertex_stamp(mesh.vertices.size(), -1);
  std::vector<int> patch;
  std::vector<char> in_patch(n, 0);
  // A seed patch as compact as a disc of the seed area: narrower (a band
  // left between facets, along a crease) and its tilt across is unknown.
  const double min_width = 0.2 * std::sqrt(options.seed_area);
  int stamp = 0;
  for (const int seed : seeds) {
    if (state[seed] != 0) continue;
    // The seed patch: breadth first over free triangles until it has the
    // seed area.
    patch.assign(1, seed);
    in_patch[seed] = 1;
    double area = graph.areas[seed];
    for (std::size_t head = 0; head < patch.size() && area < options.seed_area; ++head)
      for (const int k : graph.neighbours[patch[head]]) {
        if (k < 0 || state[k] != 0 || in_patch[k]) continue;
        in_patch[k] = 1;
        patch.push_back(k);
        area += graph.areas[k];
        if (area >= options.seed_area) break;
      }
    for (const int t : patch) in_patch[t] = 0;
    // Not beside a facet of the first pass: what is left there is the band
    // along a crease, where the matching window rounds the edge between
    // two planes; a seed in it would grow across the crease.
    bool beside_facet = false;
    for (const int t : patch)
      for (const int k : graph.neighbours[t]) beside_facet = beside_facet || (k >= 0 && taken[k]);
    bool planar = area >= options.seed_area && !beside_facet;
    PointSums sums;
    FittedPlane plane;
    if (planar) {
      ++stamp;
      for (const int t : patch)
        for (const int v : mesh.triangles[t])
          if (vertex_stamp[v] != stamp) {
            vertex_stamp[v] = stamp;
            sums.add(mesh.vertices[v]);
          }
      plane = fitted(sums);
      // The smallest spread is the points' RMS off their plane.
      planar = plane.spread(1) >= min_width && plane.spread(0) <= options.seed_rms;
    }
    if (!planar) {
      for (const int t : patch) state[t] = std::max<char>(state[t], 1);
      continue;
    }
    // Grow: every neighbour whose corners all lie within the gate joins;
    // the plane is refitted as the region grows (its points' sums).
    std::vector<int> region = patch;
    for (const int t : region) state[t] = 2;
    double next_refit = options.refit_growth * static_cast<double>(region.size());
    for (std::size_t head = 0; head < region.size(); ++head)
      for (const int k : graph.neighbours[region[head]]) {
        if (k < 0 || state[k] == 2) continue;
        bool within = true;
        for (const int v : mesh.triangles[k])
          within = within && plane.distance(mesh.vertices[v]) <= options.gate;
        if (!within) continue;
        state[k] = 2;
        region.push_back(k);
        for (const int v : mesh.triangles[k])
          if (vertex_stamp[v] != stamp) {
            vertex_stamp[v] = stamp;
            sums.add(mesh.vertices[v]);
          }
        if (static_cast<double>(region.size()) >= next_refit) {
          plane = fitted(sums);
          next_refit *= options.refit_growth;
        }
      }
    regions.push_back(std::move(region));
  }
  return regions;
}

}  // namespace rockface::measure

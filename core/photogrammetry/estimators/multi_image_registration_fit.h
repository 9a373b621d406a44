#pragma once
// The pieces of one image's registration in the merge of several 3D images
// (multi_image_registration.h): the robust similarity from 3D tie points,
// the thinned surface samples, exact nearest neighbours within the overlap
// distance, the overlap and its point-to-plane RMS, and the ICP refinement.
// Each is a pure function of its input (or an object built once and only
// read afterwards), so images of one wave are registered side by side.
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/estimators/registration.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::photogrammetry {

// Area-weighted vertex normals of the lattice mesh, unit length (zero where
// a vertex has no triangle).
std::vector<Eigen::Vector3d> vertex_normals(const SurfaceMesh& mesh);

// A thinned set of surface points (with normals) of one image, in the face
// frame: every stride-th vertex with a normal, at most about max_points.
struct SurfaceSample {
  std::vector<Eigen::Vector3d> points, normals;
};
SurfaceSample sample_surface(const SurfaceMesh& mesh, const std::vector<Eigen::Vector3d>& normals,
                             const Similarity& to_face, std::size_t max_points);
// The same sample moved by a further rigid motion (ICP's): the vertices
// sample_surface would pick through to_face.then(rigid), without the mesh.
SurfaceSample moved(const SurfaceSample& sample, const Similarity& rigid);

// Exact nearest neighbour in 3D among points closer than a fixed radius: a
// hash of cubic cells one radius wide, searched 3 x 3 x 3 around the query
// (nine searches of the sorted keys: a column of three cells is one range).
// Deterministic (flann's randomised kd-tree, used before, was neither exact
// nor the same from run to run: the merge's residuals scattered with it).
class NearestWithin {
 public:
  NearestWithin(const std::vector<Eigen::Vector3d>& points, double radius);
  // Index of the nearest point no farther than the radius and its distance,
  // or {-1, radius} when there is none; ties go to the lower index.
  std::pair<int, double> nearest(const Eigen::Vector3d& q) const;
  double radius() const { return radius_; }

 private:
  std::uint64_t key(const Eigen::Vector3d& p) const;
  const std::vector<Eigen::Vector3d>* points_;
  double radius_;
  Eigen::Vector3d origin_;
  std::vector<std::pair<std::uint64_t, int>> sorted_;  // (cell key, point index) by key
};

// 3D tie points of one pair: the same surface points, the reference's in the
// face frame, the slave's in its own.
struct TiePoints {
  std::vector<Eigen::Vector3d> reference;
  std::vector<Eigen::Vector3d> slave;
};

struct TieFit {
  Similarity slave_to_face;
  std::vector<int> inliers;
  int samples = 0;  // RANSAC samples drawn
};

// Robust similarity: 3-point Umeyama samples, the largest consensus, then
// Umeyama over all of it (twice). The samples stop when, at the best inlier
// ratio w so far, max_samples or log(1 - 0.9999) / log(1 - w^3) have been
// drawn: a run of that many samples misses an all-inlier one with
// probability 1e-4. The count follows from the data and the seed alone.
TieFit fit_tie_points(const TiePoints& tie, double inlier_m, int max_samples, std::uint64_t seed);

// Point-to-plane distances of the slave sample to the reference surface
// where the two overlap (nearest reference point within the radius).
struct OverlapFit {
  std::vector<int> slave, reference;  // sample indices of the overlapping pairs
  double rms = 0;
};
OverlapFit overlap(const SurfaceSample& slave, const SurfaceSample& reference,
                   const NearestWithin& near);

// Rigid point-to-plane ICP (cv::ppf_match_3d::ICP) of the overlapping slave
// points onto the reference points they overlap; the rigid motion in the
// face frame.
Similarity icp_refinement(const SurfaceSample& slave, const SurfaceSample& reference,
                          const OverlapFit& o, int iterations, int levels);

}  // namespace rockface::photogrammetry

#include "core/photogrammetry/estimators/multi_image_registration.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numeric>
#include <optional>
#include <random>
#include <tuple>

#include <Eigen/Geometry>
#include <opencv2/flann.hpp>
#include <opencv2/surface_matching.hpp>

#include "core/common/error.h"
#include "core/common/parallel.h"
#include "core/photogrammetry/matching/feature_matching.h"
#include "core/photogrammetry/matching/guided_matching.h"
#include "core/photogrammetry/matching/image_overlap.h"
#include "core/photogrammetry/surface/pixel_lookup.h"

namespace rockface::photogrammetry {

namespace {

// Area-weighted vertex normals of the lattice mesh, unit length (zero where
// a vertex has no triangle).
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

// A thinned set of surface points (with normals) of one image, in the face frame.
struct SurfaceSample {
  std::vector<Eigen::Vector3d> points, normals;
};

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

// Exact nearest neighbours in 3D (cv::flann single kd-tree).
class NearestPoint {
 public:
  explicit NearestPoint(const std::vector<Eigen::Vector3d>& points)
      : data_(static_cast<int>(points.size()), 3, CV_32F) {
    for (int i = 0; i < data_.rows; ++i)
      for (int k = 0; k < 3; ++k) data_.at<float>(i, k) = static_cast<float>(points[i](k));
    index_.build(data_, cv::flann::KDTreeIndexParams(1), cvflann::FLANN_DIST_L2);
  }
  // Index of the nearest point and its distance.
  std::pair<int, double> nearest(const Eigen::Vector3d& q) const {
    cv::Mat query(1, 3, CV_32F), idx(1, 1, CV_32S), dist(1, 1, CV_32F);
    for (int k = 0; k < 3; ++k) query.at<float>(0, k) = static_cast<float>(q(k));
    index_.knnSearch(query, idx, dist, 1, cv::flann::SearchParams(32));
    return {idx.at<int>(0, 0), std::sqrt(static_cast<double>(dist.at<float>(0, 0)))};
  }

 private:
  cv::Mat data_;
  mutable cv::flann::Index index_;
};

Similarity from_umeyama(const Eigen::Matrix3Xd& src, const Eigen::Matrix3Xd& dst) {
  const Eigen::Matrix4d T = Eigen::umeyama(src, dst, true);
  const Eigen::Matrix3d sR = T.topLeftCorner<3, 3>();
  Similarity s;
  s.scale = std::cbrt(sR.determinant());
  s.R = sR / s.scale;
  s.t = T.topRightCorner<3, 1>();
  return s;
}

struct TiePoints {
  std::vector<Eigen::Vector3d> reference;  // face frame
  std::vector<Eigen::Vector3d> slave;      // slave's own frame
};

// The same surface points, each in its own image's frame.
struct RawTiePoints {
  std::vector<Eigen::Vector3d> reference, slave;
  TiePoints in_face(const Similarity& reference_to_face) const {
    TiePoints t{{}, slave};
    for (const auto& p : reference) t.reference.push_back(reference_to_face.apply(p));
    return t;
  }
};

struct TieFit {
  Similarity slave_to_face;
  std::vector<int> inliers;
};

// Robust similarity: 3-point Umeyama samples, the largest consensus, then
// Umeyama over all of it.
TieFit fit_tie_points(const TiePoints& tie, double inlier_m, int iterations, std::uint64_t seed) {
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
  for (int it = 0; it < iterations; ++it) {
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
    if (in.size() > best.inliers.size()) best = {s, std::move(in)};
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

// Point-to-plane distances of the slave sample to the reference surface
// where the two overlap (nearest reference point within `overlap_m`).
struct OverlapFit {
  std::vector<int> slave, reference;  // sample indices of the overlapping pairs
  double rms = 0;
};

OverlapFit overlap(const SurfaceSample& slave, const SurfaceSample& reference,
                   const NearestPoint& tree, double overlap_m) {
  OverlapFit o;
  double sum2 = 0;
  for (std::size_t i = 0; i < slave.points.size(); ++i) {
    const auto [j, d] = tree.nearest(slave.points[i]);
    if (j < 0 || d > overlap_m) continue;
    const double e = (slave.points[i] - reference.points[j]).dot(reference.normals[j]);
    sum2 += e * e;
    o.slave.push_back(static_cast<int>(i));
    o.reference.push_back(j);
  }
  if (!o.slave.empty()) o.rms = std::sqrt(sum2 / static_cast<double>(o.slave.size()));
  return o;
}

cv::Mat point_cloud(const SurfaceSample& s, const std::vector<int>& rows) {
  cv::Mat pc(static_cast<int>(rows.size()), 6, CV_32F);
  for (int r = 0; r < pc.rows; ++r) {
    const int i = rows[r];
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

// Rigid point-to-plane ICP of the overlapping slave points onto the
// reference points; returns the rigid motion in the face frame.
Similarity icp_refinement(const SurfaceSample& slave, const SurfaceSample& reference,
                          const OverlapFit& o, const MultiImageOptions& options) {
  const cv::Mat src = point_cloud(slave, o.slave);
  const cv::Mat dst = point_cloud(reference, unique_sorted(o.reference));
  cv::ppf_match_3d::ICP icp(options.icp_iterations, 0.005f, 2.5f, options.icp_levels);
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

Similarity identity() {
  return {};
}

}  // namespace

FaceRegistration register_face_images(const std::vector<FaceImage>& images,
                                      const std::vector<FaceControlPoint>& control_points,
                                      const ReconstructionPreset& preset,
                                      const MultiImageOptions& options, Progress& progress) {
  if (images.empty()) throw InputError("3D images", "none given");
  const std::size_t n = images.size();
  FaceRegistration out;
  out.images.resize(n);
  std::vector<bool> placed(n, false);
  std::vector<std::vector<Eigen::Vector3d>> normals(n);
  std::vector<PixelLookup> grids;
  std::vector<double> spacing(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (images[i].mesh.size() < 3)
      throw InputError(images[i].name, "the 3D image has no surface to register");
    normals[i] = vertex_normals(images[i].mesh);
    grids.emplace_back(images[i].mesh);
    spacing[i] = images[i].mesh.median_edge_length();
    out.images[i].name = images[i].name;
  }
  out.images[0].to_face = identity();
  placed[0] = true;

  // SIFT is detected once per photograph (each at its own working scale),
  // all before the first match, on all cores.
  std::vector<ImageFeatures> features(n);
  parallel_for(n, [&](std::size_t i) {
    features[i] =
        detect_features(images[i].photograph,
                        working_scale(images[i].photograph.cols, preset.feature_max_width), preset);
  });
  // Which images overlap, from thumbnails (image_overlap.h): a new image is
  // matched first against the placed image that overlaps it most, and
  // against the others only while that gives too few tie points. Matching
  // every unplaced image against every placed one made the merge grow with
  // the square of the number of images.
  std::vector<Thumbnail> thumbnails;
  for (const auto& image : images) thumbnails.push_back(make_thumbnail(image.photograph));
  std::vector<std::vector<CoarseOverlap>> coarse(n, std::vector<CoarseOverlap>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      coarse[i][j] = coarse_overlap(thumbnails[i], thumbnails[j]);
      coarse[j][i] = coarse[i][j];
      coarse[j][i].shift_px = -coarse[i][j].shift_px;
    }

  // Tie points of a (placed, slave) pair, matched once each way: guided by
  // the pair's coarse shift where it was found clearly (guided_matching.h),
  // else (or when the guided ones fit too few) against all keypoints. The
  // images of one wave (below) are matched on several threads: each item
  // inserts only its own slave's keys, under the lock; the map's nodes stay
  // where they are.
  std::map<std::tuple<std::size_t, std::size_t, bool>, RawTiePoints> matched;
  std::mutex matched_lock;
  auto tie_points = [&](std::size_t ref, std::size_t slave, bool guided) -> TiePoints {
    RawTiePoints* raw = nullptr;
    bool fresh = false;
    {
      const std::lock_guard<std::mutex> lock(matched_lock);
      auto [it, inserted] = matched.try_emplace({ref, slave, guided});
      raw = &it->second;
      fresh = inserted;
    }
    if (fresh) {
      const FeatureMatches m =
          guided ? match_guided(features[ref], features[slave], coarse[ref][slave].shift_px,
                                options.guide_window * images[ref].photograph.cols, preset)
                 : match_detected(features[ref], features[slave], preset);
      for (std::size_t k = 0; k < m.size(); ++k) {
        const int a = grids[ref].nearest(m.left[k]);
        const int b = grids[slave].nearest(m.right[k]);
        if (a < 0 || b < 0) continue;
        raw->reference.push_back(images[ref].mesh.vertices[a]);
        raw->slave.push_back(images[slave].mesh.vertices[b]);
      }
    }
    return raw->in_face(out.images[ref].to_face);
  };
  std::vector<std::string> tried(n);  // what each slave was tried against
  std::vector<char> failed(n, 0);     // against every image placed when it was tried

  // One image registered to the images placed so far (`placed` is not
  // changed while a wave runs).
  struct Placement {
    bool ok = false;
    int reference = -1, tie_points = 0;
    bool guided = false;
    double surface_rms_before_icp_m = 0;
    // The residuals through to_face, in face units before ground control
    // (ImageResidual); the final transform moves slave and reference alike.
    double overlap = 0, surface_rms_m = 0, tie_rms_m = 0;
    Similarity to_face;
    std::string tried;
  };
  auto place = [&](std::size_t i) {
    Placement result;
    std::vector<std::size_t> candidates;
    for (std::size_t j = 0; j < n; ++j)
      if (placed[j]) candidates.push_back(j);
    std::stable_sort(candidates.begin(), candidates.end(), [&](std::size_t x, std::size_t y) {
      return coarse[i][x].score() > coarse[i][y].score();
    });
    TieFit best;
    double best_inlier_m = 0;
    for (const std::size_t j : candidates) {
      const double scale = out.images[j].to_face.scale;
      const double inlier_m =
          options.inlier_sigmas * images[j].sigma_z * scale + spacing[j] * scale;
      bool guided = coarse[j][i].response >= options.guide_min_response;
      TieFit fit = fit_tie_points(tie_points(j, i, guided), inlier_m, options.ransac_iterations,
                                  options.seed + i * 7919 + j);
      if (guided && static_cast<int>(fit.inliers.size()) < options.enough_tie_points) {
        TieFit all = fit_tie_points(tie_points(j, i, false), inlier_m, options.ransac_iterations,
                                    options.seed + i * 7919 + j);
        if (all.inliers.size() > fit.inliers.size()) {
          fit = std::move(all);
          guided = false;
        }
      }
      result.tried += (result.tried.empty() ? "" : ", ") + images[j].name + " (" +
                      std::to_string(fit.inliers.size()) + " tie points)";
      if (fit.inliers.size() > best.inliers.size()) {
        best = fit;
        result.reference = static_cast<int>(j);
        result.guided = guided;
        best_inlier_m = inlier_m;
      }
      if (static_cast<int>(best.inliers.size()) >= options.enough_tie_points) break;
    }
    if (static_cast<int>(best.inliers.size()) < options.min_tie_points) return result;
    result.ok = true;
    result.tie_points = static_cast<int>(best.inliers.size());
    // Refine on the overlapping surface.
    const std::size_t j = static_cast<std::size_t>(result.reference);
    const SurfaceSample reference =
        sample_surface(images[j].mesh, normals[j], out.images[j].to_face, options.icp_max_points);
    const NearestPoint tree(reference.points);
    const double overlap_m = options.overlap_distance_factor * best_inlier_m;
    const SurfaceSample before =
        sample_surface(images[i].mesh, normals[i], best.slave_to_face, options.icp_max_points);
    const OverlapFit o = overlap(before, reference, tree, overlap_m);
    result.surface_rms_before_icp_m = o.rms;
    result.to_face = best.slave_to_face;
    result.surface_rms_m = o.rms;
    result.overlap = before.points.empty() ? 0.0
                                           : static_cast<double>(o.slave.size()) /
                                                 static_cast<double>(before.points.size());
    if (o.slave.size() >= 100) {
      const Similarity rigid = icp_refinement(before, reference, o, options);
      const Similarity refined = best.slave_to_face.then(rigid);
      const SurfaceSample after =
          sample_surface(images[i].mesh, normals[i], refined, options.icp_max_points);
      const OverlapFit o2 = overlap(after, reference, tree, overlap_m);
      // ICP is kept only when it brings the surfaces closer over no less overlap.
      if (o2.rms < o.rms && o2.slave.size() + o.slave.size() / 10 >= o.slave.size()) {
        result.to_face = refined;
        result.surface_rms_m = o2.rms;
        result.overlap = after.points.empty() ? 0.0
                                              : static_cast<double>(o2.slave.size()) /
                                                    static_cast<double>(after.points.size());
      }
    }
    // The tie points through the final transform, those within the overlap
    // distance (the others are the RANSAC outliers).
    const TiePoints t = tie_points(j, i, result.guided);
    double sum2 = 0;
    int count = 0;
    for (std::size_t k = 0; k < t.slave.size(); ++k) {
      const double d = (result.to_face.apply(t.slave[k]) - t.reference[k]).norm();
      if (d < overlap_m) {
        sum2 += d * d;
        ++count;
      }
    }
    result.tie_rms_m = count ? std::sqrt(sum2 / count) : 0.0;
    return result;
  };

  std::size_t done = 1;
  while (done < n) {
    // A wave: the unplaced images that need not wait for another
    // (options.wave_share), registered side by side; they do not depend on
    // each other, and which images form a wave does not depend on the
    // number of threads, so neither do the results. When no image
    // qualifies, the one that overlaps a placed image most goes alone.
    std::vector<std::size_t> wave;
    int next = -1;
    double next_score = -1;
    std::vector<double> with_placed(n, 0.0);
    for (std::size_t i = 1; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if (j != i && placed[j]) with_placed[i] = std::max(with_placed[i], coarse[i][j].score());
    for (std::size_t i = 1; i < n; ++i) {
      if (placed[i] || failed[i]) continue;
      // Waiting for j pays only when j overlaps i clearly better than any
      // placed image and j can be placed no later than i. Comparing the
      // best overlap with any image instead kept a station from going
      // beside its mirror image whenever the thumbnails' noisy peak rated
      // its outer neighbour (not placeable yet) a little higher.
      bool waits = false;
      for (std::size_t j = 1; j < n && !waits; ++j)
        waits = j != i && !placed[j] && !failed[j] &&
                options.wave_share * coarse[i][j].score() > with_placed[i] &&
                with_placed[j] >= with_placed[i];
      if (with_placed[i] > 0 && !waits) wave.push_back(i);
      if (with_placed[i] > next_score) {
        next = static_cast<int>(i);
        next_score = with_placed[i];
      }
    }
    if (wave.empty() && next >= 0) wave.push_back(static_cast<std::size_t>(next));
    if (wave.empty()) {
      for (std::size_t i = 1; i < n; ++i)
        if (!placed[i])
          throw InputError(images[i].name,
                           "does not overlap " + tried[i] + ": fewer than " +
                               std::to_string(options.min_tie_points) +
                               " tie points agree on one surface (a photograph of another "
                               "face, or no area in common)");
    }
    progress.step("registering " + images[wave.front()].name, static_cast<double>(done) / n);
    std::vector<Placement> results(wave.size());
    parallel_for(wave.size(), [&](std::size_t k) { results[k] = place(wave[k]); });
    bool progressed = false;
    for (std::size_t k = 0; k < wave.size(); ++k) {
      const std::size_t i = wave[k];
      tried[i] = results[k].tried;
      if (!results[k].ok) {
        failed[i] = 1;  // an image placed later may overlap it
        continue;
      }
      ImageResidual& r = out.images[i];
      r.reference = results[k].reference;
      r.tie_points = results[k].tie_points;
      r.surface_rms_before_icp_m = results[k].surface_rms_before_icp_m;
      r.overlap = results[k].overlap;
      r.surface_rms_m = results[k].surface_rms_m;
      r.tie_rms_m = results[k].tie_rms_m;
      r.to_face = results[k].to_face;
      placed[i] = true;
      ++done;
      progressed = true;
    }
    // A newly placed image may be the one a failed image overlaps.
    if (progressed) std::fill(failed.begin(), failed.end(), 0);
  }

  // Ground control moves the whole block.
  if (!control_points.empty()) {
    std::vector<Eigen::Vector3d> model;
    std::vector<ControlPoint> points;
    for (const auto& cp : control_points) {
      const std::string where = "control point " + cp.id;
      if (cp.image < 0 || static_cast<std::size_t>(cp.image) >= n)
        throw InputError(where, "names image " + std::to_string(cp.image) + ", which is not given");
      const int v = grids[cp.image].nearest(cp.pixel);
      if (v < 0)
        throw InputError(where,
                         "no reconstructed surface at its pixel in " + images[cp.image].name);
      model.push_back(out.images[cp.image].to_face.apply(images[cp.image].mesh.vertices[v]));
      points.push_back({cp.id, cp.pixel, cp.world});
    }
    if (points.size() < 3)
      throw InputError("control points",
                       "three or more are needed, " + std::to_string(points.size()) + " given");
    out.control_points = register_to_control_points(model, points, "control points");
    out.datum = out.control_points->datum;
    for (auto& r : out.images) r.to_face = r.to_face.then(out.control_points->transform);
  }

  // The residuals were measured as each image was placed (the ICP's last
  // overlap is the final one); ground control moves slave and reference by
  // one similarity, which scales every distance alike.
  const double to_final = out.control_points ? out.control_points->transform.scale : 1.0;
  for (std::size_t i = 1; i < n; ++i) {
    ImageResidual& r = out.images[i];
    r.surface_rms_before_icp_m *= to_final;
    r.surface_rms_m *= to_final;
    r.tie_rms_m *= to_final;
  }
  progress.step("done", 1.0);
  return out;
}

SurfaceMesh merged_surface(const std::vector<FaceImage>& images, const FaceRegistration& face) {
  SurfaceMesh out;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const SurfaceMesh& m = images[i].mesh;
    const int offset = static_cast<int>(out.vertices.size());
    for (const auto& v : m.vertices) out.vertices.push_back(face.images[i].to_face.apply(v));
    out.colours.insert(out.colours.end(), m.colours.begin(), m.colours.end());
    out.pixels.insert(out.pixels.end(), m.pixels.begin(), m.pixels.end());
    out.texcoords.insert(out.texcoords.end(), m.texcoords.begin(), m.texcoords.end());
    for (const auto& t : m.triangles)
      out.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    if (i == 0) {
      out.texture_width = m.texture_width;
      out.texture_height = m.texture_height;
    }
  }
  return out;
}

}  // namespace rockface::photogrammetry

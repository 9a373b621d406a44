#include "core/photogrammetry/estimators/multi_image_registration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <numeric>
#include <optional>
#include <tuple>

#include <time.h>

#include <Eigen/Geometry>

#include "core/common/error.h"
#include "core/common/parallel.h"
#include "core/photogrammetry/estimators/multi_image_registration_fit.h"
#include "core/photogrammetry/matching/feature_matching.h"
#include "core/photogrammetry/matching/guided_matching.h"
#include "core/photogrammetry/matching/image_overlap.h"
#include "core/photogrammetry/surface/pixel_lookup.h"

namespace rockface::photogrammetry {

namespace {

Similarity identity() {
  return {};
}

// The same surface points, each in its own image's frame.
struct RawTiePoints {
  std::vector<Eigen::Vector3d> reference, slave;
  TiePoints in_face(const Similarity& reference_to_face) const {
    TiePoints t{{}, slave};
    t.reference.reserve(reference.size());
    for (const auto& p : reference) t.reference.push_back(reference_to_face.apply(p));
    return t;
  }
};

// A placed image as the reference of others: its surface sample in the face
// frame and the index of its points, made once, whichever image needs it first.
struct ReferenceSurface {
  SurfaceSample sample;
  std::optional<NearestWithin> near;
  std::once_flag made;
};

// Wall seconds since `from`.
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point from) {
  return std::chrono::duration<double>(Clock::now() - from).count();
}

// CPU seconds of the calling thread, or of the whole process.
double cpu_seconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
double thread_cpu() {
  return cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
}
double process_cpu() {
  return cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
}

// f(), its wall and thread CPU seconds added to wall and cpu.
template <class F>
auto timed(double& wall, double& cpu, F&& f) {
  const Clock::time_point t0 = Clock::now();
  const double c0 = thread_cpu();
  auto r = f();
  wall += seconds_since(t0);
  cpu += thread_cpu() - c0;
  return r;
}

}  // namespace

FaceRegistration register_face_images(const std::vector<FaceImage>& images,
                                      const std::vector<FaceControlPoint>& control_points,
                                      const ReconstructionPreset& preset,
                                      const MultiImageOptions& options, Progress& progress) {
  if (images.empty()) throw InputError("3D images", "none given");
  const std::size_t n = images.size();
  const Clock::time_point started = Clock::now();
  const double cpu_started = process_cpu();
  FaceRegistration out;
  out.images.resize(n);
  MergeTimes& times = out.times;
  times.match_s.assign(n, 0.0);
  times.ransac_s.assign(n, 0.0);
  times.surface_s.assign(n, 0.0);
  times.match_cpu_s.assign(n, 0.0);
  times.ransac_cpu_s.assign(n, 0.0);
  times.surface_cpu_s.assign(n, 0.0);
  times.wave.assign(n, -1);
  std::vector<bool> placed(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    if (images[i].mesh.size() < 3)
      throw InputError(images[i].name, "the 3D image has no surface to register");
    out.images[i].name = images[i].name;
  }
  out.images[0].to_face = identity();
  placed[0] = true;

  // What each image needs, made once per image and all images side by side
  // on all cores: its SIFT features (at the width the registration needs:
  // MultiImageOptions::feature_max_width), and its surface normals, pixel
  // lookup, lattice spacing and thumbnail.
  std::vector<std::vector<Eigen::Vector3d>> normals(n);
  std::vector<std::optional<PixelLookup>> grids(n);
  std::vector<double> spacing(n);
  std::vector<ImageFeatures> features(n);
  std::vector<Thumbnail> thumbnails(n);
  const int feature_width =
      options.feature_max_width > 0 ? options.feature_max_width : preset.feature_max_width;
  // Two tasks per image, SIFT first (the longest first packs the cores
  // best: five images on two cores then take 2.5 rounds, not the 3 that one
  // task per image took).
  std::vector<double> task_s(2 * n);
  parallel_for(2 * n, [&](std::size_t task) {
    const std::size_t i = task % n;
    const Clock::time_point t0 = Clock::now();
    if (task < n) {
      features[i] = detect_features(
          images[i].photograph, working_scale(images[i].photograph.cols, feature_width), preset);
    } else {
      normals[i] = vertex_normals(images[i].mesh);
      grids[i].emplace(images[i].mesh);
      spacing[i] = images[i].mesh.median_edge_length();
      thumbnails[i] = make_thumbnail(images[i].photograph);
    }
    task_s[task] = seconds_since(t0);
  });
  // The stage's wall time shared by its parts' thread times.
  const double prepared = seconds_since(started);
  const double features_sum = std::accumulate(task_s.begin(), task_s.begin() + n, 0.0);
  const double prepare_sum = std::accumulate(task_s.begin() + n, task_s.end(), 0.0);
  times.prepare_s = prepared * prepare_sum / std::max(1e-9, prepare_sum + features_sum);
  times.features_s = prepared - times.prepare_s;
  times.features_cpu_s = process_cpu() - cpu_started;
  Clock::time_point stage = Clock::now();
  double stage_cpu = process_cpu();

  // Which images overlap, from thumbnails (image_overlap.h): a new image is
  // matched first against the placed image that overlaps it most, and
  // against the others only while that gives too few tie points. Matching
  // every unplaced image against every placed one made the merge grow with
  // the square of the number of images. Every pair once, on all cores.
  std::vector<std::vector<CoarseOverlap>> coarse(n, std::vector<CoarseOverlap>(n));
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) pairs.emplace_back(i, j);
  parallel_for(pairs.size(), [&](std::size_t k) {
    const auto [i, j] = pairs[k];
    coarse[i][j] = coarse_overlap(thumbnails[i], thumbnails[j]);
    coarse[j][i] = coarse[i][j];
    coarse[j][i].shift_px = -coarse[i][j].shift_px;
  });
  times.thumbnails_s = seconds_since(stage);
  times.thumbnails_cpu_s = process_cpu() - stage_cpu;

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
        const int a = grids[ref]->nearest(m.left[k]);
        const int b = grids[slave]->nearest(m.right[k]);
        if (a < 0 || b < 0) continue;
        raw->reference.push_back(images[ref].mesh.vertices[a]);
        raw->slave.push_back(images[slave].mesh.vertices[b]);
      }
    }
    return raw->in_face(out.images[ref].to_face);
  };
  // The overlap distance of a reference depends on that image alone
  // (its sigma_z, lattice spacing and scale), so its index serves every
  // image registered to it.
  std::vector<ReferenceSurface> references(n);
  std::vector<std::string> tried(n);  // what each slave was tried against
  std::vector<char> failed(n, 0);     // against every image placed when it was tried

  // One image registered to the images placed so far (`placed` is not
  // changed while a wave runs).
  struct Placement {
    bool ok = false;
    int reference = -1, tie_points = 0;
    bool guided = false;
    double surface_rms_before_icp_m = 0;
    double match_s = 0, ransac_s = 0, surface_s = 0;  // MergeTimes
    double match_cpu_s = 0, ransac_cpu_s = 0, surface_cpu_s = 0;
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
      TiePoints tie =
          timed(result.match_s, result.match_cpu_s, [&] { return tie_points(j, i, guided); });
      TieFit fit = timed(result.ransac_s, result.ransac_cpu_s, [&] {
        return fit_tie_points(tie, inlier_m, options.ransac_iterations,
                              options.seed + i * 7919 + j);
      });
      if (guided && static_cast<int>(fit.inliers.size()) < options.enough_tie_points) {
        tie = timed(result.match_s, result.match_cpu_s, [&] { return tie_points(j, i, false); });
        TieFit all = timed(result.ransac_s, result.ransac_cpu_s, [&] {
          return fit_tie_points(tie, inlier_m, options.ransac_iterations,
                                options.seed + i * 7919 + j);
        });
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
    const Clock::time_point surface_started = Clock::now();
    const double surface_cpu = thread_cpu();
    const std::size_t j = static_cast<std::size_t>(result.reference);
    const double overlap_m = options.overlap_distance_factor * best_inlier_m;
    ReferenceSurface& ref = references[j];
    std::call_once(ref.made, [&] {
      ref.sample =
          sample_surface(images[j].mesh, normals[j], out.images[j].to_face, options.icp_max_points);
      ref.near.emplace(ref.sample.points, overlap_m);
    });
    const SurfaceSample& reference = ref.sample;
    const NearestWithin& near = *ref.near;
    const SurfaceSample before =
        sample_surface(images[i].mesh, normals[i], best.slave_to_face, options.icp_max_points);
    const OverlapFit o = overlap(before, reference, near);
    result.surface_rms_before_icp_m = o.rms;
    result.to_face = best.slave_to_face;
    result.surface_rms_m = o.rms;
    result.overlap = before.points.empty() ? 0.0
                                           : static_cast<double>(o.slave.size()) /
                                                 static_cast<double>(before.points.size());
    if (o.slave.size() >= 100) {
      const Similarity rigid =
          icp_refinement(before, reference, o, options.icp_iterations, options.icp_levels);
      const Similarity refined = best.slave_to_face.then(rigid);
      const SurfaceSample after = moved(before, rigid);
      const OverlapFit o2 = overlap(after, reference, near);
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
    result.surface_s = seconds_since(surface_started);
    result.surface_cpu_s = thread_cpu() - surface_cpu;
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
    const Clock::time_point wave_started = Clock::now();
    const double wave_cpu = process_cpu();
    parallel_for(wave.size(), [&](std::size_t k) { results[k] = place(wave[k]); });
    times.waves_s.push_back(seconds_since(wave_started));
    times.waves_cpu_s.push_back(process_cpu() - wave_cpu);
    bool progressed = false;
    for (std::size_t k = 0; k < wave.size(); ++k) {
      const std::size_t i = wave[k];
      tried[i] = results[k].tried;
      times.match_s[i] += results[k].match_s;
      times.ransac_s[i] += results[k].ransac_s;
      times.surface_s[i] += results[k].surface_s;
      times.match_cpu_s[i] += results[k].match_cpu_s;
      times.ransac_cpu_s[i] += results[k].ransac_cpu_s;
      times.surface_cpu_s[i] += results[k].surface_cpu_s;
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
      times.wave[i] = static_cast<int>(times.waves_s.size()) - 1;
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
      const int v = grids[static_cast<std::size_t>(cp.image)]->nearest(cp.pixel);
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
  // Each image's working data (normals and pixel lookup of ~1 M vertices,
  // features, surface index) freed side by side: on one thread, at the
  // function's end, this took as long as a registration.
  stage = Clock::now();
  stage_cpu = process_cpu();
  parallel_for(n, [&](std::size_t i) {
    normals[i] = {};
    grids[i].reset();
    features[i] = {};
    references[i].near.reset();
    references[i].sample = {};
  });
  times.release_s = seconds_since(stage);
  times.release_cpu_s = process_cpu() - stage_cpu;
  times.total_s = seconds_since(started);
  times.total_cpu_s = process_cpu() - cpu_started;
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

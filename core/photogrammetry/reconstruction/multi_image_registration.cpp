#include "core/photogrammetry/reconstruction/multi_image_registration.h"

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
#include "core/photogrammetry/reconstruction/multi_image_registration_phases.h"
#include "core/photogrammetry/surface/pixel_lookup.h"

namespace rockface::photogrammetry {

namespace {

Similarity identity() {
  return {};
}

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

namespace registration_phases {

PreparedImages prepare_images(const std::vector<FaceImage>& images,
                              const ReconstructionPreset& preset, const MultiImageOptions& options,
                              Clock::time_point started, double cpu_started, MergeTimes& times) {
  const std::size_t n = images.size();
  PreparedImages p;
  p.normals.resize(n);
  p.grids.resize(n);
  p.spacing.resize(n);
  p.features.resize(n);
  p.thumbnails.resize(n);
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
      p.features[i] = detect_features(
          images[i].photograph, working_scale(images[i].photograph.cols, feature_width), preset);
    } else {
      p.normals[i] = vertex_normals(images[i].mesh);
      p.grids[i].emplace(images[i].mesh);
      p.spacing[i] = images[i].mesh.median_edge_length();
      p.thumbnails[i] = make_thumbnail(images[i].photograph);
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
  return p;
}

CoarseOverlaps coarse_overlaps(const std::vector<Thumbnail>& thumbnails) {
  const std::size_t n = thumbnails.size();
  CoarseOverlaps coarse(n, std::vector<CoarseOverlap>(n));
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) pairs.emplace_back(i, j);
  parallel_for(pairs.size(), [&](std::size_t k) {
    const auto [i, j] = pairs[k];
    coarse[i][j] = coarse_overlap(thumbnails[i], thumbnails[j]);
    coarse[j][i] = coarse[i][j];
    coarse[j][i].shift_px = -coarse[i][j].shift_px;
  });
  return coarse;
}

std::vector<std::size_t> next_wave(const CoarseOverlaps& coarse, const std::vector<bool>& placed,
                                   const std::vector<char>& failed, double wave_share) {
  const std::size_t n = placed.size();
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
              wave_share * coarse[i][j].score() > with_placed[i] &&
              with_placed[j] >= with_placed[i];
    if (with_placed[i] > 0 && !waits) wave.push_back(i);
    if (with_placed[i] > next_score) {
      next = static_cast<int>(i);
      next_score = with_placed[i];
    }
  }
  if (wave.empty() && next >= 0) wave.push_back(static_cast<std::size_t>(next));
  return wave;
}

TieMatcher::TieMatcher(const std::vector<FaceImage>& images, const PreparedImages& prepared,
                       const CoarseOverlaps& coarse, const ReconstructionPreset& preset,
                       const MultiImageOptions& options)
    : images_(images), prepared_(prepared), coarse_(coarse), preset_(preset), options_(options) {}

// Guided by the pair's coarse shift where it was found clearly
// (guided_matching.h), else against all keypoints. The images of one wave
// are matched on several threads: each item inserts only its own slave's
// keys, under the lock; the map's nodes stay where they are.
TiePoints TieMatcher::tie_points(std::size_t ref, std::size_t slave, bool guided,
                                 const Similarity& reference_to_face) {
  Raw* raw = nullptr;
  bool fresh = false;
  {
    const std::lock_guard<std::mutex> lock(lock_);
    auto [it, inserted] = matched_.try_emplace({ref, slave, guided});
    raw = &it->second;
    fresh = inserted;
  }
  if (fresh) {
    const FeatureMatches m =
        guided ? match_guided(prepared_.features[ref], prepared_.features[slave],
                              coarse_[ref][slave].shift_px,
                              options_.guide_window * images_[ref].photograph.cols, preset_)
               : match_detected(prepared_.features[ref], prepared_.features[slave], preset_);
    for (std::size_t k = 0; k < m.size(); ++k) {
      const int a = prepared_.grids[ref]->nearest(m.left[k]);
      const int b = prepared_.grids[slave]->nearest(m.right[k]);
      if (a < 0 || b < 0) continue;
      raw->reference.push_back(images_[ref].mesh.vertices[a]);
      raw->slave.push_back(images_[slave].mesh.vertices[b]);
    }
  }
  TiePoints t{{}, raw->slave};
  t.reference.reserve(raw->reference.size());
  for (const auto& p : raw->reference) t.reference.push_back(reference_to_face.apply(p));
  return t;
}

namespace {

// The placed image that image i shares most tie points with (those that
// overlap it most by thumbnail tried first, until one gives
// options.enough_tie_points), its similarity fit and its inlier distance.
struct ReferenceFit {
  TieFit fit;
  double inlier_m = 0;
};
ReferenceFit find_reference(std::size_t i, const PlacementContext& c, Placement& result) {
  const std::size_t n = c.images.size();
  const MultiImageOptions& options = c.options;
  std::vector<std::size_t> candidates;
  for (std::size_t j = 0; j < n; ++j)
    if (c.placed[j]) candidates.push_back(j);
  std::stable_sort(candidates.begin(), candidates.end(), [&](std::size_t x, std::size_t y) {
    return c.coarse[i][x].score() > c.coarse[i][y].score();
  });
  ReferenceFit best;
  for (const std::size_t j : candidates) {
    const Similarity& ref_to_face = c.residuals[j].to_face;
    const double scale = ref_to_face.scale;
    const double inlier_m =
        options.inlier_sigmas * c.images[j].sigma_z * scale + c.prepared.spacing[j] * scale;
    bool guided = c.coarse[j][i].response >= options.guide_min_response;
    TiePoints tie = timed(result.match_s, result.match_cpu_s,
                          [&] { return c.matcher.tie_points(j, i, guided, ref_to_face); });
    TieFit fit = timed(result.ransac_s, result.ransac_cpu_s, [&] {
      return fit_tie_points(tie, inlier_m, options.ransac_iterations, options.seed + i * 7919 + j);
    });
    if (guided && static_cast<int>(fit.inliers.size()) < options.enough_tie_points) {
      tie = timed(result.match_s, result.match_cpu_s,
                  [&] { return c.matcher.tie_points(j, i, false, ref_to_face); });
      TieFit all = timed(result.ransac_s, result.ransac_cpu_s, [&] {
        return fit_tie_points(tie, inlier_m, options.ransac_iterations,
                              options.seed + i * 7919 + j);
      });
      if (all.inliers.size() > fit.inliers.size()) {
        fit = std::move(all);
        guided = false;
      }
    }
    result.tried += (result.tried.empty() ? "" : ", ") + c.images[j].name + " (" +
                    std::to_string(fit.inliers.size()) + " tie points)";
    if (fit.inliers.size() > best.fit.inliers.size()) {
      best.fit = fit;
      result.reference = static_cast<int>(j);
      result.guided = guided;
      best.inlier_m = inlier_m;
    }
    if (static_cast<int>(best.fit.inliers.size()) >= options.enough_tie_points) break;
  }
  return best;
}

// The tie points' similarity refined by ICP on the surface image i shares
// with its reference (kept only when it brings the surfaces closer over no
// less overlap): result.to_face, overlap and surface RMS before and after.
void refine_on_surface(std::size_t i, const PlacementContext& c, const TieFit& best,
                       double overlap_m, Placement& result) {
  const MultiImageOptions& options = c.options;
  const std::size_t j = static_cast<std::size_t>(result.reference);
  ReferenceSurface& ref = c.references[j];
  std::call_once(ref.made, [&] {
    ref.sample = sample_surface(c.images[j].mesh, c.prepared.normals[j], c.residuals[j].to_face,
                                options.icp_max_points);
    ref.near.emplace(ref.sample.points, overlap_m);
  });
  const SurfaceSample& reference = ref.sample;
  const NearestWithin& near = *ref.near;
  const SurfaceSample before = sample_surface(c.images[i].mesh, c.prepared.normals[i],
                                              best.slave_to_face, options.icp_max_points);
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
}

}  // namespace

double tie_point_rms(const TiePoints& tie, const Similarity& to_face, double max_distance) {
  double sum2 = 0;
  int count = 0;
  for (std::size_t k = 0; k < tie.slave.size(); ++k) {
    const double d = (to_face.apply(tie.slave[k]) - tie.reference[k]).norm();
    if (d < max_distance) {
      sum2 += d * d;
      ++count;
    }
  }
  return count ? std::sqrt(sum2 / count) : 0.0;
}

Placement place_image(std::size_t i, const PlacementContext& context) {
  Placement result;
  const ReferenceFit best = find_reference(i, context, result);
  if (static_cast<int>(best.fit.inliers.size()) < context.options.min_tie_points) return result;
  result.ok = true;
  result.tie_points = static_cast<int>(best.fit.inliers.size());
  // Refine on the overlapping surface.
  const Clock::time_point surface_started = Clock::now();
  const double surface_cpu = thread_cpu();
  const std::size_t j = static_cast<std::size_t>(result.reference);
  const double overlap_m = context.options.overlap_distance_factor * best.inlier_m;
  refine_on_surface(i, context, best.fit, overlap_m, result);
  // The tie points through the final transform, those within the overlap
  // distance (the others are the RANSAC outliers).
  const TiePoints t = context.matcher.tie_points(j, i, result.guided, context.residuals[j].to_face);
  result.tie_rms_m = tie_point_rms(t, result.to_face, overlap_m);
  result.surface_s = seconds_since(surface_started);
  result.surface_cpu_s = thread_cpu() - surface_cpu;
  return result;
}

std::size_t record_wave(const std::vector<std::size_t>& wave, const std::vector<Placement>& results,
                        FaceRegistration& out, std::vector<bool>& placed, std::vector<char>& failed,
                        std::vector<std::string>& tried) {
  MergeTimes& times = out.times;
  std::size_t placed_now = 0;
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
    ++placed_now;
  }
  // A newly placed image may be the one a failed image overlaps.
  if (placed_now > 0) std::fill(failed.begin(), failed.end(), 0);
  return placed_now;
}

void apply_ground_control(const std::vector<FaceImage>& images,
                          const std::vector<FaceControlPoint>& control_points,
                          const PreparedImages& prepared, FaceRegistration& out) {
  const std::size_t n = images.size();
  std::vector<Eigen::Vector3d> model;
  std::vector<ControlPoint> points;
  for (const auto& cp : control_points) {
    const std::string where = "control point " + cp.id;
    if (cp.image < 0 || static_cast<std::size_t>(cp.image) >= n)
      throw InputError(where, "names image " + std::to_string(cp.image) + ", which is not given");
    const int v = prepared.grids[static_cast<std::size_t>(cp.image)]->nearest(cp.pixel);
    if (v < 0)
      throw InputError(where, "no reconstructed surface at its pixel in " + images[cp.image].name);
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

void scale_residuals(FaceRegistration& out) {
  // The residuals were measured as each image was placed (the ICP's last
  // overlap is the final one); ground control moves slave and reference by
  // one similarity, which scales every distance alike.
  const double to_final = out.control_points ? out.control_points->transform.scale : 1.0;
  for (std::size_t i = 1; i < out.images.size(); ++i) {
    ImageResidual& r = out.images[i];
    r.surface_rms_before_icp_m *= to_final;
    r.surface_rms_m *= to_final;
    r.tie_rms_m *= to_final;
  }
}

}  // namespace registration_phases

namespace {

// The result with one residual per image, named, the master in the face
// frame; throws InputError for no images or an image without surface.
FaceRegistration start_registration(const std::vector<FaceImage>& images) {
  if (images.empty()) throw InputError("3D images", "none given");
  const std::size_t n = images.size();
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
  for (std::size_t i = 0; i < n; ++i) {
    if (images[i].mesh.size() < 3)
      throw InputError(images[i].name, "the 3D image has no surface to register");
    out.images[i].name = images[i].name;
  }
  out.images[0].to_face = identity();
  return out;
}

// The refusal of the first image that no wave could place.
[[noreturn]] void refuse_unplaced(const std::vector<FaceImage>& images,
                                  const std::vector<bool>& placed,
                                  const std::vector<std::string>& tried,
                                  const MultiImageOptions& options) {
  for (std::size_t i = 1; i < images.size(); ++i)
    if (!placed[i])
      throw InputError(images[i].name,
                       "does not overlap " + tried[i] + ": fewer than " +
                           std::to_string(options.min_tie_points) +
                           " tie points agree on one surface (a photograph of another "
                           "face, or no area in common)");
  throw InputError("3D images", "no image left to register");
}

}  // namespace

FaceRegistration register_face_images(const std::vector<FaceImage>& images,
                                      const std::vector<FaceControlPoint>& control_points,
                                      const ReconstructionPreset& preset,
                                      const MultiImageOptions& options, Progress& progress) {
  using namespace registration_phases;
  const Clock::time_point started = Clock::now();
  const double cpu_started = process_cpu();
  FaceRegistration out = start_registration(images);
  const std::size_t n = images.size();
  MergeTimes& times = out.times;
  std::vector<bool> placed(n, false);
  placed[0] = true;

  // What each image needs, made once per image and all images side by side
  // on all cores: its SIFT features (at the width the registration needs:
  // MultiImageOptions::feature_max_width), and its surface normals, pixel
  // lookup, lattice spacing and thumbnail.
  PreparedImages prepared = prepare_images(images, preset, options, started, cpu_started, times);
  Clock::time_point stage = Clock::now();
  double stage_cpu = process_cpu();

  // Which images overlap, from thumbnails (image_overlap.h): a new image is
  // matched first against the placed image that overlaps it most, and
  // against the others only while that gives too few tie points. Matching
  // every unplaced image against every placed one made the merge grow with
  // the square of the number of images. Every pair once, on all cores.
  const CoarseOverlaps coarse = coarse_overlaps(prepared.thumbnails);
  times.thumbnails_s = seconds_since(stage);
  times.thumbnails_cpu_s = process_cpu() - stage_cpu;

  TieMatcher matcher(images, prepared, coarse, preset, options);
  // The overlap distance of a reference depends on that image alone
  // (its sigma_z, lattice spacing and scale), so its index serves every
  // image registered to it.
  std::vector<ReferenceSurface> references(n);
  std::vector<std::string> tried(n);  // what each slave was tried against
  std::vector<char> failed(n, 0);     // against every image placed when it was tried
  const PlacementContext context{images, prepared,   coarse,  options,
                                 placed, out.images, matcher, references};

  std::size_t done = 1;
  while (done < n) {
    // A wave: the unplaced images that need not wait for another
    // (options.wave_share), registered side by side; they do not depend on
    // each other, and which images form a wave does not depend on the
    // number of threads, so neither do the results.
    const std::vector<std::size_t> wave = next_wave(coarse, placed, failed, options.wave_share);
    if (wave.empty()) refuse_unplaced(images, placed, tried, options);
    progress.step("registering " + images[wave.front()].name, static_cast<double>(done) / n);
    std::vector<Placement> results(wave.size());
    const Clock::time_point wave_started = Clock::now();
    const double wave_cpu = process_cpu();
    parallel_for(wave.size(), [&](std::size_t k) { results[k] = place_image(wave[k], context); });
    times.waves_s.push_back(seconds_since(wave_started));
    times.waves_cpu_s.push_back(process_cpu() - wave_cpu);
    done += record_wave(wave, results, out, placed, failed, tried);
  }

  // Ground control moves the whole block.
  if (!control_points.empty()) apply_ground_control(images, control_points, prepared, out);
  scale_residuals(out);

  // Each image's working data (normals and pixel lookup of ~1 M vertices,
  // features, surface index) freed side by side: on one thread, at the
  // function's end, this took as long as a registration.
  stage = Clock::now();
  stage_cpu = process_cpu();
  parallel_for(n, [&](std::size_t i) {
    prepared.normals[i] = {};
    prepared.grids[i].reset();
    prepared.features[i] = {};
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

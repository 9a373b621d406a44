#pragma once
// What the merge benchmarks share (face_merge_bench.cpp, face_merge_ratio_bench.cpp):
// the synthetic face's pairs reconstructed once per station, one timed
// merge with its wall and CPU time and its residuals against the truth.
//
// The face: tests/support/multi_image_face.h, 1200 x 800 px,
// standard preset; the station at 0 is registered by range pole and compass,
// the others are registered to it (photogrammetry::register_face_images).
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "core/photogrammetry/reconstruction/multi_image_registration.h"
#include "tests/support/multi_image_face.h"

namespace rockface::bench {

namespace rp = rockface::photogrammetry;
namespace rt = rockface::testing;

// One reconstructed pair per station offset (East, metres), made once.
inline const rt::FacePair& pair_at(double offset) {
  static std::map<double, rt::FacePair> cache;
  auto it = cache.find(offset);
  if (it == cache.end())
    it = cache
             .emplace(offset,
                      rt::photograph_and_reconstruct(rt::multi_image_face(offset), offset == 0.0))
             .first;
  return it->second;
}

inline std::vector<rp::FaceImage> face_images(const std::vector<double>& offsets) {
  std::vector<rp::FaceImage> images;
  for (double o : offsets)
    images.push_back(rt::face_image(pair_at(o), "station " + std::to_string(o) + " m"));
  return images;
}

// One merge: its wall and process CPU time (every thread), where the time
// went, and the residuals against the truth.
struct MergeRun {
  double wall_s = 0, cpu_s = 0;
  rp::MergeTimes times;
  double overlap = 0, tie_rms = 0, surface_rms = 0, truth_rms = 0, width = 0;
  int tie_points = 1 << 30;
};

inline double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

inline double load_average() {
  double load = 0;
  if (FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &load) != 1) load = 0;
    std::fclose(f);
  }
  return load;
}

// The registration alone is timed; the residuals against the truth after.
inline MergeRun run_merge(const std::vector<rp::FaceImage>& images,
                          const rp::MultiImageOptions& options = {}) {
  MergeRun run;
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = process_cpu_s();
  NoProgress progress;
  const rp::FaceRegistration face =
      rp::register_face_images(images, {}, rp::preset_standard(), options, progress);
  run.cpu_s = process_cpu_s() - cpu0;
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  run.times = face.times;
  const Eigen::Vector3d origin = rt::face_origin(pair_at(0.0));
  for (std::size_t i = 0; i < images.size(); ++i) {
    const rp::ImageResidual& r = face.images[i];
    if (i > 0) {
      run.overlap += r.overlap / static_cast<double>(images.size() - 1);
      run.tie_points = std::min(run.tie_points, r.tie_points);
      run.tie_rms = std::max(run.tie_rms, r.tie_rms_m);
      run.surface_rms = std::max(run.surface_rms, r.surface_rms_m);
    }
    double sum2 = 0;
    std::size_t n = 0;
    for (std::size_t v = 0; v < images[i].mesh.size(); v += 5) {
      const auto d = rt::distance_to_face(r.to_face.apply(images[i].mesh.vertices[v]) + origin);
      if (!d || *d > 0.5) continue;  // the pole, 3 m in front of the face, or off the facets
      sum2 += *d * *d;
      ++n;
    }
    if (n > 0) run.truth_rms = std::max(run.truth_rms, std::sqrt(sum2 / static_cast<double>(n)));
  }
  const rp::SurfaceMesh merged = rp::merged_surface(images, face);
  double west = 1e9, east = -1e9;
  for (const auto& v : merged.vertices) {
    const Eigen::Vector3d w = v + origin;
    const auto d = rt::distance_to_face(w);
    if (!d || *d > 0.5) continue;
    west = std::min(west, w.x());
    east = std::max(east, w.x());
  }
  run.width = east - west;
  return run;
}

}  // namespace rockface::bench

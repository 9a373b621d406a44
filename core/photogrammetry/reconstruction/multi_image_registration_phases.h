#pragma once
// The phases of register_face_images (multi_image_registration.h), each a
// function of its own input, declared here so that each can be read and
// tested on its own:
//   1. prepare_images: SIFT features, normals, pixel lookup, lattice spacing
//      and thumbnail of every image, side by side;
//   2. coarse_overlaps: the thumbnails' phase correlation, every pair once;
//   3. next_wave: which unplaced images are registered next, side by side;
//   4. place_image: one image registered to the placed ones (a reference
//      found by tie points, then refined on the overlapping surface);
//   5. record_wave: the wave's placements written into the registration;
//   6. apply_ground_control: the whole block moved onto the control points;
//   7. scale_residuals: the residuals brought to the final frame's units.
#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/estimators/multi_image_registration_fit.h"
#include "core/photogrammetry/matching/feature_matching.h"
#include "core/photogrammetry/matching/image_overlap.h"
#include "core/photogrammetry/reconstruction/multi_image_registration.h"
#include "core/photogrammetry/surface/pixel_lookup.h"

namespace rockface::photogrammetry::registration_phases {

// What each image needs, made once per image.
struct PreparedImages {
  std::vector<std::vector<Eigen::Vector3d>> normals;
  std::vector<std::optional<PixelLookup>> grids;
  std::vector<double> spacing;  // median lattice edge length, the mesh's units
  std::vector<ImageFeatures> features;
  std::vector<Thumbnail> thumbnails;
};

// Every image's SIFT features (at options.feature_max_width, else the
// preset's) and its normals, pixel lookup, lattice spacing and thumbnail,
// all images side by side. Sets times.prepare_s, features_s and
// features_cpu_s (measured from `started` and `cpu_started`: the merge's
// start, wall clock and process CPU seconds).
PreparedImages prepare_images(const std::vector<FaceImage>& images,
                              const ReconstructionPreset& preset, const MultiImageOptions& options,
                              std::chrono::steady_clock::time_point started, double cpu_started,
                              MergeTimes& times);

// coarse[i][j]: how image j's thumbnail overlaps image i's; coarse[j][i]
// is the same with the shift reversed. The diagonal stays default.
using CoarseOverlaps = std::vector<std::vector<CoarseOverlap>>;
CoarseOverlaps coarse_overlaps(const std::vector<Thumbnail>& thumbnails);

// The unplaced images (not failed either) that need not wait for another:
// an image waits for an unplaced one only when that overlaps it better
// than any placed image by more than 1 / wave_share and is itself no
// farther from being placed. When no image qualifies, the one that overlaps
// a placed image most goes alone; empty when no unplaced, unfailed image
// remains. Image 0 (the master) is never in a wave.
std::vector<std::size_t> next_wave(const CoarseOverlaps& coarse, const std::vector<bool>& placed,
                                   const std::vector<char>& failed, double wave_share);

// Tie points of a (placed, slave) pair, matched once each way (guided by
// the coarse shift, or against all keypoints) and lifted to both surfaces;
// several threads may ask at once.
class TieMatcher {
 public:
  TieMatcher(const std::vector<FaceImage>& images, const PreparedImages& prepared,
             const CoarseOverlaps& coarse, const ReconstructionPreset& preset,
             const MultiImageOptions& options);
  // The reference's points in the face frame (through reference_to_face),
  // the slave's in its own.
  TiePoints tie_points(std::size_t ref, std::size_t slave, bool guided,
                       const Similarity& reference_to_face);

 private:
  // The same surface points, each in its own image's frame.
  struct Raw {
    std::vector<Eigen::Vector3d> reference, slave;
  };
  const std::vector<FaceImage>& images_;
  const PreparedImages& prepared_;
  const CoarseOverlaps& coarse_;
  const ReconstructionPreset& preset_;
  const MultiImageOptions& options_;
  std::map<std::tuple<std::size_t, std::size_t, bool>, Raw> matched_;
  std::mutex lock_;
};

// A placed image as the reference of others: its surface sample in the face
// frame and the index of its points, made once, whichever image needs it first.
struct ReferenceSurface {
  SurfaceSample sample;
  std::optional<NearestWithin> near;
  std::once_flag made;
};

// One image registered to the images placed so far.
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

// What place_image reads (`placed` and the placed images' to_face do not
// change while a wave runs).
struct PlacementContext {
  const std::vector<FaceImage>& images;
  const PreparedImages& prepared;
  const CoarseOverlaps& coarse;
  const MultiImageOptions& options;
  const std::vector<bool>& placed;
  const std::vector<ImageResidual>& residuals;  // to_face of the placed images
  TieMatcher& matcher;
  std::vector<ReferenceSurface>& references;
};

// Image i registered to the placed image that overlaps it most (coarse
// overlap first, then tie points); ok is false when no placed image shares
// options.min_tie_points tie points with it.
Placement place_image(std::size_t i, const PlacementContext& context);

// RMS distance of the tie points within max_distance of their reference
// point after moving the slave's through to_face (0 when none is).
double tie_point_rms(const TiePoints& tie, const Similarity& to_face, double max_distance);

// The wave's placements written into out (residuals, times, wave index),
// `placed` and `failed` updated, `tried` kept for the refusal message.
// Returns the number of images placed.
std::size_t record_wave(const std::vector<std::size_t>& wave, const std::vector<Placement>& results,
                        FaceRegistration& out, std::vector<bool>& placed, std::vector<char>& failed,
                        std::vector<std::string>& tried);

// Moves every image onto the control points (out.control_points, datum and
// each to_face). Throws InputError naming a control point whose image is not
// given or whose pixel has no surface, or when fewer than three are given.
void apply_ground_control(const std::vector<FaceImage>& images,
                          const std::vector<FaceControlPoint>& control_points,
                          const PreparedImages& prepared, FaceRegistration& out);

// The residuals of images[1..] multiplied by the ground control's scale
// (they were measured in the face frame before it; 1 without it).
void scale_residuals(FaceRegistration& out);

}  // namespace rockface::photogrammetry::registration_phases

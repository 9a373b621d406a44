#pragma once
// Several 3D images of one face (one visit): registers the second, third, ...
// stereo reconstruction to the first, master-slave as in the field workflow.
// For each slave:
//   1. tie points: SIFT matches (feature_matching) between its left photograph
//      and that of an image already in the face frame (the one its thumbnail
//      overlaps most first: image_overlap.h), lifted to both surfaces
//      through the pixels of the lattice vertices;
//   2. a similarity transform (Eigen::umeyama) estimated robustly (RANSAC over
//      3-point samples, then all inliers), so a slave may be unscaled and
//      unoriented (model units of its own base);
//   3. refined on the overlapping surface by point-to-plane ICP
//      (cv::ppf_match_3d::ICP, OpenCV's surface_matching module);
// then, when ground control points are given (three or more, on any image),
// the whole block is moved onto them (registration.h's Umeyama fit) and each
// point's residual is kept. A slave that shares too few tie points with every
// image already placed is refused, by name: it does not overlap, or shows
// another face.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/common/progress.h"
#include "core/photogrammetry/estimators/registration.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::photogrammetry {

// One 3D image: a reconstructed surface and the photograph its vertices'
// pixels refer to. The first image's frame is the face frame.
struct FaceImage {
  std::string name;    // how errors and reports name it ("pair 2", a capture label)
  cv::Mat photograph;  // the left image of the pair, 8-bit grey or BGR
  SurfaceMesh mesh;    // in the image's own frame (registered or model units)
  double sigma_z = 0;  // predicted depth precision at the face, in the mesh's units
};

// A control point seen in one image.
struct FaceControlPoint {
  std::string id;
  int image = 0;                                    // index into the images
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  // in that image's photograph
  Eigen::Vector3d world = Eigen::Vector3d::Zero();  // surveyed, absolute coordinates
};

struct MultiImageOptions {
  // Fewer 3D tie points (RANSAC inliers) than this with every placed image:
  // the pair does not overlap (SIFT on unrelated rock still gives a few
  // chance matches that agree with some similarity; 20 is well above that).
  int min_tie_points = 20;
  // Tie points with one placed image that end the search for a reference:
  // the placed images are tried in the order of their coarse overlap with the
  // new one (image_overlap.h), and one that overlaps gives hundreds to
  // thousands; chance matches on unrelated rock stay near min_tie_points.
  int enough_tie_points = 200;
  // Guided matching (guided_matching.h) for pairs whose thumbnails' phase
  // correlation peaks at least this high (0.23 at a third of the frame in
  // common, ~0.05 for unrelated rock: image_overlap.h), in a window of this
  // fraction of the photograph's width around the coarse shift: the face's
  // relief (±1 m at 10 m, stations 1 m apart) moves points by ±2 % of the
  // width against the shift, and the shift is found to under 1 %.
  double guide_min_response = 0.15;
  double guide_window = 0.1;
  // Images are registered side by side, on all cores, in waves (a
  // station's neighbours on both sides of the master, then theirs): an
  // image waits for an unplaced one only when that overlaps it better than
  // any placed image by more than 1 / wave_share and is itself no farther
  // from being placed (its best overlap with a placed image is at least
  // as good); every other image with a placed neighbour goes now.
  double wave_share = 0.8;
  // SIFT for the tie points is detected on photographs reduced to at most
  // this width (0: the preset's feature_max_width). The tie points only seed
  // the ICP on the dense surfaces: they need a pixel at the face well within
  // the inlier distance below (~4 cm: 9 mm at 600 px on the bench's face at
  // 10 m, 16 mm for a 24 Mpx camera with a 24 mm lens), not the
  // reconstruction's resolution, and SIFT's time falls with the pixels
  // (face_merge_bench's BM_MergeFeatureWidth: 1200 -> 600 px, the same truth
  // RMS within 0.03 mm, 40 % of SIFT's time, 1,000+ tie points still).
  int feature_max_width = 600;
  // RANSAC samples at most (fewer when the inlier ratio found allows:
  // multi_image_registration_fit.h).
  int ransac_iterations = 400;
  // Tie-point inlier distance, in units of the reference image's predicted
  // depth precision sigma_z plus one point spacing (the vertex picked at a
  // pixel is up to one lattice cell off the true point): two independent
  // depth errors at 3 sigma each.
  double inlier_sigmas = 4.0;
  // Surface points of a slave closer to the reference surface than this
  // many inlier distances count as overlap (used for ICP and the residual).
  double overlap_distance_factor = 1.0;
  int icp_iterations = 40;
  int icp_levels = 4;
  std::size_t icp_max_points = 20000;  // surface points per cloud fed to ICP
  std::uint64_t seed = 1;
};

// How well one image fits the face.
struct ImageResidual {
  std::string name;
  int reference = -1;                   // the image it was registered to; -1 for the master
  int tie_points = 0;                   // RANSAC inliers (3D tie points)
  double tie_rms_m = 0;                 // their RMS distance after the final transform, face units
  double overlap = 0;                   // fraction of its surface lying on the reference surface
  double surface_rms_m = 0;             // RMS point-to-plane distance there, after ICP
  double surface_rms_before_icp_m = 0;  // the same after the tie-point similarity alone
  Similarity to_face;                   // its frame -> face frame (after ground control, if any)
};

// Where the merge's time went, in seconds (the benchmark and
// docs/accuracy-cost.md read it; nothing else depends on it). Wall times
// say how long a stage took on this machine as loaded; CPU times say how
// much work it was, which a shared machine does not change: the wall time
// of two registrations side by side on a core the machine shares also
// holds the time the other one (or another process) had the core.
struct MergeTimes {
  double prepare_s = 0;         // normals, pixel lookups and lattice spacing of every surface
  double features_s = 0;        // SIFT on every photograph (and what overlaps it in time)
  double thumbnails_s = 0;      // thumbnails and their phase correlation
  std::vector<double> waves_s;  // each wave of registrations, side by side
  std::vector<int> wave;        // per image, the wave that placed it (-1: the master)
  double release_s = 0;         // the working data freed
  // Per registered image (zero for the master), summed over the placed
  // images the registration tried: SIFT matching and lifting to 3D,
  // RANSAC, and the surface stage (samples, index, overlap, ICP). Wall
  // time, and the CPU time of the thread that ran it (each registration
  // runs on one thread, its stages on no other).
  std::vector<double> match_s, ransac_s, surface_s;
  std::vector<double> match_cpu_s, ransac_cpu_s, surface_cpu_s;
  // CPU time of the process (every thread, OpenCV's workers in SIFT
  // included) in each phase: preparation and SIFT, thumbnails, each wave,
  // the release; and in the whole merge.
  double features_cpu_s = 0, thumbnails_cpu_s = 0, release_cpu_s = 0;
  std::vector<double> waves_cpu_s;
  double total_s = 0, total_cpu_s = 0;
};

struct FaceRegistration {
  std::vector<ImageResidual> images;  // one per input image, same order
  MergeTimes times;
  // Ground control: the face frame is then datum-relative world, absolute =
  // face + datum; without ground control the datum is zero.
  std::optional<ControlPointRegistration> control_points;
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
};

// Registers images[1..] to images[0]: each new image to the placed image
// that overlaps it most (coarse overlap of thumbnails, then at least
// options.enough_tie_points tie points; else to the placed image it shares
// most tie points with), the image that overlaps a placed one most first. Throws InputError naming
// the image that overlaps no placed image, or a control point whose pixel has no surface.
FaceRegistration register_face_images(const std::vector<FaceImage>& images,
                                      const std::vector<FaceControlPoint>& control_points,
                                      const ReconstructionPreset& preset,
                                      const MultiImageOptions& options, Progress& progress);

// All surfaces in the face frame, one mesh (triangles re-indexed; pixels and
// texture coordinates keep referring to each image's own photograph).
SurfaceMesh merged_surface(const std::vector<FaceImage>& images, const FaceRegistration& face);

}  // namespace rockface::photogrammetry

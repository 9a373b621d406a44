#pragma once
// The two cues of trace proposals as images on the working scale of the
// left photograph (trace_proposals.h): one-pixel-wide lines where the
// photograph shows a dark line and where the surface folds, with the
// strength of each cue at every line pixel. Image work only (OpenCV); the
// lines become polylines in line_chains.h.
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::measure::proposals {

struct DarkLineSettings {
  std::vector<double> widths_px;  // working-image pixels, one Hessian scale each
  double seed_sigmas = 6, keep_sigmas = 3;
  double min_contrast_grey = 6;
};

struct DarkLines {
  cv::Mat lines;     // CV_8U, 255 on the thinned line pixels
  cv::Mat sigmas;    // CV_32F, response in robust sigmas above the median (line pixels)
  cv::Mat contrast;  // CV_32F, grey levels darker than both sides (line pixels)
  double noise = 0;  // robust sigma of the scale-normalised response
};

// `grey`: CV_32F grey levels 0..255 on the working scale; `mask`: CV_8U,
// non-zero where the surface is (lines are kept only there).
DarkLines find_dark_lines(const cv::Mat& grey, const cv::Mat& mask,
                          const DarkLineSettings& settings);

// The mesh drawn into the working image: the smoothed surface normal (unit,
// toward the camera) and the
// surface point at each pixel, and where there is surface at all. Triangles
// across a depth jump (an edge longer than `max_edge_m`: the range pole
// against the face) are left out, so the jump is a hole, not a fold.
struct SurfaceImage {
  cv::Mat normals;  // CV_32FC3, smoothed over `smoothing_px`
  cv::Mat points;   // CV_32FC3, the drawn triangle's centre relative to `origin` (not smoothed)
  cv::Mat mask;     // CV_8U, 255 where a triangle was drawn
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

// `scale`: working image / photograph; normals are turned toward
// `camera_centre` (mesh frame).
SurfaceImage draw_surface(const photogrammetry::SurfaceMesh& mesh, cv::Size size, double scale,
                          const Eigen::Vector3d& camera_centre, double max_edge_m,
                          double smoothing_px);

struct FoldSettings {
  double smoothing_px = 3;  // of the normals (SurfaceImage)
  double seed_deg = 12, keep_deg = 7;
};

struct Folds {
  cv::Mat lines;  // CV_8U, 255 on the thinned fold pixels
  cv::Mat angle;  // CV_32F, degrees the normal turns across the fold (line pixels)
  cv::Mat ridge;  // CV_8U, 255 where the fold is convex (a ridge), 0 concave (a valley)
};

Folds find_folds(const SurfaceImage& surface, const FoldSettings& settings);

// Hysteresis (Canny's linking): the 8-connected groups of `keep` that hold
// at least one pixel of `seed`. Both CV_8U; returns CV_8U 0 / 255.
cv::Mat hysteresis(const cv::Mat& keep, const cv::Mat& seed);

}  // namespace rockface::measure::proposals

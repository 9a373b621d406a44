#pragma once
// The depth precision predicted at each cell of the lining (issue 38).
//
// A photographed round's 3D image is not equally precise everywhere: the
// cameras stand in the tunnel and look along it, so the walls, the roof and
// the invert are seen from 2 to 10 m and at grazing angles, and one figure
// for the whole image (the stereo pair's sigma_Z at the face's median depth)
// is too large for the near lining and too small for the far, grazing one:
// there the reconstruction's noise passed the noise threshold and was counted
// as underbreak. Here each cell gets its own sigma, from the stereo pairs
// that made the image.
//
// The model (docs/accuracy-cost.md, "Issue 38 (sixth session)", with its
// check against the rendered headings' measured residuals), for a point P of
// the lining with unit normal n, seen by a pair whose left camera is at C:
//
//   sigma_n = sqrt( (sigma_d r Z cos i / (f B))^2 + (w Z |n.b| / (sqrt(12) f))^2 )
//
// r = |P - C|, Z the depth along the rectified pair's axis, i the angle
// between the viewing ray and n, f the focal length in pixels at the scale
// the disparities were measured, B the base, b its direction, sigma_d the
// preset's disparity precision (pixels), w the matching window (pixels).
// Derivation: a disparity error dd moves the point along the viewing ray by
// r Z dd / (f B) (the normal case's Z^2 dd / (f B) in depth, times r / Z),
// and the lining's normal takes cos i of that. The disparity error is the
// matching's own sigma_d and, on a surface receding across the window, the
// window's: for the plane n.X = c (c = r cos i from the camera) the
// disparity f B / Z = B (n.x) / c grows along the image row by
// g = B |n.b| / (r cos i) pixels per pixel, and a window of w pixels
// compared as if the surface faced the cameras spreads its disparity over
// g w, sigma g w / sqrt(12) (uniform). Put together, the slant's term is
// w Z |n.b| / (sqrt(12) f): the window's footprint at depth Z, whatever the
// base or the incidence. A wall (normal along the base) is as imprecise as
// its depth in pixels of window; the invert and the roof (normal across the
// base: the disparity does not change along the row) only the first term.
// The face's own figure, sigma_Z = Z^2 sigma_d / (f B) at its depth, is the
// first term at i = 0. A cell seen by several pairs takes the best pair's
// sigma (the mesh there is mostly that pair's).
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/profile_deviation.h"

namespace rockface::tunnel {

// A stereo pair that made (part of) the visit's 3D image, in the
// alignment's local frame (datum-relative, as the mesh).
struct StereoPairView {
  Eigen::Vector3d left_centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d right_centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d optical_axis = Eigen::Vector3d::UnitY();  // the left camera's
  double focal_px = 0;            // at the scale the disparities were measured
  double disparity_sigma_px = 0;  // the preset's stated disparity precision
  double window_px = 0;           // the dense matching's window (block size)
};

struct LiningPrecision {
  std::vector<StereoPairView> pairs;  // empty: the stated depth sigma for every cell
};

// One sigma (m) of a point of the lining normal to it: `point` on the
// lining, `normal` its unit normal, both datum-relative; nullopt when no
// pair has it in front of its cameras.
std::optional<double> predicted_normal_sigma(const LiningPrecision& precision,
                                             const Eigen::Vector3d& point,
                                             const Eigen::Vector3d& normal);

// The developed view's cells (row i at chainage[i], column j at the design
// outline's arc length s[j]): each cell's predicted sigma at its design
// point, `fallback` where no pair sees it. Row-major.
std::vector<double> cell_sigmas(const LiningPrecision& precision, const Alignment& alignment,
                                const DesignProfile& profile, std::span<const double> chainage,
                                std::span<const double> s, double fallback);

// What the profile says of the cells' precision.
struct CellPrecisionFigures {
  std::string model;  // how each cell's sigma was predicted, in words
  double min_sigma_m = 0, median_sigma_m = 0, max_sigma_m = 0;  // over the valued cells
};

// The round measured with each cell's own noise threshold (noise_sigmas x
// its predicted sigma) instead of options.depth_sigma_m for all: the
// same as profile_deviation() otherwise. With no pairs it is
// profile_deviation() itself. `cell_sigma_m` is the developed view's
// per-cell sigma (row-major as the view; NaN where the view has no value).
struct PreciseDeviation {
  ProfileDeviation deviation;
  std::optional<CellPrecisionFigures> precision;  // absent without pairs
  std::vector<float> cell_sigma_m;
};
PreciseDeviation profile_deviation_per_cell(const SurfaceInput& surface, const Alignment& alignment,
                                            const DesignProfile& profile,
                                            const DeviationOptions& options,
                                            const LiningPrecision& precision);

}  // namespace rockface::tunnel

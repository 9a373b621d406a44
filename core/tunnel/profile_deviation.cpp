#include "core/tunnel/profile_deviation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/parallel.h"
#include "core/common/units.h"
#include "core/tunnel/break_crest.h"
#include "core/tunnel/break_flanks.h"
#include "core/tunnel/break_patches.h"
#include "core/tunnel/break_significance.h"
#include "core/tunnel/developed_cells.h"
#include "core/tunnel/deviation_message.h"
#include "core/tunnel/lining_interpolation.h"
#include "core/tunnel/lining_precision.h"
#include "core/tunnel/lining_statistics.h"
#include "core/tunnel/mesh_raycast.h"
#include "core/tunnel/underbreak_patches.h"

namespace rockface::tunnel {

namespace {

// The developed view's states (profile_deviation.h); while the cells are
// measured, "left out" is told apart as off the lining or below the invert.
constexpr std::uint8_t kSeen = 0, kNotSeen = 1, kExcluded = 2, kLeftOut = 3;
constexpr std::uint8_t kOffLining = 4, kBelowInvert = 5;
// Filled from measured neighbours (lining_interpolation.h); state 4 of the
// developed view.
constexpr std::uint8_t kInterpolated = 6, kViewInterpolated = 4;

enum class Region : std::uint8_t { roof, wall, floor };

// One ray of the cross-section, the same in every section.
struct Ray {
  double s = 0;              // arc length of the design point it aims at
  double angle = 0;          // radians, counter-clockwise from right
  double design = 0;         // distance from the ray centre to the design outline
  double cos_incidence = 1;  // between the ray and the outline's outward normal
  double dtheta = 0;         // the angle this ray stands for (sums to 2 pi)
  Region region = Region::wall;
};

void require_positive(double v, const char* name) {
  if (!std::isfinite(v) || !(v > 0))
    throw InputError(std::string("options.") + name,
                     "must be a positive number, got " + format_fixed(v, 6));
}

std::vector<Ray> rays_of(const DesignProfile& profile, double ray_spacing) {
  const double P = profile.perimeter();
  const std::size_t m =
      std::max<std::size_t>(16, static_cast<std::size_t>(std::ceil(P / ray_spacing)));
  const Eigen::Vector2d c = profile.ray_centre();
  std::vector<double> boundary(m + 1);
  for (std::size_t k = 0; k <= m; ++k) boundary[k] = profile.angle_at_length(P * k / m);
  std::vector<Ray> rays(m);
  for (std::size_t j = 0; j < m; ++j) {
    Ray& r = rays[j];
    r.s = P * (j + 0.5) / m;
    const Eigen::Vector2d q = profile.point_at_length(r.s);
    const Eigen::Vector2d d = q - c;
    r.design = d.norm();
    r.angle = std::atan2(d.y(), d.x());
    const Eigen::Vector2d n = profile.outward_normal_at_length(r.s);
    r.cos_incidence = std::max(0.0, n.dot(d / r.design));
    // The outline turns counter-clockwise about the centre (validated star
    // shape), so each step of angle is in (0, 2 pi).
    double dt = boundary[j + 1] - boundary[j];
    while (dt < 0) dt += 2 * kPi;
    while (dt >= 2 * kPi) dt -= 2 * kPi;
    r.dtheta = dt;
    if (n.y() < -std::sqrt(0.5))
      r.region = Region::floor;  // facing down within 45 degrees: the invert
    else if (q.y() >= c.y())
      r.region = Region::roof;
    else
      r.region = Region::wall;
  }
  return rays;
}

// n rays inside each column, evenly along the outline (the cell's rays, with
// the section's n positions along the chainage): the same in every section.
std::vector<Ray> sub_rays_of(const DesignProfile& profile, const std::vector<Ray>& rays,
                             std::size_t n, double cell_s) {
  const double P = profile.perimeter();
  const Eigen::Vector2d c = profile.ray_centre();
  std::vector<Ray> out;
  out.reserve(rays.size() * n);
  for (const Ray& column : rays)
    for (std::size_t b = 0; b < n; ++b) {
      Ray r = column;
      r.s = column.s + ((static_cast<double>(b) + 0.5) / static_cast<double>(n) - 0.5) * cell_s;
      r.s = std::fmod(r.s + P, P);
      const Eigen::Vector2d d = profile.point_at_length(r.s) - c;
      r.design = d.norm();
      r.angle = std::atan2(d.y(), d.x());
      r.cos_incidence = std::max(0.0, profile.outward_normal_at_length(r.s).dot(d / r.design));
      out.push_back(r);
    }
  return out;
}

}  // namespace

const char* deviation_status_name(DeviationStatus status) {
  switch (status) {
    case DeviationStatus::ok:
      return "ok";
    case DeviationStatus::partly_seen:
      return "partly_seen";
    case DeviationStatus::no_walls_in_view:
      return "no_walls_in_view";
    case DeviationStatus::outside_alignment:
      return "outside_alignment";
  }
  return "ok";
}

ProfileDeviation profile_deviation(const SurfaceInput& surface, const Alignment& alignment,
                                   const DesignProfile& profile, const DeviationOptions& options) {
  const MeshRaycaster caster(surface.vertices, surface.triangles);
  return profile_deviation(caster, surface, alignment, profile, options);
}

namespace {

void check_deviation_input(const SurfaceInput& surface, const DesignProfile& profile,
                           const DeviationOptions& options) {
  require_positive(options.section_spacing_m, "section_spacing_m");
  require_positive(options.ray_spacing_m, "ray_spacing_m");
  require_positive(options.max_overbreak_m, "max_overbreak_m");
  require_positive(options.plausible_slope, "plausible_slope");
  require_positive(options.max_invert_overbreak_m, "max_invert_overbreak_m");
  if (!std::isfinite(options.max_interpolated_hole_m) || options.max_interpolated_hole_m < 0)
    throw InputError("options.max_interpolated_hole_m", "must be a number >= 0 (0: never)");
  for (const auto& [v, name] : {std::pair{options.min_break_chainage_m, "min_break_chainage_m"},
                                std::pair{options.min_break_outline_m, "min_break_outline_m"}})
    if (!std::isfinite(v) || v < 0)
      throw InputError(
          std::string("options.") + name,
          "must be a number >= 0 (0: every counted cell counts), got " + format_fixed(v, 6));
  if (options.rays_per_cell_side < 1 || options.rays_per_cell_side > 15)
    throw InputError("options.rays_per_cell_side",
                     "must be 1 to 15, got " + std::to_string(options.rays_per_cell_side));
  if (!std::isfinite(options.depth_sigma_m) || options.depth_sigma_m < 0)
    throw InputError("options.depth_sigma_m", "must be a number >= 0 (0: not stated)");
  if (!std::isfinite(options.noise_sigmas) || options.noise_sigmas < 0)
    throw InputError("options.noise_sigmas", "must be a number >= 0");
  if (!std::isfinite(options.underbreak_tolerance_m) || options.underbreak_tolerance_m < 0)
    throw InputError("options.underbreak_tolerance_m", "must be a number >= 0");
  if (!std::isfinite(options.chainage_from) || !std::isfinite(options.chainage_to))
    throw InputError("options.chainage_from", "the chainage range must be finite");
  if (!surface.not_rock_vertex.empty() && surface.not_rock_vertex.size() != surface.vertices.size())
    throw InputError("surface.not_rock_vertex",
                     "one flag per vertex (" + std::to_string(surface.vertices.size()) + "), got " +
                         std::to_string(surface.not_rock_vertex.size()));
  if (!surface.not_rock_triangle.empty() &&
      surface.not_rock_triangle.size() != surface.triangles.size())
    throw InputError("surface.not_rock_triangle",
                     "one flag per triangle (" + std::to_string(surface.triangles.size()) +
                         "), got " + std::to_string(surface.not_rock_triangle.size()));
  profile.require_valid("profile");
}

// The chainage range cut to the alignment (`clipped` says so); false, with
// out's status and message, when it lies wholly outside it.
bool clip_to_alignment(const Alignment& alignment, double& lo, double& hi, std::string& clipped,
                       ProfileDeviation& out) {
  if (hi < alignment.first_chainage() || lo > alignment.last_chainage()) {
    out.status = DeviationStatus::outside_alignment;
    out.message = "chainage " + format_fixed(lo, 3) + " to " + format_fixed(hi, 3) +
                  " lies outside the alignment (" + format_fixed(alignment.first_chainage(), 3) +
                  " to " + format_fixed(alignment.last_chainage(), 3) + ")";
    return false;
  }
  if (lo < alignment.first_chainage() || hi > alignment.last_chainage()) {
    clipped = "; the range was cut to the alignment's " +
              format_fixed(alignment.first_chainage(), 3) + " to " +
              format_fixed(alignment.last_chainage(), 3);
    lo = std::max(lo, alignment.first_chainage());
    hi = std::min(hi, alignment.last_chainage());
  }
  return true;
}

// Per triangle: 1 where it, or one of its corners, is not rock.
std::vector<std::uint8_t> not_rock_triangles(const SurfaceInput& surface) {
  std::vector<std::uint8_t> masked(surface.triangles.size(), 0);
  for (std::size_t i = 0; i < surface.triangles.size(); ++i) {
    bool m = !surface.not_rock_triangle.empty() && surface.not_rock_triangle[i] != 0;
    if (!surface.not_rock_vertex.empty())
      for (int k : surface.triangles[i])
        m = m || surface.not_rock_vertex[static_cast<std::size_t>(k)] != 0;
    masked[i] = m ? 1 : 0;
  }
  return masked;
}

// The developed view's cells: a row per cross-section over the chainage
// range, a column per ray of the outline, each cell cast with n x n rays.
struct DeviationCells {
  std::vector<Ray> rays, sub_rays;
  std::size_t cols = 0, all_rows = 0, rows = 0, n = 1;
  double lo = 0, dc = 0, cell_c = 0, cell_s = 0;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  // The design's lowest point: a wall or roof ray whose surface lies below
  // it (by more than the noise) went through a hole in the invert's mesh.
  double invert_v = std::numeric_limits<double>::infinity();
  // Per cell: its state, the median normal and ray deviations of its rays;
  // per row, its chainage.
  std::vector<std::uint8_t> state;
  std::vector<double> normal_dev, ray_dev, chainage;
  std::vector<double> interpolation_sigma;  // per cell, of the interpolated ones
  // Per cell: the depth sigma predicted for it (lining_precision.h; the
  // stated one for every cell when no pair was given) and its noise
  // threshold (noise_sigmas of it).
  std::vector<double> sigma, threshold;
};

DeviationCells cells_over(const DesignProfile& profile, const DeviationOptions& options, double lo,
                          double hi) {
  DeviationCells g;
  g.rays = rays_of(profile, options.ray_spacing_m);
  g.cols = g.rays.size();
  g.all_rows =
      hi > lo
          ? static_cast<std::size_t>(std::ceil((hi - lo) / options.section_spacing_m - 1e-9)) + 1
          : 1;
  g.lo = lo;
  g.dc = g.all_rows > 1 ? (hi - lo) / static_cast<double>(g.all_rows - 1) : 0;
  g.cell_c = g.all_rows > 1 ? g.dc : options.section_spacing_m;
  g.cell_s = profile.perimeter() / static_cast<double>(g.cols);
  g.centre = profile.ray_centre();
  g.n = static_cast<std::size_t>(options.rays_per_cell_side);
  // The cell's rays along the outline: n evenly inside each column.
  g.sub_rays = sub_rays_of(profile, g.rays, g.n, g.cell_s);
  for (const Ray& r : g.sub_rays)
    g.invert_v = std::min(g.invert_v, g.centre.y() + r.design * std::sin(r.angle));
  g.state.assign(g.all_rows * g.cols, kNotSeen);
  g.normal_dev.assign(g.all_rows * g.cols, 0.0);
  g.ray_dev.assign(g.all_rows * g.cols, 0.0);
  g.chainage.resize(g.all_rows);
  return g;
}

// Every cell's rays cast on the surface: the cell is rock where its rays
// met more rock than not rock (the median of those that did); at the frayed
// edge of a reconstruction a few rays are all there is.
void cast_cell_rays(DeviationCells& g, const MeshRaycaster& caster, const Alignment& alignment,
                    const std::vector<std::uint8_t>& masked, const DeviationOptions& options) {
  const std::size_t n = g.n, cols = g.cols, all_rows = g.all_rows;
  const Eigen::Vector2d centre = g.centre;
  parallel_for(all_rows, [&](std::size_t i) {
    const double c = all_rows > 1 ? g.lo + g.dc * static_cast<double>(i) : g.lo;
    g.chainage[i] = c;
    std::vector<TunnelFrame> frames;
    for (std::size_t a = 0; a < n; ++a)
      frames.push_back(alignment.frame_at(
          std::clamp(c + ((static_cast<double>(a) + 0.5) / static_cast<double>(n) - 0.5) * g.cell_c,
                     alignment.first_chainage(), alignment.last_chainage())));
    std::vector<double> nd, rd;
    for (std::size_t j = 0; j < cols; ++j) {
      nd.clear();
      rd.clear();
      std::size_t excluded = 0;
      for (const TunnelFrame& f : frames) {
        const Eigen::Vector3d origin = f.to_local(centre.x(), centre.y());
        for (std::size_t b = 0; b < n; ++b) {
          const Ray& r = g.sub_rays[j * n + b];
          const Eigen::Vector3d dir = std::cos(r.angle) * f.right + std::sin(r.angle) * f.up;
          const auto hit = caster.first_hit(origin, dir, 0.0, r.design + options.max_overbreak_m);
          if (!hit) continue;
          if (masked[hit->triangle]) {
            ++excluded;
            continue;
          }
          rd.push_back(hit->t - r.design);
          nd.push_back((hit->t - r.design) * r.cos_incidence);
        }
      }
      const std::size_t k = i * cols + j;
      if (!nd.empty() && nd.size() >= excluded) {
        g.state[k] = kSeen;
        g.normal_dev[k] = median_of(nd);
        g.ray_dev[k] = median_of(rd);
        const Ray& r = g.rays[j];
        const bool below = r.region == Region::floor
                               ? g.normal_dev[k] > options.max_invert_overbreak_m
                               : centre.y() + (r.design + g.ray_dev[k]) * std::sin(r.angle) <
                                     g.invert_v - g.threshold[k];
        if (below) g.state[k] = kBelowInvert;
      } else if (excluded > 0) {
        g.state[k] = kExcluded;
      }
    }
  });
}

// The round is measured where the surface is: sections at its ends that met
// nothing are left out, and said.
void trim_unmet_ends(DeviationCells& g, ProfileDeviation& out) {
  const std::size_t cols = g.cols, all_rows = g.all_rows;
  std::size_t first = 0, last = all_rows;
  auto row_met_something = [&](std::size_t i) {
    for (std::size_t j = 0; j < cols; ++j)
      if (g.state[i * cols + j] != kNotSeen) return true;
    return false;
  };
  while (first < all_rows && !row_met_something(first)) ++first;
  while (last > first && !row_met_something(last - 1)) --last;
  if (first == last) {
    first = 0;  // nothing anywhere: every section stays, all unseen
    last = all_rows;
  } else {
    const char* why = "the surface does not reach there (the photographs do not both see it)";
    if (first > 0)
      out.sections_left_out.push_back({g.chainage[0], g.chainage[first - 1], first, why});
    if (last < all_rows)
      out.sections_left_out.push_back(
          {g.chainage[last], g.chainage[all_rows - 1], all_rows - last, why});
  }
  g.rows = last - first;
  auto keep_rows = [&](auto& v, std::size_t per_row) {
    v.erase(v.begin() + static_cast<std::ptrdiff_t>(last * per_row), v.end());
    v.erase(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(first * per_row));
  };
  keep_rows(g.state, cols);
  keep_rows(g.normal_dev, cols);
  keep_rows(g.ray_dev, cols);
  keep_rows(g.sigma, cols);
  keep_rows(g.threshold, cols);
  keep_rows(g.chainage, 1);
}

// Cells off any plausible lining (lining_statistics.h). A piece smaller
// than the smallest break the round counts (the patch rule's rectangle)
// that jumps off the seen lining all round is stray, not a break.
void mark_off_lining(DeviationCells& g, const DeviationOptions& options, double noise_threshold) {
  const std::size_t cells = g.rows * g.cols;
  std::vector<std::uint8_t> seen(cells);
  for (std::size_t k = 0; k < cells; ++k) seen[k] = g.state[k] == kSeen ? 1 : 0;
  const std::vector<std::uint8_t> off = cells_off_the_lining(
      g.rows, g.cols, g.normal_dev, seen, {g.cell_c, g.cell_s}, options.plausible_slope,
      2 * noise_threshold, options.min_break_chainage_m * options.min_break_outline_m);
  for (std::size_t k = 0; k < cells; ++k)
    if (off[k]) g.state[k] = kOffLining;
}

// Unseen cells inside the measured lining filled from their measured
// neighbours (lining_interpolation.h); returns how many.
std::size_t interpolate_holes(DeviationCells& g, const DeviationOptions& options) {
  const std::size_t cells = g.rows * g.cols;
  std::vector<std::uint8_t> measured(cells), fillable(cells);
  for (std::size_t k = 0; k < cells; ++k) {
    measured[k] = g.state[k] == kSeen ? 1 : 0;
    fillable[k] = g.state[k] == kNotSeen ? 1 : 0;
  }
  g.interpolation_sigma.assign(cells, 0.0);
  const std::vector<FilledCell> filled =
      fill_lining_holes(g.rows, g.cols, g.normal_dev, g.ray_dev, measured, fillable,
                        {g.cell_c, g.cell_s}, options.max_interpolated_hole_m);
  for (const FilledCell& f : filled) {
    g.state[f.cell] = kInterpolated;
    g.normal_dev[f.cell] = f.normal_m;
    g.ray_dev[f.cell] = f.ray_m;
    g.interpolation_sigma[f.cell] = f.sigma_m;
  }
  return filled.size();
}

// The lining around a break patch whose spread tells the noise
// (break_significance.h): 1 m on each side, wider than the matching
// window's footprint on the lining (a few centimetres to 0.3 m), so the
// noise's correlated blobs are measured, and narrow enough to stay in the
// same region of the outline and the same distance from the cameras.
constexpr double kLiningAroundM = 1.0;
std::size_t lining_around(double cell_m) {
  return cell_m > 0 ? static_cast<std::size_t>(std::ceil(kLiningAroundM / cell_m - 1e-9)) : 0;
}

// Which cells count as over- or underbreak: those beyond the noise
// threshold, and the flanks of such a break down to half the threshold
// (connected cells of the same sign, 4-neighbours, the outline wrapping),
// which shape the patches; noise that never reaches the threshold counts
// for nothing. Interpolated cells count as measured ones do (they lie
// between measured cells). Then only patches at least min_break_chainage_m
// by min_break_outline_m count (break_patches.h), and of those only the
// ones deeper than the lining around them is rough (break_significance.h;
// the others are told in `out`); last, each break's flanks are followed
// down to the design (break_flanks.h).
std::vector<std::uint8_t> counted_cells(const DeviationCells& g, const DeviationOptions& options,
                                        double offset, ProfileDeviation& out) {
  const std::size_t rows = g.rows, cols = g.cols;
  std::vector<std::uint8_t> counted(rows * cols, 0);
  auto dev = [&](std::size_t k) { return g.normal_dev[k] - offset; };
  auto valued = [&](std::size_t k) { return g.state[k] == kSeen || g.state[k] == kInterpolated; };
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < rows * cols; ++start) {
    if (counted[start] || !valued(start) || !(std::abs(dev(start)) > g.threshold[start])) continue;
    const bool over = dev(start) > 0;
    counted[start] = 1;
    stack.assign(1, start);
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      for (std::size_t q : developed_neighbours(k, rows, cols)) {
        if (counted[q] || !valued(q)) continue;
        const double d = dev(q);
        if ((d > 0) == over && std::abs(d) > 0.5 * g.threshold[q]) {
          counted[q] = 1;
          stack.push_back(q);
        }
      }
    }
  }
  // The robust patch rule (break_patches.h): only patches of a break at
  // least the options' rectangle wide count.
  std::vector<std::int8_t> sign(rows * cols, 0);
  std::vector<std::uint8_t> has_value(rows * cols, 0);
  for (std::size_t k = 0; k < rows * cols; ++k) {
    has_value[k] = valued(k) ? 1 : 0;
    if (counted[k]) sign[k] = dev(k) > 0 ? 1 : -1;
  }
  const std::vector<std::int8_t> opened =
      open_break_patches(rows, cols, sign, has_value,
                         patch_size_for(options.min_break_chainage_m, options.min_break_outline_m,
                                        g.cell_c, g.cell_s));
  // A patch as deep as the lining around it is rough is noise
  // (break_significance.h); a break's flanks are followed down to the
  // design (break_flanks.h).
  std::vector<double> deviation(rows * cols);
  for (std::size_t k = 0; k < rows * cols; ++k) deviation[k] = dev(k);
  BreakSignificanceOptions significance;
  significance.noise_sigmas = options.noise_sigmas;
  significance.ring_rows = lining_around(g.cell_c);
  significance.ring_cols = lining_around(g.cell_s);
  // Without a stated precision every deviation counts (and is said so).
  std::vector<PatchSignificance> decided;
  const std::vector<std::int8_t> breaks =
      out.noise_threshold_m > 0 ? significant_breaks(rows, cols, opened, deviation, has_value,
                                                     g.sigma, significance, &decided)
                                : opened;
  for (const PatchSignificance& p : decided) {
    if (p.counts) continue;
    ++out.noise_patches;
    const double m3 = p.mean_depth_m * static_cast<double>(p.cells) * g.cell_c * g.cell_s;
    (p.sign > 0 ? out.noise_patches_overbreak_m3 : out.noise_patches_underbreak_m3) += m3;
  }
  const std::vector<std::int8_t> kept =
      follow_break_flanks(rows, cols, breaks, deviation, has_value);
  for (std::size_t k = 0; k < rows * cols; ++k) counted[k] = kept[k] != 0 ? 1 : 0;
  return counted;
}

// The developed area (m^2) of the cells counted as over- and underbreak.
struct CountedArea {
  double over = 0, under = 0;
  // The same weighted by each cell's predicted depth sigma (m^3).
  double sigma_over = 0, sigma_under = 0;
  // Of the interpolated cells: per section their over- and underbreak area
  // (m^2 of cross-section), and their sigma times their developed area.
  std::vector<double> interpolated_over_m2, interpolated_under_m2;
  double interpolation_sigma_over = 0, interpolation_sigma_under = 0;
};

// Each cross-section from its cells: the developed view's states and
// deviations (the lining's offset taken out), each seen cell's place, the
// over- and underbreak areas and the largest of each, the fractions seen.
CountedArea measure_sections(DeviationCells& g, const Alignment& alignment, double offset,
                             const std::vector<std::uint8_t>& counted, ProfileDeviation& out,
                             std::vector<ProfilePosition>& position) {
  const std::size_t rows = g.rows, cols = g.cols;
  DevelopedView& view = out.view;
  // Rays of each region, to turn what was seen into fractions.
  std::size_t region_rays[3] = {0, 0, 0};
  for (const Ray& r : g.rays) ++region_rays[static_cast<int>(r.region)];
  // Before the loop below takes the offset out of the cells in place.
  std::vector<double> deviation(rows * cols);
  std::vector<std::uint8_t> valued(rows * cols), candidate(rows * cols);
  for (std::size_t k = 0; k < rows * cols; ++k) {
    deviation[k] = g.normal_dev[k] - offset;
    valued[k] = g.state[k] == kSeen || g.state[k] == kInterpolated ? 1 : 0;
    candidate[k] = counted[k] && g.state[k] == kSeen ? 1 : 0;
  }
  const std::vector<std::optional<double>> crest =
      break_crest_depths(rows, cols, deviation, valued, candidate);
  CountedArea area;
  area.interpolated_over_m2.assign(rows, 0.0);
  area.interpolated_under_m2.assign(rows, 0.0);
  for (std::size_t i = 0; i < rows; ++i) {
    const double c = g.chainage[i];
    const TunnelFrame f = alignment.frame_at(c);
    const Eigen::Vector3d origin = f.to_local(g.centre.x(), g.centre.y());
    SectionDeviation& sec = out.sections[i];
    sec.chainage = c;
    std::size_t seen_rays = 0, excluded_rays = 0, region_seen[3] = {0, 0, 0};
    for (std::size_t j = 0; j < cols; ++j) {
      const Ray& r = g.rays[j];
      const std::size_t k = i * cols + j;
      const std::uint8_t state = g.state[k];
      view.state[k] = state == kSeen           ? kSeen
                      : state == kExcluded     ? kExcluded
                      : state == kNotSeen      ? kNotSeen
                      : state == kInterpolated ? kViewInterpolated
                                               : kLeftOut;
      if (state == kExcluded) ++excluded_rays;
      if (state != kSeen && state != kInterpolated) continue;
      const bool interpolated = state == kInterpolated;
      const double nd = g.normal_dev[k] - offset;
      const double rd = g.ray_dev[k] - (r.cos_incidence > 0.2 ? offset / r.cos_incidence : offset);
      const double t = r.design + rd;
      view.deviation_m[k] = static_cast<float>(nd);
      g.normal_dev[k] = nd;
      const Eigen::Vector3d dir = std::cos(r.angle) * f.right + std::sin(r.angle) * f.up;
      ProfilePosition& pos = position[k];
      pos.chainage = c;
      pos.s = r.s;
      pos.angle = r.angle;
      pos.local = origin + t * dir;
      pos.survey = alignment.to_survey(pos.local);
      if (!interpolated) {
        ++seen_rays;
        ++region_seen[static_cast<int>(r.region)];
      }
      // The reconstruction's noise, not counted.
      if (!counted[k]) continue;
      // Polar area between the design line and the surface, exact for the
      // sampled radii (A = 1/2 r^2 dtheta).
      const double a = 0.5 * (t * t - r.design * r.design) * r.dtheta;
      if (a > 0) {
        sec.overbreak_area_m2 += a;
        area.over += g.cell_s * g.cell_c;
        area.sigma_over += g.sigma[k] * g.cell_s * g.cell_c;
      } else {
        sec.underbreak_area_m2 -= a;
        area.under += g.cell_s * g.cell_c;
        area.sigma_under += g.sigma[k] * g.cell_s * g.cell_c;
      }
      if (interpolated) {
        // Its part of the volumes and its own uncertainty; the largest
        // breaks are measured ones (an interpolation lies between them).
        const double sigma_area = g.interpolation_sigma[k] * g.cell_s * g.cell_c;
        if (a > 0) {
          area.interpolated_over_m2[i] += a;
          area.interpolation_sigma_over += sigma_area;
        } else {
          area.interpolated_under_m2[i] -= a;
          area.interpolation_sigma_under += sigma_area;
        }
        continue;
      }
      // The largest breaks from the crest's robust depth (break_crest.h), of
      // the cell's own sign.
      if (!crest[k]) continue;
      const double depth = a > 0 ? std::max(0.0, *crest[k]) : std::min(0.0, *crest[k]);
      sec.max_overbreak_m = std::max(sec.max_overbreak_m, depth);
      sec.max_underbreak_m = std::max(sec.max_underbreak_m, -depth);
      if (depth > out.max_overbreak_m) {
        out.max_overbreak_m = depth;
        out.max_overbreak = pos;
      }
      if (-depth > out.max_underbreak_m) {
        out.max_underbreak_m = -depth;
        out.max_underbreak = pos;
        out.has_underbreak = true;
      }
    }
    // Every ray stands for the same length of outline: fractions are counts.
    auto part = [](std::size_t count, std::size_t of) {
      return of > 0 ? static_cast<double>(count) / static_cast<double>(of) : 0.0;
    };
    sec.seen_fraction = part(seen_rays, cols);
    sec.excluded_fraction = part(excluded_rays, cols);
    sec.roof_seen = part(region_seen[0], region_rays[0]);
    sec.walls_seen = part(region_seen[1], region_rays[1]);
    sec.floor_seen = part(region_seen[2], region_rays[2]);
  }
  return area;
}

}  // namespace

namespace {

// The median of the cells' values where `use` holds; 0 when none does.
double median_where(const std::vector<double>& values, const std::vector<std::uint8_t>& state,
                    bool (*use)(std::uint8_t)) {
  std::vector<double> kept;
  for (std::size_t k = 0; k < values.size(); ++k)
    if (use(state[k])) kept.push_back(values[k]);
  return kept.empty() ? 0.0 : median_of(kept);
}

// The round measured; with `precision`, each cell's noise threshold from its
// own predicted sigma (lining_precision.h), and `extra` gets the figures.
ProfileDeviation measure_round(const MeshRaycaster& caster, const SurfaceInput& surface,
                               const Alignment& alignment, const DesignProfile& profile,
                               const DeviationOptions& options, const LiningPrecision* precision,
                               PreciseDeviation* extra) {
  check_deviation_input(surface, profile, options);
  ProfileDeviation out;
  out.underbreak_tolerance_m = options.underbreak_tolerance_m;
  out.max_invert_overbreak_m = options.max_invert_overbreak_m;
  double lo = std::min(options.chainage_from, options.chainage_to);
  double hi = std::max(options.chainage_from, options.chainage_to);
  std::string clipped;
  if (!clip_to_alignment(alignment, lo, hi, clipped, out)) return out;

  out.triangles = caster.triangle_count();
  const std::vector<std::uint8_t> masked = not_rock_triangles(surface);
  DeviationCells g = cells_over(profile, options, lo, hi);
  const bool per_cell = precision && !precision->pairs.empty();
  if (per_cell) {
    for (std::size_t i = 0; i < g.all_rows; ++i)
      g.chainage[i] = g.all_rows > 1 ? g.lo + g.dc * static_cast<double>(i) : g.lo;
    std::vector<double> s(g.cols);
    for (std::size_t j = 0; j < g.cols; ++j) s[j] = g.rays[j].s;
    g.sigma = cell_sigmas(*precision, alignment, profile, g.chainage, s, options.depth_sigma_m);
  } else {
    g.sigma.assign(g.all_rows * g.cols, options.depth_sigma_m);
  }
  g.threshold.resize(g.sigma.size());
  for (std::size_t k = 0; k < g.sigma.size(); ++k)
    g.threshold[k] = options.noise_sigmas * g.sigma[k];
  cast_cell_rays(g, caster, alignment, masked, options);
  trim_unmet_ends(g, out);
  const std::size_t rows = g.rows, cols = g.cols;
  // One figure for what is said and for the checks that take one: the
  // median measured cell's threshold (the stated one when every cell has it).
  auto is_seen = [](std::uint8_t state) { return state == kSeen; };
  out.noise_threshold_m = per_cell ? median_where(g.threshold, g.state, is_seen)
                                   : options.depth_sigma_m * options.noise_sigmas;
  mark_off_lining(g, options, out.noise_threshold_m);
  // The lining's offset from the design as a whole: the median of the
  // cells within the noise threshold of the median of all. A round's breaks
  // lie beyond it and would pull the median of all toward the more common
  // sign (issue 38: by 0.4 mm on the sample heading, 440 cells of
  // overbreak and 200 of underbreak among 4300, and by 0.9 mm on the D
  // heading; taken out of every cell, 0.9 mm is 3 % of that underbreak).
  {
    std::vector<double> all, intact;
    for (std::size_t k = 0; k < rows * cols; ++k)
      if (g.state[k] == kSeen) all.push_back(g.normal_dev[k]);
    const LiningOffset first = lining_offset(all);
    for (std::size_t k = 0; k < rows * cols; ++k)
      if (g.state[k] == kSeen && std::abs(g.normal_dev[k] - first.median_m) <= g.threshold[k])
        intact.push_back(g.normal_dev[k]);
    out.lining_offset = intact.empty() ? first : lining_offset(intact);
  }
  out.lining_offset_removed = out.noise_threshold_m > 0 && out.lining_offset.cells > 0 &&
                              std::abs(out.lining_offset.median_m) <= out.noise_threshold_m;
  const double offset = out.lining_offset_removed ? out.lining_offset.median_m : 0.0;

  DevelopedView& view = out.view;
  view.chainage = g.chainage;
  view.s.resize(cols);
  for (std::size_t j = 0; j < cols; ++j) view.s[j] = g.rays[j].s;
  view.deviation_m.assign(rows * cols, std::numeric_limits<float>::quiet_NaN());
  view.state.assign(rows * cols, kNotSeen);
  std::vector<ProfilePosition> position(rows * cols);
  out.sections.resize(rows);
  const std::size_t interpolated = interpolate_holes(g, options);
  out.max_interpolated_hole_m = options.max_interpolated_hole_m;
  const std::vector<std::uint8_t> counted = counted_cells(g, options, offset, out);
  const CountedArea counted_area = measure_sections(g, alignment, offset, counted, out, position);
  out.rays_cast = g.all_rows * cols * g.n * g.n;

  // Volumes (trapezoidal along the chainage), the fractions.
  std::size_t seen = 0, excluded = 0;
  for (std::size_t k = 0; k < rows * cols; ++k) {
    if (g.state[k] == kSeen) ++seen;
    if (g.state[k] == kExcluded) ++excluded;
    if (g.state[k] == kOffLining) ++out.cells_off_lining;
    if (g.state[k] == kBelowInvert) ++out.cells_below_invert;
  }
  for (std::size_t i = 0; i + 1 < rows; ++i) {
    out.overbreak_volume_m3 +=
        0.5 * (out.sections[i].overbreak_area_m2 + out.sections[i + 1].overbreak_area_m2) * g.dc;
    out.underbreak_volume_m3 +=
        0.5 * (out.sections[i].underbreak_area_m2 + out.sections[i + 1].underbreak_area_m2) * g.dc;
    out.interpolated_overbreak_m3 +=
        0.5 * (counted_area.interpolated_over_m2[i] + counted_area.interpolated_over_m2[i + 1]) *
        g.dc;
    out.interpolated_underbreak_m3 +=
        0.5 * (counted_area.interpolated_under_m2[i] + counted_area.interpolated_under_m2[i + 1]) *
        g.dc;
  }
  if (options.depth_sigma_m > 0 || per_cell) {
    // Each counted cell's sigma and the offset's standard error over its
    // area, taken as fully correlated, and the interpolated cells' own.
    const double se = out.lining_offset.standard_error_m;
    out.overbreak_volume_sigma_m3 =
        counted_area.sigma_over + se * counted_area.over + counted_area.interpolation_sigma_over;
    out.underbreak_volume_sigma_m3 =
        counted_area.sigma_under + se * counted_area.under + counted_area.interpolation_sigma_under;
    out.cell_sigma_m = per_cell ? median_where(g.sigma, g.state, is_seen) : options.depth_sigma_m;
  }
  std::optional<CellPrecisionFigures> figures;
  if (per_cell) {
    figures = CellPrecisionFigures{};
    figures->model =
        "each cell's own, from its distance and incidence to the pair that sees it best: "
        "sqrt((sigma_d r Z cos i / (f B))^2 + (w Z |n.b| / (sqrt(12) f))^2)";
    std::vector<double> valued;
    for (std::size_t k = 0; k < rows * cols; ++k)
      if (g.state[k] == kSeen || g.state[k] == kInterpolated) valued.push_back(g.sigma[k]);
    if (!valued.empty()) {
      figures->min_sigma_m = *std::min_element(valued.begin(), valued.end());
      figures->max_sigma_m = *std::max_element(valued.begin(), valued.end());
      figures->median_sigma_m = median_of(valued);
    }
  }
  out.seen_fraction = static_cast<double>(seen) / static_cast<double>(rows * cols);
  out.excluded_fraction = static_cast<double>(excluded) / static_cast<double>(rows * cols);
  out.interpolated_fraction = static_cast<double>(interpolated) / static_cast<double>(rows * cols);
  out.beyond_tolerance =
      underbreak_patches(out, options.underbreak_tolerance_m, g.cell_s, g.cell_c, position);
  tell_the_geologist(out, options, seen, excluded, clipped, figures ? &*figures : nullptr);
  if (extra) {
    extra->precision = figures;
    extra->cell_sigma_m.assign(rows * cols, std::numeric_limits<float>::quiet_NaN());
    for (std::size_t k = 0; k < rows * cols; ++k)
      if (g.state[k] == kSeen || g.state[k] == kInterpolated)
        extra->cell_sigma_m[k] = static_cast<float>(g.sigma[k]);
  }
  return out;
}

}  // namespace

ProfileDeviation profile_deviation(const MeshRaycaster& caster, const SurfaceInput& surface,
                                   const Alignment& alignment, const DesignProfile& profile,
                                   const DeviationOptions& options) {
  return measure_round(caster, surface, alignment, profile, options, nullptr, nullptr);
}

// Declared in lining_precision.h (the per-cell thresholds' entry point): it
// is this file's computation with each cell's own sigma.
PreciseDeviation profile_deviation_per_cell(const SurfaceInput& surface, const Alignment& alignment,
                                            const DesignProfile& profile,
                                            const DeviationOptions& options,
                                            const LiningPrecision& precision) {
  const MeshRaycaster caster(surface.vertices, surface.triangles);
  PreciseDeviation out;
  out.deviation = measure_round(caster, surface, alignment, profile, options, &precision, &out);
  return out;
}

DeviationOptions deviation_options(Preset preset) {
  DeviationOptions o;
  switch (preset) {
    case Preset::fast:
      o.section_spacing_m = 0.5;
      o.ray_spacing_m = 0.1;
      break;
    case Preset::standard:
      o.section_spacing_m = 0.25;
      o.ray_spacing_m = 0.05;
      break;
    case Preset::precise:
      o.section_spacing_m = 0.1;
      o.ray_spacing_m = 0.02;
      break;
  }
  return o;
}

}  // namespace rockface::tunnel

#include "core/measure/proposals/trace_proposals.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>
#include <stdexcept>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/measure/proposals/disc_morphology.h"
#include "core/measure/proposals/line_chains.h"
#include "core/measure/proposals/line_evidence.h"
#include "core/measure/proposals/proposal_search.h"
#include "core/measure/proposals/row_stripes.h"
#include "core/measure/proposals/trace_proposals_phases.h"

namespace rockface::measure {

namespace pr = proposals;

namespace {

// Chains are joined across gaps and junctions when they run on within this
// angle: a joint trace bends gently; two joints meet at larger angles.
constexpr double kJoinTurnDeg = 30.0;
// Fewest pixels of a chain worth following (shorter: speckle).
constexpr int kMinChainPixels = 5;
// Douglas-Peucker tolerance of a chain's polyline, working pixels: the
// thinned line is within a pixel of the ridge.
constexpr double kSimplifyPx = 1.0;
// A triangle with an edge this many lattice spacings long bridges a depth
// jump (the range pole in front of the face), not rock.
constexpr double kJumpEdgeSpacings = 4.0;
// Dark-line and fold evidence found within this many working pixels of a
// chain counts as lying on it (the thinned lines of the two cues are a
// pixel or two apart where both see the same trace).
constexpr int kEvidenceReachPx = 2;

cv::Mat dilated(const cv::Mat& m, int radius) {
  return pr::dilate_disc(m, radius);
}

// The working-image samples of a polyline, one per pixel along it.
std::vector<cv::Point> pixels_along(const std::vector<cv::Point2f>& poly) {
  std::vector<cv::Point> out;
  for (std::size_t i = 1; i < poly.size(); ++i) {
    const cv::Point2f a = poly[i - 1], b = poly[i];
    const int n = std::max(1, static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y))));
    for (int k = i == 1 ? 0 : 1; k <= n; ++k) {
      const float t = static_cast<float>(k) / static_cast<float>(n);
      out.emplace_back(static_cast<int>(std::lround(a.x + t * (b.x - a.x))),
                       static_cast<int>(std::lround(a.y + t * (b.y - a.y))));
    }
  }
  return out;
}

double turn_deg(cv::Point2f a, cv::Point2f b, cv::Point2f c) {
  const cv::Point2f u = b - a, v = c - b;
  const double lu = std::hypot(u.x, u.y), lv = std::hypot(v.x, v.y);
  if (lu == 0 || lv == 0) return 0;
  return std::acos(std::clamp((u.x * v.x + u.y * v.y) / (lu * lv), -1.0, 1.0)) * 180 / M_PI;
}

// Distance from p to the closed polygon's edges.
double distance_to_outline(const std::vector<Eigen::Vector3d>& outline, const Eigen::Vector3d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector3d& a = outline[i];
    const Eigen::Vector3d& b = outline[(i + 1) % outline.size()];
    const Eigen::Vector3d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-24), 0.0, 1.0);
    best = std::min(best, (a + t * ab - p).norm());
  }
  return best;
}

}  // namespace

namespace proposal_phases {

// Pixels of the photograph per metre on the surface: the median over a
// sample of lattice edges.
double pixels_per_metre(const photogrammetry::SurfaceMesh& mesh) {
  std::vector<double> r;
  const std::size_t stride = std::max<std::size_t>(1, mesh.triangles.size() / 5000);
  for (std::size_t i = 0; i < mesh.triangles.size(); i += stride) {
    const auto& t = mesh.triangles[i];
    const double m = (mesh.vertices[t[0]] - mesh.vertices[t[1]]).norm();
    if (m > 0) r.push_back((mesh.pixels[t[0]] - mesh.pixels[t[1]]).cast<double>().norm() / m);
  }
  if (r.empty()) return 1.0;
  auto mid = r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2);
  std::nth_element(r.begin(), mid, r.end());
  return *mid;
}

void check_proposal_input(const photogrammetry::SurfaceMesh& mesh, const PhotoView& view,
                          const cv::Mat& photo, const ProposalOptions& options,
                          const std::string& where) {
  if (photo.empty()) throw InputError(where, "no photograph to find traces on");
  if (photo.cols != view.camera.width || photo.rows != view.camera.height)
    throw InputError(where, "the photograph is " + std::to_string(photo.cols) + " x " +
                                std::to_string(photo.rows) + " px but its camera " +
                                std::to_string(view.camera.width) + " x " +
                                std::to_string(view.camera.height));
  if (mesh.empty() || mesh.pixels.size() != mesh.vertices.size() || mesh.triangles.empty())
    throw InputError(where, "the 3D image has no lattice on the photograph (no vertex pixels)");
  if (options.line_widths_m.empty() || options.pixels_per_line <= 0)
    throw InputError(where, "no line widths to look for");
}

WorkingImage working_image(const photogrammetry::SurfaceMesh& mesh, const cv::Mat& photo,
                           const ProposalOptions& options) {
  WorkingImage out;
  const double px_per_m = pixels_per_metre(mesh);
  const double narrowest =
      *std::min_element(options.line_widths_m.begin(), options.line_widths_m.end());
  const double scale = std::min(1.0, options.pixels_per_line / (narrowest * px_per_m));
  out.scale = scale;
  out.px_per_m = px_per_m * scale;
  cv::Mat grey_levels;
  if (photo.channels() == 3)
    cv::cvtColor(photo, grey_levels, cv::COLOR_BGR2GRAY);
  else
    grey_levels = photo;
  // 24 Mpx in floats (96 MB, each page touched for the first time): on the
  // analysis threads, each its stripe.
  cv::Mat& grey = out.grey;
  grey.create(grey_levels.size(), CV_MAKETYPE(CV_32F, grey_levels.channels()));
  proposals::for_row_stripes(grey_levels.size(), [&](cv::Range rows) {
    cv::Mat grey_rows = grey.rowRange(rows);
    grey_levels.rowRange(rows).convertTo(grey_rows, CV_32F);
  });
  if (scale < 1) cv::resize(grey, grey, cv::Size(), scale, scale, cv::INTER_AREA);
  return out;
}

pr::DarkLines find_dark_lines_on(const WorkingImage& image, const pr::SurfaceImage& surface,
                                 const ProposalOptions& options) {
  pr::DarkLineSettings dark_settings;
  double widest_px = 0;
  for (double w : options.line_widths_m) {
    dark_settings.widths_px.push_back(w * image.px_per_m);
    widest_px = std::max(widest_px, w * image.px_per_m);
  }
  dark_settings.seed_sigmas = options.dark_seed_sigmas;
  dark_settings.keep_sigmas = options.dark_keep_sigmas;
  dark_settings.min_contrast_grey = options.min_contrast_grey;
  // The surface's edge is a step to no surface, not a line.
  const int dark_margin = static_cast<int>(std::ceil(widest_px)) + 2;
  return pr::find_dark_lines(image.grey, pr::erode_disc(surface.mask, dark_margin), dark_settings);
}

EvidenceMaps evidence_maps(const pr::DarkLines& dark, const pr::Folds& folds, double smoothing_px) {
  EvidenceMaps maps;
  maps.dark = dilated(dark.lines, kEvidenceReachPx);
  maps.dark_sigmas = dilated(dark.sigmas, kEvidenceReachPx);
  maps.dark_contrast = dilated(dark.contrast, kEvidenceReachPx);
  // A fold is located only to its smoothing width: the dark line beside it
  // is the same trace when within that.
  const int fold_reach = std::max(kEvidenceReachPx, static_cast<int>(std::ceil(smoothing_px)));
  maps.fold = dilated(folds.lines, fold_reach);
  maps.fold_angle = dilated(folds.angle, fold_reach);
  maps.ridge = dilated(folds.ridge & folds.lines, fold_reach);
  maps.valley = dilated(~folds.ridge & folds.lines, fold_reach);
  maps.dark_near_fold = dilated(dark.lines, fold_reach);
  return maps;
}

std::vector<pr::Chain> fold_runs(const pr::Chain& chain, const cv::Mat& dark_near_fold,
                                 int min_pixels) {
  std::vector<pr::Chain> runs;
  pr::Chain run;
  for (const cv::Point2f& p : chain) {
    if (dark_near_fold.at<std::uint8_t>(cv::Point(p))) {
      if (static_cast<int>(run.size()) >= min_pixels) runs.push_back(run);
      run.clear();
    } else {
      run.push_back(p);
    }
  }
  if (static_cast<int>(run.size()) >= min_pixels) runs.push_back(run);
  return runs;
}

std::vector<pr::Chain> candidate_chains(const pr::DarkLines& dark, const pr::Folds& folds,
                                        const cv::Mat& dark_near_fold, double gap_px) {
  std::vector<pr::Chain> chains =
      pr::join_chains(pr::trace_chains(dark.lines, kMinChainPixels), gap_px, kJoinTurnDeg);
  std::vector<pr::Chain> runs;
  for (const pr::Chain& c : pr::trace_chains(folds.lines, kMinChainPixels)) {
    const std::vector<pr::Chain> away = fold_runs(c, dark_near_fold, kMinChainPixels);
    runs.insert(runs.end(), away.begin(), away.end());
  }
  const std::vector<pr::Chain> joined_folds = pr::join_chains(runs, gap_px, kJoinTurnDeg);
  chains.insert(chains.end(), joined_folds.begin(), joined_folds.end());
  return chains;
}

std::vector<std::vector<cv::Point2f>> surface_runs(
    const std::vector<cv::Point2f>& poly,
    const std::function<bool(const cv::Point2f&)>& on_surface) {
  std::vector<std::vector<cv::Point2f>> runs(1);
  for (const auto& p : poly) {
    if (on_surface(p)) {
      runs.back().push_back(p);
    } else if (!runs.back().empty()) {
      runs.emplace_back();
    }
  }
  return runs;
}

std::vector<std::vector<cv::Point2f>> split_at_turns(
    const std::vector<cv::Point2f>& run, double split_turn_deg,
    const std::function<bool(const std::vector<cv::Point2f>&)>& one_plane, double window_px) {
  // Arc length to each vertex, and the point at arc length t (clamped).
  std::vector<double> arc(run.size(), 0.0);
  for (std::size_t k = 1; k < run.size(); ++k)
    arc[k] = arc[k - 1] + std::hypot(run[k].x - run[k - 1].x, run[k].y - run[k - 1].y);
  const auto at = [&](double t) {
    if (t <= 0) return run.front();
    if (t >= arc.back()) return run.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(arc.begin(), arc.end(), t) -
                                                   arc.begin());  // arc[k-1] <= t < arc[k]
    const double f = (t - arc[k - 1]) / std::max(arc[k] - arc[k - 1], 1e-9);
    return run[k - 1] + static_cast<float>(f) * (run[k] - run[k - 1]);
  };
  // The turn at each vertex, between the directions over window_px on
  // either side (the neighbouring vertices without a window).
  std::vector<double> turn(run.size(), 0.0);
  for (std::size_t k = 1; k + 1 < run.size(); ++k)
    turn[k] = window_px > 0 ? turn_deg(at(arc[k] - window_px), run[k], at(arc[k] + window_px))
                            : turn_deg(run[k - 1], run[k], run[k + 1]);
  // One split per turn: the sharpest vertex of each run of vertices over the
  // threshold within a window of each other.
  std::vector<bool> split(run.size(), false);
  for (std::size_t k = 1; k + 1 < run.size();) {
    if (turn[k] <= split_turn_deg) {
      ++k;
      continue;
    }
    std::size_t best = k, e = k;
    while (e + 1 < run.size() - 1 && turn[e + 1] > split_turn_deg &&
           arc[e + 1] - arc[e] <= std::max(window_px, 0.0)) {
      ++e;
      if (turn[e] > turn[best]) best = e;
    }
    split[best] = true;
    k = e + 1;
  }
  std::vector<std::vector<cv::Point2f>> pieces{{run[0]}};
  for (std::size_t k = 1; k < run.size(); ++k) {
    pieces.back().push_back(run[k]);
    if (split[k]) pieces.push_back({run[k]});
  }
  std::vector<std::vector<cv::Point2f>> kept;
  for (auto& piece : pieces) {
    if (piece.size() < 2) continue;
    if (!kept.empty()) {
      std::vector<cv::Point2f> both = kept.back();
      both.insert(both.end(), piece.begin() + 1, piece.end());
      if (one_plane(both)) {
        kept.back() = std::move(both);
        continue;
      }
    }
    kept.push_back(std::move(piece));
  }
  return kept;
}

Evidence evidence_along(const EvidenceMaps& maps, const std::vector<cv::Point2f>& poly) {
  Evidence e;
  int n = 0, dark = 0, fold = 0, ridge = 0, valley = 0;
  for (const cv::Point& p : pixels_along(poly)) {
    if (p.x < 0 || p.y < 0 || p.x >= maps.dark.cols || p.y >= maps.dark.rows) continue;
    ++n;
    if (maps.dark.at<std::uint8_t>(p)) {
      ++dark;
      e.sigmas += maps.dark_sigmas.at<float>(p);
      e.contrast += maps.dark_contrast.at<float>(p);
    }
    if (maps.fold.at<std::uint8_t>(p)) {
      ++fold;
      e.fold_deg += maps.fold_angle.at<float>(p);
      ridge += maps.ridge.at<std::uint8_t>(p) != 0;
      valley += maps.valley.at<std::uint8_t>(p) != 0;
    }
  }
  if (n == 0) return e;
  e.dark_fraction = static_cast<double>(dark) / n;
  e.fold_fraction = static_cast<double>(fold) / n;
  if (dark > 0) {
    e.sigmas /= dark;
    e.contrast /= dark;
  }
  if (fold > 0) e.fold_deg /= fold;
  e.ridge = ridge > valley;
  return e;
}

ProposalCue proposal_cue(const Evidence& e) {
  return e.dark_fraction >= 0.5 && e.fold_fraction >= 0.5 ? ProposalCue::both
         : e.dark_fraction >= e.fold_fraction             ? ProposalCue::dark_line
                                                          : ProposalCue::fold;
}

double proposal_confidence(const Evidence& e, double length_m, const ProposalOptions& options) {
  const double e_dark = e.dark_fraction * (1 - std::exp(-e.sigmas / options.dark_seed_sigmas));
  const double e_fold = e.fold_fraction * (1 - std::exp(-e.fold_deg / options.min_fold_deg));
  const double cues = 1 - (1 - e_dark) * (1 - e_fold);
  const double length_factor = 1 - std::exp(-length_m / (2 * options.min_length_m));
  return std::clamp(cues * length_factor, 0.0, 1.0);
}

MeasuredChains measure_chains(const std::vector<pr::Chain>& chains, const EvidenceMaps& maps,
                              const MeshPicker& picker, const PhotoView& view,
                              const WorkingImage& image, const ProposalOptions& options,
                              Progress& progress, const std::string& where,
                              const std::vector<std::size_t>* which) {
  const double scale = image.scale;
  const double min_length_px = options.min_length_m * image.px_per_m;
  // Turns are read over two widths of the widest line: within that the
  // skeleton wiggles where another line crosses.
  const double turn_window_px =
      2.0 * *std::max_element(options.line_widths_m.begin(), options.line_widths_m.end()) *
      image.px_per_m;
  MeasuredChains out;
  std::vector<TraceProposal>& found = out.found;
  int& short_chains = out.short_chains;
  int& unmeasurable = out.unmeasurable;
  const auto to_photo = [scale](const cv::Point2f& p) {
    return Eigen::Vector2d(p.x / scale, p.y / scale);
  };
  auto on_surface = [&](const cv::Point2f& p) {
    const Eigen::Vector2d px = to_photo(p);
    return pixel_in_image(view, px) && picker.pick(ray_through_pixel(view, px, where)).has_value();
  };
  auto measure_piece =
      [&](const std::vector<cv::Point2f>& poly) -> std::optional<TraceMeasurement> {
    std::vector<Eigen::Vector2d> pixels;
    for (const auto& p : poly) pixels.push_back(to_photo(p));
    try {
      return measure_trace(picker, view, "", pixels, options.measure, where);
    } catch (const InputError&) {
      return std::nullopt;  // a vertex off the surface: checked before, so rare
    }
  };
  auto one_plane = [&](const std::vector<cv::Point2f>& poly) {
    const auto m = measure_piece(poly);
    return m && m->plane.known;
  };
  const std::size_t count = which ? which->size() : chains.size();
  for (std::size_t at = 0; at < count; ++at) {
    const std::size_t ci = which ? (*which)[at] : at;
    if (at % 64 == 0)
      progress.step("measuring proposals",
                    0.65 + 0.3 * static_cast<double>(at) / static_cast<double>(count));
    if (pr::chain_length(chains[ci]) < min_length_px) {
      ++short_chains;
      continue;
    }
    std::vector<cv::Point2f> poly;
    cv::approxPolyDP(chains[ci], poly, kSimplifyPx, false);
    for (const auto& run : surface_runs(poly, on_surface)) {
      if (run.size() < 2) continue;
      // Split at sharp turns unless both sides are one plane with relief
      // (a trace crossing a fold of the face).
      for (const auto& piece :
           split_at_turns(run, options.split_turn_deg, one_plane, turn_window_px)) {
        if (pr::chain_length(piece) < min_length_px) {
          ++short_chains;
          continue;
        }
        auto m = measure_piece(piece);
        if (!m || m->length < options.min_length_m) {
          ++(m ? short_chains : unmeasurable);
          continue;
        }
        TraceProposal p;
        const Evidence e = evidence_along(maps, piece);
        p.contrast_grey = e.contrast;
        p.fold_deg = e.fold_deg;
        p.ridge = e.ridge;
        p.dark_fraction = e.dark_fraction;
        p.fold_fraction = e.fold_fraction;
        p.cue = proposal_cue(e);
        p.confidence = proposal_confidence(e, m->length, options);
        p.trace = std::move(*m);
        found.push_back(std::move(p));
        out.chain_of.push_back(ci);
      }
    }
  }
  return out;
}

std::vector<std::string> left_out_notes(const MeasuredChains& measured,
                                        const ProposalOptions& options) {
  std::vector<std::string> notes;
  const int short_chains = measured.short_chains, unmeasurable = measured.unmeasurable;
  if (short_chains > 0)
    notes.push_back(std::to_string(short_chains) + " lines shorter than " +
                    std::to_string(static_cast<int>(std::lround(options.min_length_m * 100))) +
                    " cm left out");
  if (unmeasurable > 0)
    notes.push_back(std::to_string(unmeasurable) +
                    " lines left out: no surface of the 3D image under them");

  return notes;
}

void link_facets(std::vector<TraceProposal>& found, const std::vector<ProposalFacet>& facets,
                 const ProposalOptions& options) {
  // Each outline's bounding box: a point farther than the tolerance from
  // the box is farther from the outline, and its segments need not be
  // read (1 nm more than the tolerance: the box's distance and the
  // segments' are rounded differently).
  std::vector<Eigen::AlignedBox3d> boxes;
  boxes.reserve(facets.size());
  for (const ProposalFacet& f : facets) {
    Eigen::AlignedBox3d box;
    for (const auto& x : f.outline) box.extend(x);
    boxes.push_back(box);
  }
  const double reach = options.facet_tolerance_m + 1e-9;
  for (TraceProposal& p : found) {
    for (std::size_t i = 0; i < facets.size(); ++i) {
      const ProposalFacet& f = facets[i];
      if (f.outline.size() < 2 || p.trace.points.empty()) continue;
      std::size_t near = 0;
      for (const auto& x : p.trace.points)
        near += boxes[i].exteriorDistance(x) <= reach &&
                distance_to_outline(f.outline, x) <= options.facet_tolerance_m;
      const double fraction =
          static_cast<double>(near) / static_cast<double>(p.trace.points.size());
      if (fraction >= options.facet_fraction && fraction > p.facet_fraction) {
        p.facet_id = f.id;
        p.facet_fraction = fraction;
      }
    }
  }
}

void rank_proposals(std::vector<TraceProposal>& found, const ProposalOptions& options,
                    std::vector<std::string>& notes) {
  const std::size_t before = found.size();
  found.erase(
      std::remove_if(found.begin(), found.end(),
                     [&](const TraceProposal& p) { return p.confidence < options.min_confidence; }),
      found.end());
  if (found.size() < before)
    notes.push_back(std::to_string(before - found.size()) + " lines left out: confidence below " +
                    std::to_string(static_cast<int>(std::lround(options.min_confidence * 100))) +
                    " %");
  std::stable_sort(found.begin(), found.end(), [](const TraceProposal& a, const TraceProposal& b) {
    return a.confidence > b.confidence;
  });
  for (std::size_t i = 0; i < found.size(); ++i) {
    found[i].id = "P" + std::to_string(i + 1);
    found[i].trace.id = found[i].id;
  }
}

}  // namespace proposal_phases

struct ProposalSearch::State {
  const MeshPicker* picker = nullptr;
  const PhotoView* view = nullptr;
  ProposalOptions options;
  std::string where;
  proposal_phases::WorkingImage image;
  proposal_phases::EvidenceMaps maps;
  std::vector<pr::Chain> chains;
  ProposalResult result;  // the figures of the cues; the proposals come at the end
  // The chains by falling length (ties: the earlier first), how many of
  // them are measured, and what they gave.
  std::vector<std::size_t> longest_first;
  std::size_t measured_count = 0;
  proposal_phases::MeasuredChains measured;
  bool finished = false;
};

ProposalSearch::ProposalSearch(const photogrammetry::SurfaceMesh& mesh, const MeshPicker& picker,
                               const PhotoView& view, const cv::Mat& photo,
                               const ProposalOptions& options, Progress& progress,
                               const std::string& where)
    : state_(std::make_unique<State>()) {
  using namespace proposal_phases;
  check_proposal_input(mesh, view, photo, options, where);
  State& s = *state_;
  s.picker = &picker;
  s.view = &view;
  s.options = options;
  s.where = where;

  progress.step("reading the photograph", 0.05);
  s.image = working_image(mesh, photo, options);
  const double work_px_per_m = s.image.px_per_m;
  s.result.pixel_scale = s.image.scale;

  progress.step("drawing the surface", 0.15);
  const double spacing = mesh.median_edge_length();
  const double smoothing_px =
      std::max(options.fold_scale_m * work_px_per_m, 3.0 * spacing * work_px_per_m);
  const pr::SurfaceImage surface =
      pr::draw_surface(mesh, s.image.grey.size(), s.image.scale, view.pose.centre,
                       kJumpEdgeSpacings * spacing, smoothing_px);

  progress.step("finding dark lines", 0.3);
  const pr::DarkLines dark = find_dark_lines_on(s.image, surface, options);
  s.result.line_noise = dark.noise;
  s.result.dark_pixels = static_cast<std::size_t>(cv::countNonZero(dark.lines));

  progress.step("finding folds", 0.45);
  pr::FoldSettings fold_settings;
  fold_settings.smoothing_px = smoothing_px;
  fold_settings.seed_deg = options.min_fold_deg;
  fold_settings.keep_deg = options.fold_keep_deg;
  const pr::Folds folds = pr::find_folds(surface, fold_settings);
  s.result.fold_pixels = static_cast<std::size_t>(cv::countNonZero(folds.lines));

  progress.step("joining lines", 0.55);
  s.maps = evidence_maps(dark, folds, smoothing_px);
  s.chains =
      candidate_chains(dark, folds, s.maps.dark_near_fold, options.max_gap_m * work_px_per_m);
  std::vector<double> length(s.chains.size());
  for (std::size_t i = 0; i < s.chains.size(); ++i) length[i] = pr::chain_length(s.chains[i]);
  s.longest_first.resize(s.chains.size());
  std::iota(s.longest_first.begin(), s.longest_first.end(), std::size_t{0});
  std::stable_sort(s.longest_first.begin(), s.longest_first.end(),
                   [&](std::size_t a, std::size_t b) { return length[a] > length[b]; });
}

ProposalSearch::~ProposalSearch() = default;

std::vector<TraceProposal> ProposalSearch::longest(std::size_t count, Progress& progress) {
  State& s = *state_;
  if (s.finished) throw std::logic_error("ProposalSearch::longest after finish");
  const std::size_t from = s.measured_count;
  const std::size_t to = std::min(s.chains.size(), from + count);
  const std::vector<std::size_t> which(s.longest_first.begin() + static_cast<std::ptrdiff_t>(from),
                                       s.longest_first.begin() + static_cast<std::ptrdiff_t>(to));
  proposal_phases::MeasuredChains batch = proposal_phases::measure_chains(
      s.chains, s.maps, *s.picker, *s.view, s.image, s.options, progress, s.where, &which);
  s.measured_count = to;
  std::vector<TraceProposal> shown;
  for (const TraceProposal& p : batch.found)
    if (p.confidence >= s.options.min_confidence) shown.push_back(p);
  std::stable_sort(shown.begin(), shown.end(), [](const TraceProposal& a, const TraceProposal& b) {
    return a.confidence > b.confidence;
  });
  auto& m = s.measured;
  m.found.insert(m.found.end(), std::make_move_iterator(batch.found.begin()),
                 std::make_move_iterator(batch.found.end()));
  m.chain_of.insert(m.chain_of.end(), batch.chain_of.begin(), batch.chain_of.end());
  m.short_chains += batch.short_chains;
  m.unmeasurable += batch.unmeasurable;
  return shown;
}

std::size_t ProposalSearch::chains_left() const {
  return state_->chains.size() - state_->measured_count;
}

ProposalResult ProposalSearch::finish(const std::vector<ProposalFacet>& facets,
                                      Progress& progress) {
  using namespace proposal_phases;
  State& s = *state_;
  if (s.finished) throw std::logic_error("ProposalSearch::finish twice");
  if (s.measured_count == 0) {
    progress.step("measuring proposals", 0.65);
    s.measured =
        measure_chains(s.chains, s.maps, *s.picker, *s.view, s.image, s.options, progress, s.where);
  } else {
    longest(s.chains.size(), progress);
    // In the chains' own order, as measuring them all in one go lists
    // them: the ranking's ties, and so the names, come out the same.
    std::vector<std::size_t> order(s.measured.found.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return s.measured.chain_of[a] < s.measured.chain_of[b];
    });
    std::vector<TraceProposal> found;
    found.reserve(order.size());
    for (std::size_t i : order) found.push_back(std::move(s.measured.found[i]));
    s.measured.found = std::move(found);
  }
  s.finished = true;
  ProposalResult result = std::move(s.result);
  result.notes = left_out_notes(s.measured, s.options);
  std::vector<TraceProposal>& found = s.measured.found;

  progress.step("linking facets", 0.95);
  link_facets(found, facets, s.options);
  rank_proposals(found, s.options, result.notes);
  result.proposals = std::move(found);
  progress.step("proposals ready", 1.0);
  return result;
}

ProposalResult propose_traces(const photogrammetry::SurfaceMesh& mesh, const MeshPicker& picker,
                              const PhotoView& view, const cv::Mat& photo,
                              const std::vector<ProposalFacet>& facets,
                              const ProposalOptions& options, Progress& progress,
                              const std::string& where) {
  ProposalSearch search(mesh, picker, view, photo, options, progress, where);
  return search.finish(facets, progress);
}

}  // namespace rockface::measure

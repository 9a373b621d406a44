#include "core/measure/facets/facets.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>

#include <Eigen/Eigenvalues>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/measure/facets/facet_outline.h"
#include "core/measure/facets/plane_led_growing.h"
#include "core/measure/facets/triangle_graph.h"
#include "core/measure/tolerances.h"

namespace rockface::measure {

namespace {

constexpr int kFree = -1;     // not yet in any region
constexpr int kDropped = -2;  // in a region too small or not planar: no seed, joins nothing
// A region with more than this share of its points beyond the planarity
// gate is rough, not planar: 5 % beyond 4 sigma means a scatter of at least
// twice the stated point precision (2 sigma of a normal law is its 4.6 %).
constexpr double kMaxOffPlaneShare = 0.05;
// Facets this many triangles apart (across a step of dense matching's
// terraces and the unfacetted band beside it: 10-25 cm at the standard
// preset's point spacing) are neighbours that may be merged when they are
// one plane.
constexpr int kTerraceHops = 30;

// The running plane of a growing region: area-weighted sums of the
// triangles' centres (for the best-fit plane) and normals (the mean normal
// the angle test compares with).
struct RunningPlane {
  double weight = 0;
  Eigen::Vector3d sum_centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum_outer = Eigen::Matrix3d::Zero();
  Eigen::Vector3d sum_normal = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d plane_normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  bool fitted = false;  // plane_normal is the best-fit plane's (else the mean normal)

  void add(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, double area) {
    weight += area;
    sum_centre += area * centre;
    sum_outer += area * centre * centre.transpose();
    sum_normal += area * normal;
  }
  // Mean normal always; the fitted plane's normal once the region is wide
  // enough in both directions that its tilt is better known than the
  // smoothed normals' mean (`wide`, m RMS).
  void refit(double wide) {
    mean_normal = sum_normal.normalized();
    centroid = sum_centre / weight;
    const Eigen::Matrix3d cov = sum_outer / weight - centroid * centroid.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const Eigen::Vector3d spread = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    Eigen::Vector3d n = eig.eigenvectors().col(0);
    if (n.dot(mean_normal) < 0) n = -n;
    fitted = spread(1) > wide;
    plane_normal = fitted ? n : mean_normal;
  }
};

// The facet search over one mesh: its triangle graph, smoothed normals and
// bending, the tests' thresholds, and each triangle's state as the phases
// (growing, plane-led growing, merging terraces, outlines) go.
class FacetFinder {
 public:
  FacetFinder(const photogrammetry::SurfaceMesh& mesh, const MeasureSettings& settings,
              const FacetOptions& options)
      : mesh_(mesh),
        settings_(settings),
        options_(options),
        graph_(triangle_graph(mesh)),
        normals_(smoothed_normals(graph_, options.smoothing_passes)),
        bend_(bending(graph_, normals_)) {}

  // The usable triangles (their area mapped, their normals summed into the
  // surface's), flattest first: the seeds. Empty when there are none.
  std::vector<int> seeds_flattest_first(FacetSearch& out) const;
  // What is set once the seeds are known: the thresholds and the state.
  void prepare();
  // The first pass: regions grown from the seeds, flattest first, by the
  // angle of their normals and the gate of their running plane.
  void grow_by_normals(const std::vector<int>& seeds, Progress& progress);
  // The second pass (plane_led_growing.h) over what the first left.
  void grow_led_by_planes(const std::vector<int>& seeds);
  void merge_terraces();
  // The rejected regions, and their area, as far as no facet took them.
  void count_rejected(FacetSearch& out) const;
  // Largest first, numbered, outlined; into `out`.
  void outline_facets(FacetSearch& out);

 private:
  std::vector<int> interior(const std::vector<int>& tris);
  Facet measured(const std::vector<int>& tris);
  std::vector<int> grow_region(int seed, int region, RunningPlane& plane);
  void add_or_reject(std::vector<int>& region, bool drop_rejected);
  std::vector<std::vector<int>> facets_within_terrace_hops() const;
  std::vector<int> with_steps(const Facet& merged, const std::vector<int>& group);

  const photogrammetry::SurfaceMesh& mesh_;
  const MeasureSettings& settings_;
  const FacetOptions& options_;
  const TriangleGraph graph_;
  const std::vector<Eigen::Vector3d> normals_;
  const std::vector<float> bend_;
  double angle_ = 0, cos_angle_ = 1, cos_twice_ = 1, gate_ = 0, edge_ = 0;
  std::vector<int> label_;
  // The region that failed the planarity tests, per triangle (-1: none):
  // what is left of it in no facet at the end is the rejected area (a
  // triangle of a rejected region may still join a facet later, by the
  // plane-led pass or as a step between terraces, and is then counted
  // there alone).
  std::vector<int> rejected_in_;
  int rejected_count_ = 0;
  std::vector<char> vertex_seen_;
  std::vector<int> queue_;
  std::vector<Facet> facets_;
  std::size_t done_ = 0;
  int border_hops_ = 0;
  std::vector<int> region_stamp_, hops_;
  int stamp_ = 0;
};

std::vector<int> FacetFinder::seeds_flattest_first(FacetSearch& out) const {
  Eigen::Vector3d surface = Eigen::Vector3d::Zero();
  std::vector<int> seeds;
  for (std::size_t t = 0; t < graph_.size(); ++t)
    if (graph_.usable(t)) {
      out.mapped_area += graph_.areas[t];
      surface += graph_.areas[t] * graph_.normals[t];
      seeds.push_back(static_cast<int>(t));
    }
  if (seeds.empty()) return seeds;
  if (surface.squaredNorm() > 0) out.surface_normal = surface.normalized();
  if (out.surface_normal.z() < 0) out.surface_normal = -out.surface_normal;
  // Flattest first (qFacets and DSE seed where the surface is most planar);
  // ties by index keep the result independent of the sort's whims. The
  // bend's bits order as its value (a bend is never negative), and the
  // seeds come in rising index: a stable radix sort on the bits gives the
  // order a stable sort on the bend gives, in four linear passes (a
  // comparison sort of the millions of seeds of a 24 Mpx model was a
  // third of the facets' first stage).
  std::vector<std::uint32_t> bits(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i)
    std::memcpy(&bits[i], &bend_[seeds[i]], sizeof bits[i]);
  std::vector<std::uint32_t> bits_out(seeds.size());
  std::vector<int> seeds_out(seeds.size());
  for (int shift = 0; shift < 32; shift += 8) {
    std::size_t start[257] = {};
    for (const std::uint32_t b : bits) ++start[((b >> shift) & 0xffu) + 1];
    for (int d = 0; d < 256; ++d) start[d + 1] += start[d];
    for (std::size_t i = 0; i < seeds.size(); ++i) {
      const std::size_t to = start[(bits[i] >> shift) & 0xffu]++;
      bits_out[to] = bits[i];
      seeds_out[to] = seeds[i];
    }
    bits.swap(bits_out);
    seeds.swap(seeds_out);
  }
  return seeds;
}

void FacetFinder::prepare() {
  angle_ = deg_to_rad(options_.angle_tolerance_deg);
  cos_angle_ = std::cos(angle_);
  cos_twice_ = std::cos(2 * angle_);
  gate_ = options_.planarity_in_sigmas * settings_.point_sigma;
  label_.assign(graph_.size(), kFree);
  rejected_in_.assign(graph_.size(), -1);
  vertex_seen_.assign(mesh_.vertices.size(), 0);
  edge_ = mesh_.median_edge_length();
  // The matching window blends the depths of the two sides of an edge over
  // its width (the correlation length), and a region grown to the gate of
  // its plane takes a band across a crease whose points lie on one side of
  // it: at each end of a strip a different side, which turns the plane
  // (stepped faces: 1.9 deg for strips whose inner points are 0.6 deg off).
  // The plane is therefore measured on the region's interior, the triangles
  // more than a correlation length (in triangle steps) from its border,
  // when that interior is itself as large as the smallest facet; the area
  // and outline stay the whole region's.
  border_hops_ = edge_ > 0 ? static_cast<int>(std::ceil(settings_.correlation_length / edge_)) : 0;
  region_stamp_.assign(graph_.size(), -1);
  hops_.assign(graph_.size(), 0);
}

std::vector<int> FacetFinder::interior(const std::vector<int>& tris) {
  if (border_hops_ <= 0) return tris;
  ++stamp_;
  for (int t : tris) region_stamp_[t] = stamp_;
  std::vector<int> frontier;
  for (int t : tris) {
    bool border = false;
    for (const int k : graph_.neighbours[t]) border = border || k < 0 || region_stamp_[k] != stamp_;
    hops_[t] = border ? 0 : -1;
    if (border) frontier.push_back(t);
  }
  for (std::size_t head = 0; head < frontier.size(); ++head) {
    const int t = frontier[head];
    if (hops_[t] >= border_hops_) continue;
    for (const int k : graph_.neighbours[t])
      if (k >= 0 && region_stamp_[k] == stamp_ && hops_[k] < 0) {
        hops_[k] = hops_[t] + 1;
        frontier.push_back(k);
      }
  }
  std::vector<int> inner;
  double area = 0;
  for (int t : tris)
    if (hops_[t] < 0) {
      inner.push_back(t);
      area += graph_.areas[t];
    }
  return area >= options_.min_area_m2 ? inner : tris;
}

// A region measured as an area picked by hand: its vertices' plane, the
// planarity, sliver, roughness and relief tests (plane.problem says which
// failed; empty when it is a facet), area, centroid and margins.
Facet FacetFinder::measured(const std::vector<int>& tris) {
  Facet f;
  std::vector<Eigen::Vector3d> points;
  for (int t : interior(tris))
    for (int v : mesh_.triangles[t])
      if (!vertex_seen_[v]) {
        vertex_seen_[v] = 1;
        points.push_back(mesh_.vertices[v]);
      }
  for (int t : tris)
    for (int v : mesh_.triangles[t]) vertex_seen_[v] = 0;
  f.plane = plane_of_points(points, settings_);
  f.plane.problem =
      planarity_problem(f.plane, settings_, options_.planarity_in_sigmas, "the facet");
  const double sigma_deg = rad_to_deg(f.plane.sigma);
  // The area measurement's sliver test: a region no wider than the noise
  // (a band along a crease, where the smoothed normals turn from one
  // plane to the next) is a line, not a plane.
  if (f.plane.problem.empty() && f.plane.fit.relief() < kMinReliefInSigmas * settings_.point_sigma)
    f.plane.problem = "orientation unknown: the region is a sliver (" +
                      format_fixed(f.plane.fit.relief() * 1000, 0) + " mm wide RMS)";
  // The growing kept triangles near its running plane: on a surface
  // rougher than the point precision it picks its way between the rest,
  // and the points it keeps can pass the RMS test only because the others
  // were left out. Their tail gives it away: under the stated precision a
  // point lies beyond the 4-sigma gate with odds of 6e-5.
  std::size_t off = 0;
  for (const auto& p : points) off += std::abs(f.plane.fit.plane().signed_distance(p)) > gate_;
  const double off_share = static_cast<double>(off) / static_cast<double>(points.size());
  if (f.plane.problem.empty() && off_share > kMaxOffPlaneShare)
    f.plane.problem = "orientation unknown: the surface is rougher than the point precision (" +
                      format_fixed(100 * off_share, 0) + " % of its points more than " +
                      format_fixed(options_.planarity_in_sigmas, 1) +
                      " point sigmas off its plane)";
  if (f.plane.problem.empty() && sigma_deg > settings_.max_plane_sigma_deg)
    f.plane.problem = "orientation unknown: too little relief for a reliable plane (" +
                      format_fixed(sigma_deg, 1) + " deg)";
  if (!f.plane.problem.empty()) return f;
  f.plane.known = true;
  double area = 0;
  Eigen::Vector3d sum_centre = Eigen::Vector3d::Zero();
  for (int t : tris) {
    area += graph_.areas[t];
    sum_centre += graph_.areas[t] * graph_.centres[t];
  }
  f.area = area;
  f.centroid = sum_centre / area;
  f.triangles = tris.size();
  f.vertices = points.size();
  f.planarity_margin_sigmas =
      options_.planarity_in_sigmas - f.plane.fit.rms_off_plane() / settings_.point_sigma;
  f.orientation_margin_deg = settings_.max_plane_sigma_deg - sigma_deg;
  f.marginal = f.planarity_margin_sigmas < 1.0 || f.orientation_margin_deg < sigma_deg;
  f.mesh_triangles = tris;
  return f;
}

// The region grown from `seed` (labelled `region`), its running plane in
// `plane`.
std::vector<int> FacetFinder::grow_region(int seed, int region, RunningPlane& plane) {
  std::vector<int> members(1, seed);
  queue_.assign(1, seed);
  label_[seed] = region;
  plane.add(graph_.centres[seed], normals_[seed], graph_.areas[seed]);
  plane.refit(gate_ * 10);
  double next_refit = 3;
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const int t = queue_[head];
    for (const int k : graph_.neighbours[t]) {
      if (k < 0 || label_[k] != kFree || !graph_.usable(static_cast<std::size_t>(k))) continue;
      // On the plane: all three corners within the planarity gate and
      // the normal within twice the tolerance (a noisy normal does not
      // keep a triangle that lies on the plane out, but one across a
      // ridge, whose smoothed normal is bent half way, stays out).
      // Else: its normal agrees and its centre is within the gate.
      // Only once the region's plane is fitted (wide enough): against a
      // plane still set by a few smoothed normals the corners' test would
      // pick points toward that first guess.
      // Nor where the surface creases (bending over the tolerance): the
      // corners of a triangle across a ridge lie within the gate of both
      // planes and would tilt the facet toward its neighbour.
      bool on_plane =
          plane.fitted && bend_[k] <= angle_ && normals_[k].dot(plane.mean_normal) >= cos_twice_;
      for (const int v : mesh_.triangles[k])
        on_plane = on_plane &&
                   std::abs(plane.plane_normal.dot(mesh_.vertices[v] - plane.centroid)) <= gate_;
      if (!on_plane &&
          (normals_[k].dot(plane.mean_normal) < cos_angle_ ||
           std::abs(plane.plane_normal.dot(graph_.centres[k] - plane.centroid)) > gate_))
        continue;
      label_[k] = region;
      members.push_back(k);
      queue_.push_back(k);
      plane.add(graph_.centres[k], normals_[k], graph_.areas[k]);
      if (static_cast<double>(members.size()) >= next_refit) {
        // Ten times the gate across the region: its fitted tilt is then
        // known to a few tenths of the angle tolerance.
        plane.refit(gate_ * 10);
        next_refit = std::max(next_refit + 1, next_refit * options_.refit_growth);
      }
    }
  }
  return members;
}

// A grown region measured: a facet, or rejected (its triangles dropped
// from the growing when `drop_rejected`).
void FacetFinder::add_or_reject(std::vector<int>& region, bool drop_rejected) {
  Facet f = measured(region);
  if (!f.plane.problem.empty()) {
    for (int t : region) {
      if (drop_rejected) label_[t] = kDropped;
      rejected_in_[t] = rejected_count_;
    }
    ++rejected_count_;
    return;
  }
  if (!drop_rejected)
    for (int t : region) label_[t] = static_cast<int>(facets_.size());
  facets_.push_back(std::move(f));
}

void FacetFinder::grow_by_normals(const std::vector<int>& seeds, Progress& progress) {
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const int seed = seeds[s];
    if ((s & 0xfff) == 0)
      progress.step("facets: growing",
                    static_cast<double>(done_) / static_cast<double>(seeds.size()));
    if (label_[seed] != kFree) continue;
    // The rest of the surface bends more than the tolerance at every
    // triangle: edges, creases, noise. No facet grows from there.
    if (bend_[seed] > angle_) break;
    RunningPlane plane;
    std::vector<int> members = grow_region(seed, static_cast<int>(facets_.size()), plane);
    done_ += members.size();
    if (plane.weight < options_.min_area_m2) {
      for (int t : members) label_[t] = kDropped;
      continue;
    }
    add_or_reject(members, true);
  }
}

// Led by the distance of the points to a fitted plane against the stated
// point precision, it finds the planes whose single triangles' normals
// scatter beyond the tolerance (a face seen obliquely). A seed patch's
// points must lie within two point sigmas RMS of their plane: half the
// planarity test a facet passes at the end, so that a seed across a crease
// or on a rough patch is refused before it grows.
void FacetFinder::grow_led_by_planes(const std::vector<int>& seeds) {
  std::vector<char> taken(graph_.size(), 0);
  for (std::size_t t = 0; t < graph_.size(); ++t) taken[t] = label_[t] >= 0;
  PlaneLedOptions led;
  led.gate = gate_;
  led.seed_rms = 2 * settings_.point_sigma;
  led.seed_area = options_.min_area_m2;
  led.refit_growth = options_.refit_growth;
  for (auto& region : plane_led_regions(mesh_, graph_, taken, seeds, led)) {
    double area = 0;
    for (int t : region) area += graph_.areas[t];
    if (area < options_.min_area_m2) continue;
    add_or_reject(region, false);
  }
}

// For each facet, the later facets within kTerraceHops usable triangles of
// it (ascending, once each).
std::vector<std::vector<int>> FacetFinder::facets_within_terrace_hops() const {
  const int n = static_cast<int>(facets_.size());
  std::vector<std::vector<int>> near(static_cast<std::size_t>(n));
  std::vector<int> stamp(graph_.size(), -1), depth(graph_.size(), 0), frontier;
  for (int i = 0; i < n; ++i) {
    frontier.clear();
    for (int t : facets_[i].mesh_triangles) {
      stamp[t] = i;
      depth[t] = 0;
      frontier.push_back(t);
    }
    for (std::size_t head = 0; head < frontier.size(); ++head) {
      const int t = frontier[head];
      for (const int k : graph_.neighbours[t]) {
        if (k < 0 || stamp[k] == i || !graph_.usable(static_cast<std::size_t>(k))) continue;
        stamp[k] = i;
        if (label_[k] >= 0) {
          if (label_[k] > i) near[i].push_back(label_[k]);
        } else if (depth[t] < kTerraceHops) {
          depth[k] = depth[t] + 1;
          frontier.push_back(k);
        }
      }
    }
    std::sort(near[i].begin(), near[i].end());
    near[i].erase(std::unique(near[i].begin(), near[i].end()), near[i].end());
  }
  return near;
}

// A merged group's triangles and the steps between its terraces: triangles
// of no facet next to the merged plane's, all three corners within the gate
// of it (marked -3 in label_, as the group's own).
std::vector<int> FacetFinder::with_steps(const Facet& merged, const std::vector<int>& group) {
  const Eigen::Vector3d normal = merged.plane.fit.normal;
  const Eigen::Vector3d centre = merged.plane.fit.centroid;
  std::vector<int> tris = group;
  for (int t : tris) label_[t] = -3;  // in this group
  for (std::size_t head = 0; head < tris.size(); ++head)
    for (const int k : graph_.neighbours[tris[head]]) {
      if (k < 0 || label_[k] >= 0 || label_[k] == -3 || !graph_.usable(static_cast<std::size_t>(k)))
        continue;
      bool within = true;
      for (const int v : mesh_.triangles[k])
        within = within && std::abs(normal.dot(mesh_.vertices[v] - centre)) <= gate_;
      if (!within) continue;
      label_[k] = -3;
      tris.push_back(k);
    }
  return tris;
}

// Dense matching's terraces (issue 38): on a face seen nearly square,
// sub-pixel disparities lock to whole pixels, and a plane comes out as
// strips a few pixels wide, each tilted a few degrees the same way, with a
// step between them where the normals turn further than the tolerance:
// the growing stops at every step and gives one facet per strip, tilted
// as the strips are. Facets within kTerraceHops triangles of each other
// (across the steps) whose normals agree within the tolerance and whose
// points together pass the planarity tests are one plane: merged (most
// alike first), then the steps between them, whose corners lie within
// the gate of the merged plane, taken in. The merged plane is the
// terraces' mean: the true plane.
void FacetFinder::merge_terraces() {
  const int n = static_cast<int>(facets_.size());
  if (n < 2) return;
  const std::vector<std::vector<int>> near = facets_within_terrace_hops();
  struct Pair {
    double angle;
    int a, b;
  };
  std::vector<Pair> pairs;
  for (int i = 0; i < n; ++i)
    for (int j : near[i]) {
      const double a = std::acos(std::clamp(
          std::abs(facets_[i].plane.fit.normal.dot(facets_[j].plane.fit.normal)), 0.0, 1.0));
      if (a <= angle_) pairs.push_back({a, i, j});
    }
  if (pairs.empty()) return;
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const Pair& x, const Pair& y) { return x.angle < y.angle; });
  std::vector<int> root(static_cast<std::size_t>(n));
  std::iota(root.begin(), root.end(), 0);
  std::vector<std::vector<int>> group(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) group[i] = facets_[i].mesh_triangles;
  // A merged group's measure: that of its last merge, which measured
  // exactly the group's triangles in their order (kept, not measured
  // again below).
  std::vector<Facet> merged(static_cast<std::size_t>(n));
  const auto find = [&](int x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  bool merged_any = false;
  for (const Pair& p : pairs) {
    const int ra = find(p.a), rb = find(p.b);
    if (ra == rb) continue;
    std::vector<int> both = group[ra];
    both.insert(both.end(), group[rb].begin(), group[rb].end());
    Facet joined = measured(both);
    if (!joined.plane.problem.empty()) continue;
    root[rb] = ra;
    merged[ra] = std::move(joined);
    group[ra] = std::move(both);
    group[rb].clear();
    merged_any = true;
  }
  if (!merged_any) return;
  std::vector<Facet> kept;
  for (int i = 0; i < n; ++i) {
    if (find(i) != i) continue;
    if (group[i].size() == facets_[i].mesh_triangles.size()) {
      kept.push_back(std::move(facets_[i]));
      continue;
    }
    Facet f = std::move(merged[i]);
    Facet steps_in = measured(with_steps(f, group[i]));
    kept.push_back(steps_in.plane.problem.empty() ? std::move(steps_in) : std::move(f));
  }
  facets_ = std::move(kept);
  for (std::size_t i = 0; i < facets_.size(); ++i)
    for (int t : facets_[i].mesh_triangles) label_[t] = static_cast<int>(i);
}

void FacetFinder::count_rejected(FacetSearch& out) const {
  std::vector<char> counted(static_cast<std::size_t>(rejected_count_), 0);
  for (std::size_t t = 0; t < graph_.size(); ++t)
    if (rejected_in_[t] >= 0 && label_[t] < 0) {
      out.rejected_area += graph_.areas[t];
      counted[rejected_in_[t]] = 1;
    }
  out.rejected_regions = static_cast<int>(std::count(counted.begin(), counted.end(), 1));
}

void FacetFinder::outline_facets(FacetSearch& out) {
  std::stable_sort(facets_.begin(), facets_.end(),
                   [](const Facet& a, const Facet& b) { return a.area > b.area; });
  std::vector<int> position(graph_.size(), -1);  // facet_outline's scratch
  for (std::size_t i = 0; i < facets_.size(); ++i) {
    Facet& f = facets_[i];
    f.id = static_cast<int>(i) + 1;
    // Thinned to two point spacings: the outline keeps the facet's shape
    // to the resolution of the 3D image without its lattice staircase.
    const FacetOutline outline =
        facet_outline(mesh_, f.mesh_triangles, 2.0 * edge_, &graph_, &position);
    f.outline = outline.outer;
    f.holes = outline.holes;
    out.facet_area += f.area;
  }
  out.facets = std::move(facets_);
}

}  // namespace

FacetSearch find_facets(const photogrammetry::SurfaceMesh& mesh, const MeasureSettings& settings,
                        const FacetOptions& options, Progress& progress) {
  check_facet_options(options);
  if (!(settings.point_sigma > 0) || !std::isfinite(settings.point_sigma))
    throw InputError("point_sigma",
                     "the point precision of the 3D image must be a positive "
                     "length (m), got " +
                         std::to_string(settings.point_sigma));
  FacetSearch out;
  out.options = options;
  out.point_sigma = settings.point_sigma;
  if (mesh.triangles.empty()) {
    out.notes.push_back("the 3D image has no triangles: no facets");
    return out;
  }
  progress.step("facets: mesh", 0.0);
  FacetFinder finder(mesh, settings, options);
  const std::vector<int> seeds = finder.seeds_flattest_first(out);
  if (seeds.empty()) {
    out.notes.push_back("the 3D image has no usable triangle (all degenerate): no facets");
    return out;
  }
  finder.prepare();
  finder.grow_by_normals(seeds, progress);
  progress.step("facets: plane-led growing", 0.8);
  finder.grow_led_by_planes(seeds);
  finder.merge_terraces();
  finder.count_rejected(out);
  progress.step("facets: outlines", 0.95);
  finder.outline_facets(out);
  if (out.facets.empty())
    out.notes.push_back("no planar region of at least " + format_fixed(options.min_area_m2, 2) +
                        " m2 within " + format_fixed(options.angle_tolerance_deg, 0) + " deg and " +
                        format_fixed(options.planarity_in_sigmas, 1) + " point sigmas of a plane");
  progress.step("facets: done", 1.0);
  return out;
}

}  // namespace rockface::measure

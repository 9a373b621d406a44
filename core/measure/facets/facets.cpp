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
  const TriangleGraph graph = triangle_graph(mesh);
  const std::vector<Eigen::Vector3d> normals = smoothed_normals(graph, options.smoothing_passes);
  const std::vector<float> bend = bending(graph, normals);
  Eigen::Vector3d surface = Eigen::Vector3d::Zero();
  std::vector<int> seeds;
  for (std::size_t t = 0; t < graph.size(); ++t)
    if (graph.usable(t)) {
      out.mapped_area += graph.areas[t];
      surface += graph.areas[t] * graph.normals[t];
      seeds.push_back(static_cast<int>(t));
    }
  if (seeds.empty()) {
    out.notes.push_back("the 3D image has no usable triangle (all degenerate): no facets");
    return out;
  }
  if (surface.squaredNorm() > 0) out.surface_normal = surface.normalized();
  if (out.surface_normal.z() < 0) out.surface_normal = -out.surface_normal;
  // Flattest first (qFacets and DSE seed where the surface is most planar);
  // ties by index keep the result independent of the sort's whims. Sorted
  // as one 64-bit key per seed, the bend's bits above the index (a bend is
  // never negative, so its bits order as its value): the order a stable
  // sort on the bend gives, without its indirect reads.
  {
    std::vector<std::uint64_t> keys(seeds.size());
    for (std::size_t i = 0; i < seeds.size(); ++i) {
      std::uint32_t bits = 0;
      std::memcpy(&bits, &bend[seeds[i]], sizeof bits);
      keys[i] = (static_cast<std::uint64_t>(bits) << 32) | static_cast<std::uint32_t>(seeds[i]);
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < seeds.size(); ++i)
      seeds[i] = static_cast<int>(keys[i] & 0xffffffffu);
  }

  const double angle = deg_to_rad(options.angle_tolerance_deg);
  const double cos_angle = std::cos(angle), cos_twice = std::cos(2 * angle);
  const double gate = options.planarity_in_sigmas * settings.point_sigma;
  std::vector<int> label(graph.size(), kFree);
  // The region that failed the planarity tests, per triangle (-1: none):
  // what is left of it in no facet at the end is the rejected area (a
  // triangle of a rejected region may still join a facet later, by the
  // plane-led pass or as a step between terraces, and is then counted
  // there alone).
  std::vector<int> rejected_in(graph.size(), -1);
  int rejected_count = 0;
  std::vector<char> vertex_seen(mesh.vertices.size(), 0);
  std::vector<int> members, queue;
  std::vector<Facet> facets;
  const double edge = mesh.median_edge_length();
  std::size_t done = 0;
  // A region measured as an area picked by hand: its vertices' plane, the
  // planarity, sliver, roughness and relief tests (plane.problem says which
  // failed; empty when it is a facet), area, centroid and margins.
  // The matching window blends the depths of the two sides of an edge over
  // its width (the correlation length), and a region grown to the gate of
  // its plane takes a band across a crease whose points lie on one side of
  // it: at each end of a strip a different side, which turns the plane
  // (stepped faces: 1.9 deg for strips whose inner points are 0.6 deg off).
  // The plane is therefore measured on the region's interior, the triangles
  // more than a correlation length (in triangle steps) from its border,
  // when that interior is itself as large as the smallest facet; the area
  // and outline stay the whole region's.
  const int border_hops =
      edge > 0 ? static_cast<int>(std::ceil(settings.correlation_length / edge)) : 0;
  std::vector<int> region_stamp(graph.size(), -1), hops(graph.size(), 0);
  int stamp = 0;
  const auto interior = [&](const std::vector<int>& tris) {
    if (border_hops <= 0) return tris;
    ++stamp;
    for (int t : tris) region_stamp[t] = stamp;
    std::vector<int> frontier;
    for (int t : tris) {
      bool border = false;
      for (const int k : graph.neighbours[t]) border = border || k < 0 || region_stamp[k] != stamp;
      hops[t] = border ? 0 : -1;
      if (border) frontier.push_back(t);
    }
    for (std::size_t head = 0; head < frontier.size(); ++head) {
      const int t = frontier[head];
      if (hops[t] >= border_hops) continue;
      for (const int k : graph.neighbours[t])
        if (k >= 0 && region_stamp[k] == stamp && hops[k] < 0) {
          hops[k] = hops[t] + 1;
          frontier.push_back(k);
        }
    }
    std::vector<int> inner;
    double area = 0;
    for (int t : tris)
      if (hops[t] < 0) {
        inner.push_back(t);
        area += graph.areas[t];
      }
    return area >= options.min_area_m2 ? inner : tris;
  };
  const auto measured = [&](const std::vector<int>& tris) {
    Facet f;
    std::vector<Eigen::Vector3d> points;
    for (int t : interior(tris))
      for (int v : mesh.triangles[t])
        if (!vertex_seen[v]) {
          vertex_seen[v] = 1;
          points.push_back(mesh.vertices[v]);
        }
    for (int t : tris)
      for (int v : mesh.triangles[t]) vertex_seen[v] = 0;
    f.plane = plane_of_points(points, settings);
    f.plane.problem =
        planarity_problem(f.plane, settings, options.planarity_in_sigmas, "the facet");
    const double sigma_deg = rad_to_deg(f.plane.sigma);
    // The area measurement's sliver test: a region no wider than the noise
    // (a band along a crease, where the smoothed normals turn from one
    // plane to the next) is a line, not a plane.
    if (f.plane.problem.empty() && f.plane.fit.relief() < kMinReliefInSigmas * settings.point_sigma)
      f.plane.problem = "orientation unknown: the region is a sliver (" +
                        format_fixed(f.plane.fit.relief() * 1000, 0) + " mm wide RMS)";
    // The growing kept triangles near its running plane: on a surface
    // rougher than the point precision it picks its way between the rest,
    // and the points it keeps can pass the RMS test only because the others
    // were left out. Their tail gives it away: under the stated precision a
    // point lies beyond the 4-sigma gate with odds of 6e-5.
    std::size_t off = 0;
    for (const auto& p : points) off += std::abs(f.plane.fit.plane().signed_distance(p)) > gate;
    const double off_share = static_cast<double>(off) / static_cast<double>(points.size());
    if (f.plane.problem.empty() && off_share > kMaxOffPlaneShare)
      f.plane.problem = "orientation unknown: the surface is rougher than the point precision (" +
                        format_fixed(100 * off_share, 0) + " % of its points more than " +
                        format_fixed(options.planarity_in_sigmas, 1) +
                        " point sigmas off its plane)";
    if (f.plane.problem.empty() && sigma_deg > settings.max_plane_sigma_deg)
      f.plane.problem = "orientation unknown: too little relief for a reliable plane (" +
                        format_fixed(sigma_deg, 1) + " deg)";
    if (!f.plane.problem.empty()) return f;
    f.plane.known = true;
    double area = 0;
    Eigen::Vector3d sum_centre = Eigen::Vector3d::Zero();
    for (int t : tris) {
      area += graph.areas[t];
      sum_centre += graph.areas[t] * graph.centres[t];
    }
    f.area = area;
    f.centroid = sum_centre / area;
    f.triangles = tris.size();
    f.vertices = points.size();
    f.planarity_margin_sigmas =
        options.planarity_in_sigmas - f.plane.fit.rms_off_plane() / settings.point_sigma;
    f.orientation_margin_deg = settings.max_plane_sigma_deg - sigma_deg;
    f.marginal = f.planarity_margin_sigmas < 1.0 || f.orientation_margin_deg < sigma_deg;
    f.mesh_triangles = tris;
    return f;
  };

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
  const auto merge_terraces = [&](std::vector<Facet>& found, std::vector<int>& owner) {
    const int n = static_cast<int>(found.size());
    if (n < 2) return;
    std::vector<std::vector<int>> near(static_cast<std::size_t>(n));
    std::vector<int> stamp(graph.size(), -1), depth(graph.size(), 0), frontier;
    for (int i = 0; i < n; ++i) {
      frontier.clear();
      for (int t : found[i].mesh_triangles) {
        stamp[t] = i;
        depth[t] = 0;
        frontier.push_back(t);
      }
      for (std::size_t head = 0; head < frontier.size(); ++head) {
        const int t = frontier[head];
        for (const int k : graph.neighbours[t]) {
          if (k < 0 || stamp[k] == i || !graph.usable(static_cast<std::size_t>(k))) continue;
          stamp[k] = i;
          if (owner[k] >= 0) {
            if (owner[k] > i) near[i].push_back(owner[k]);
          } else if (depth[t] < kTerraceHops) {
            depth[k] = depth[t] + 1;
            frontier.push_back(k);
          }
        }
      }
      std::sort(near[i].begin(), near[i].end());
      near[i].erase(std::unique(near[i].begin(), near[i].end()), near[i].end());
    }
    struct Pair {
      double angle;
      int a, b;
    };
    std::vector<Pair> pairs;
    for (int i = 0; i < n; ++i)
      for (int j : near[i]) {
        const double a = std::acos(std::clamp(
            std::abs(found[i].plane.fit.normal.dot(found[j].plane.fit.normal)), 0.0, 1.0));
        if (a <= angle) pairs.push_back({a, i, j});
      }
    if (pairs.empty()) return;
    std::stable_sort(pairs.begin(), pairs.end(),
                     [](const Pair& x, const Pair& y) { return x.angle < y.angle; });
    std::vector<int> root(static_cast<std::size_t>(n));
    std::iota(root.begin(), root.end(), 0);
    std::vector<std::vector<int>> group(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) group[i] = found[i].mesh_triangles;
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
      if (group[i].size() == found[i].mesh_triangles.size()) {
        kept.push_back(std::move(found[i]));
        continue;
      }
      Facet f = std::move(merged[i]);
      // The steps: triangles of no facet next to the merged plane's, all
      // three corners within the gate of it.
      const Eigen::Vector3d normal = f.plane.fit.normal;
      const Eigen::Vector3d centre = f.plane.fit.centroid;
      std::vector<int> tris = group[i];
      for (int t : tris) owner[t] = -3;  // in this group
      for (std::size_t head = 0; head < tris.size(); ++head)
        for (const int k : graph.neighbours[tris[head]]) {
          if (k < 0 || owner[k] >= 0 || owner[k] == -3 ||
              !graph.usable(static_cast<std::size_t>(k)))
            continue;
          bool within = true;
          for (const int v : mesh.triangles[k])
            within = within && std::abs(normal.dot(mesh.vertices[v] - centre)) <= gate;
          if (!within) continue;
          owner[k] = -3;
          tris.push_back(k);
        }
      Facet with_steps = measured(tris);
      kept.push_back(with_steps.plane.problem.empty() ? std::move(with_steps) : std::move(f));
    }
    found = std::move(kept);
    for (std::size_t i = 0; i < found.size(); ++i)
      for (int t : found[i].mesh_triangles) owner[t] = static_cast<int>(i);
  };

  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const int seed = seeds[s];
    if ((s & 0xfff) == 0)
      progress.step("facets: growing",
                    static_cast<double>(done) / static_cast<double>(seeds.size()));
    if (label[seed] != kFree) continue;
    // The rest of the surface bends more than the tolerance at every
    // triangle: edges, creases, noise. No facet grows from there.
    if (bend[seed] > angle) break;
    const int region = static_cast<int>(facets.size());
    members.assign(1, seed);
    queue.assign(1, seed);
    label[seed] = region;
    RunningPlane plane;
    plane.add(graph.centres[seed], normals[seed], graph.areas[seed]);
    plane.refit(gate * 10);
    double next_refit = 3;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int t = queue[head];
      for (const int k : graph.neighbours[t]) {
        if (k < 0 || label[k] != kFree || !graph.usable(static_cast<std::size_t>(k))) continue;
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
            plane.fitted && bend[k] <= angle && normals[k].dot(plane.mean_normal) >= cos_twice;
        for (const int v : mesh.triangles[k])
          on_plane = on_plane &&
                     std::abs(plane.plane_normal.dot(mesh.vertices[v] - plane.centroid)) <= gate;
        if (!on_plane &&
            (normals[k].dot(plane.mean_normal) < cos_angle ||
             std::abs(plane.plane_normal.dot(graph.centres[k] - plane.centroid)) > gate))
          continue;
        label[k] = region;
        members.push_back(k);
        queue.push_back(k);
        plane.add(graph.centres[k], normals[k], graph.areas[k]);
        if (static_cast<double>(members.size()) >= next_refit) {
          // Ten times the gate across the region: its fitted tilt is then
          // known to a few tenths of the angle tolerance.
          plane.refit(gate * 10);
          next_refit = std::max(next_refit + 1, next_refit * options.refit_growth);
        }
      }
    }
    done += members.size();
    if (plane.weight < options.min_area_m2) {
      for (int t : members) label[t] = kDropped;
      continue;
    }
    Facet f = measured(members);
    if (!f.plane.problem.empty()) {
      for (int t : members) {
        label[t] = kDropped;
        rejected_in[t] = rejected_count;
      }
      ++rejected_count;
      continue;
    }
    facets.push_back(std::move(f));
  }
  // The second pass (plane_led_growing.h) over what the first left: led by
  // the distance of the points to a fitted plane against the stated point
  // precision, it finds the planes whose single triangles' normals scatter
  // beyond the tolerance (a face seen obliquely). A seed patch's points
  // must lie within two point sigmas RMS of their plane: half the
  // planarity test a facet passes at the end, so that a seed across a
  // crease or on a rough patch is refused before it grows.
  progress.step("facets: plane-led growing", 0.8);
  {
    std::vector<char> taken(graph.size(), 0);
    for (std::size_t t = 0; t < graph.size(); ++t) taken[t] = label[t] >= 0;
    PlaneLedOptions led;
    led.gate = gate;
    led.seed_rms = 2 * settings.point_sigma;
    led.seed_area = options.min_area_m2;
    led.refit_growth = options.refit_growth;
    for (auto& region : plane_led_regions(mesh, graph, taken, seeds, led)) {
      double area = 0;
      for (int t : region) area += graph.areas[t];
      if (area < options.min_area_m2) continue;
      Facet f = measured(region);
      if (!f.plane.problem.empty()) {
        for (int t : region) rejected_in[t] = rejected_count;
        ++rejected_count;
        continue;
      }
      for (int t : region) label[t] = static_cast<int>(facets.size());
      facets.push_back(std::move(f));
    }
  }
  merge_terraces(facets, label);
  // The rejected regions, and their area, as far as no facet took them.
  {
    std::vector<char> counted(static_cast<std::size_t>(rejected_count), 0);
    for (std::size_t t = 0; t < graph.size(); ++t)
      if (rejected_in[t] >= 0 && label[t] < 0) {
        out.rejected_area += graph.areas[t];
        counted[rejected_in[t]] = 1;
      }
    out.rejected_regions = static_cast<int>(std::count(counted.begin(), counted.end(), 1));
  }
  progress.step("facets: outlines", 0.95);
  std::stable_sort(facets.begin(), facets.end(),
                   [](const Facet& a, const Facet& b) { return a.area > b.area; });
  for (std::size_t i = 0; i < facets.size(); ++i) {
    Facet& f = facets[i];
    f.id = static_cast<int>(i) + 1;
    // Thinned to two point spacings: the outline keeps the facet's shape
    // to the resolution of the 3D image without its lattice staircase.
    const FacetOutline outline = facet_outline(mesh, f.mesh_triangles, 2.0 * edge);
    f.outline = outline.outer;
    f.holes = outline.holes;
    out.facet_area += f.area;
  }
  out.facets = std::move(facets);
  if (out.facets.empty())
    out.notes.push_back("no planar region of at least " + format_fixed(options.min_area_m2, 2) +
                        " m2 within " + format_fixed(options.angle_tolerance_deg, 0) + " deg and " +
                        format_fixed(options.planarity_in_sigmas, 1) + " point sigmas of a plane");
  progress.step("facets: done", 1.0);
  return out;
}

}  // namespace rockface::measure

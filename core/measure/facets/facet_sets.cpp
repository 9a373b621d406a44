#include "core/measure/facets/facet_sets.h"

#include <algorithm>
#include <cmath>

#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/measure/tolerances.h"

namespace rockface::measure {

namespace {

std::string percent(double share) {
  return format_fixed(100 * share, 0, " %");
}

// Two facets lie in one plane when the centroid of one is within
// kSameDiscontinuityM of the plane of the other, the better known (smaller
// sigma), plus what that plane's uncertainty makes of the lever arm between
// them (two of its sigmas): a wall seen in pieces is one plane although its
// pieces' planes, each a little tilted, part by centimetres over metres;
// a poorly known small facet cannot chain two planes of a set together.
// The planes are the groups of facets so linked.
int distinct_planes(const std::vector<const Facet*>& facets) {
  const std::size_t n = facets.size();
  std::vector<std::size_t> root(n);
  for (std::size_t i = 0; i < n; ++i) root[i] = i;
  auto find = [&](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  auto on_plane_of = [](const Facet& a, const Facet& b) {
    const Eigen::Vector3d d = b.centroid - a.centroid;
    return std::abs(a.plane.fit.normal.dot(d)) <=
           kSameDiscontinuityM + 2 * std::tan(a.plane.sigma) * d.norm();
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (facets[i]->plane.sigma <= facets[j]->plane.sigma ? on_plane_of(*facets[i], *facets[j])
                                                           : on_plane_of(*facets[j], *facets[i]))
        root[find(i)] = find(j);
  int planes = 0;
  for (std::size_t i = 0; i < n; ++i) planes += find(i) == i;
  return planes;
}

}  // namespace

FacetSets facet_sets(const FacetSearch& search, const ClusterOptions& clustering) {
  FacetSets out;
  out.clustering = clustering;
  const std::size_t n = search.facets.size();
  out.set_of.assign(n, -1);
  if (n == 0) return out;
  std::vector<Eigen::Vector3d> poles;
  std::vector<SetMember> members;
  for (const Facet& f : search.facets) {
    poles.push_back(f.plane.fit.normal);
    SetMember m;
    m.normal = f.plane.fit.normal;
    m.point = f.centroid;
    members.push_back(m);
  }
  const PoleClusters clusters = cluster_poles(poles, clustering);
  // Only the clusters that are families of parallel joints go on as sets.
  PoleClusters kept;
  kept.set_of.assign(n, -1);
  std::vector<std::vector<int>> kept_ids;
  for (std::size_t s = 0; s < clusters.sets.size(); ++s) {
    std::vector<int> ids;
    std::vector<const Facet*> in_set;
    double area = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (clusters.set_of[i] == static_cast<int>(s)) {
        ids.push_back(search.facets[i].id);
        in_set.push_back(&search.facets[i]);
        area += search.facets[i].area;
      }
    const int planes = distinct_planes(in_set);
    const double to_face = rad_to_deg(
        std::acos(std::min(1.0, std::abs(clusters.sets[s].mean.dot(search.surface_normal)))));
    const double share = search.mapped_area > 0 ? area / search.mapped_area : 0;
    std::string reason;
    if (to_face <= kFaceParallelDeg && share >= kFaceShare) {
      reason = "the excavation surface, not a joint set: within " +
               format_fixed(to_face, 1, " deg") +
               " of the mapped surface's mean plane and covering " + percent(share) + " of it";
    } else if (planes < 2) {
      reason = "one surface, not a set: its " + std::to_string(ids.size()) +
               (ids.size() == 1 ? " facet lies" : " facets lie") +
               " in one plane; a set needs parallel facets on two or more planes";
    }
    if (!reason.empty()) {
      out.not_sets.push_back({clusters.sets[s], ids, area, reason});
      continue;
    }
    const int index = static_cast<int>(kept.sets.size());
    for (std::size_t i = 0; i < n; ++i)
      if (clusters.set_of[i] == static_cast<int>(s)) kept.set_of[i] = index;
    kept.sets.push_back(clusters.sets[s]);
    kept_ids.push_back(ids);
    FacetSet fs;
    fs.facet_ids = ids;
    fs.planes = planes;
    fs.area = area;
    out.sets.push_back(fs);
  }
  const std::vector<JointSetSummary> summaries = summarise_joint_sets(members, kept);
  for (std::size_t s = 0; s < out.sets.size(); ++s) out.sets[s].summary = summaries[s];
  out.set_of = kept.set_of;
  return out;
}

}  // namespace rockface::measure

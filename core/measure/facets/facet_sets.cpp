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

// Two facets of a set lie in one plane when their centroids are within
// kSameDiscontinuityM of one plane through both, plus what the uncertainty
// of that plane's normal makes of the lever arm between them: a wall seen
// in pieces is one plane although its pieces' planes, each a little tilted,
// part by centimetres over metres. The normal is the better known of the
// set's Fisher mean (its 95 % cone, alpha95) and the better facet's own
// plane (two of its sigmas): the facets of a set are parallel, so with many
// members the mean is known far better than any one of them. The planes are
// the groups of facets so linked.
//
// Until stop 37 the normal was always the better facet's: two small facets
// of 3.5 to 5 deg sigma on different strips 5.5 m apart then had a
// tolerance of 0.7 m, the very spacing of the set, and chained its three
// planes into one. Whether they did turned on the last bits of the
// reconstruction, which differ with OpenCV's CPU dispatch (AVX-512, AVX2 or
// SSE kernels): the set was found on one machine and not on another.
int distinct_planes(const std::vector<const Facet*>& facets, const FisherStatistics& set) {
  const std::size_t n = facets.size();
  std::vector<std::size_t> root(n);
  for (std::size_t i = 0; i < n; ++i) root[i] = i;
  auto find = [&](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  // a is the better known of the two.
  auto one_plane = [&](const Facet& a, const Facet& b) {
    const double facet_cone = 2 * a.plane.sigma;
    const bool by_mean = set.alpha95 < facet_cone;
    const Eigen::Vector3d& normal = by_mean ? set.mean : a.plane.fit.normal;
    // Capped short of a right angle, where the tangent turns: a plane known
    // that poorly holds every facet.
    const double cone = std::min(by_mean ? set.alpha95 : facet_cone, deg_to_rad(89.0));
    const Eigen::Vector3d d = b.centroid - a.centroid;
    const double off = std::abs(normal.dot(d));
    const double along = std::sqrt(std::max(0.0, d.squaredNorm() - off * off));
    return off <= kSameDiscontinuityM + std::tan(cone) * along;
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (facets[i]->plane.sigma <= facets[j]->plane.sigma ? one_plane(*facets[i], *facets[j])
                                                           : one_plane(*facets[j], *facets[i]))
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
    const int planes = distinct_planes(in_set, clusters.sets[s]);
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

#include "core/measure/facets/facet_sets.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/common/units.h"
#include "core/measure/tolerances.h"

namespace rockface::measure {

namespace {

std::string percent(double share) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(0);
  s << 100 * share << " %";
  return s.str();
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
    std::vector<double> offsets;
    double area = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (clusters.set_of[i] == static_cast<int>(s)) {
        ids.push_back(search.facets[i].id);
        offsets.push_back(clusters.sets[s].mean.dot(search.facets[i].centroid));
        area += search.facets[i].area;
      }
    std::sort(offsets.begin(), offsets.end());
    int planes = 0;
    for (std::size_t i = 0; i < offsets.size(); ++i)
      if (i == 0 || offsets[i] - offsets[i - 1] > kSameDiscontinuityM) ++planes;
    const double to_face = rad_to_deg(
        std::acos(std::min(1.0, std::abs(clusters.sets[s].mean.dot(search.surface_normal)))));
    const double share = search.mapped_area > 0 ? area / search.mapped_area : 0;
    std::string reason;
    if (to_face <= kFaceParallelDeg && share >= kFaceShare) {
      std::ostringstream r;
      r.setf(std::ios::fixed);
      r.precision(1);
      r << "the excavation surface, not a joint set: within " << to_face
        << " deg of the mapped surface's mean plane and covering " << percent(share) << " of it";
      reason = r.str();
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

#pragma once
// Joint sets from facets, with the statistics of hand-picked planes
// (joint_sets.h): the facets' poles clustered on the sphere, each set's
// Fisher mean, K and alpha95, and its spacing from the parallel facets
// (their centroids along the set's mean normal).
//
// What a geologist accepts as a set, and what not: a set is a family of
// parallel discontinuities, so a cluster whose facets all lie in one plane
// (within kSameDiscontinuityM plus the uncertainty of the better known of
// the set's mean normal and the facets' own over the distance between them)
// is one surface and gives no set (a flat
// wall broken into pieces by the growing stays a wall); and a cluster
// parallel to the mapped surface that covers most of it (kFaceParallelDeg,
// kFaceShare) is the excavation surface, not a joint set. Both are listed
// with the reason, never dropped silently.
#include <string>
#include <vector>

#include "core/measure/facets/facets.h"
#include "core/measure/joint_sets.h"

namespace rockface::measure {

struct FacetSet {
  JointSetSummary summary;     // label S1, S2, ...; Fisher statistics; spacing
  std::vector<int> facet_ids;  // Facet::id of its members
  int planes = 0;              // distinct parallel planes among them
  double area = 0;             // m^2 of its facets
};

// A cluster of facets that is not a joint set, and why.
struct FacetCluster {
  FisherStatistics fisher;
  std::vector<int> facet_ids;
  double area = 0;
  std::string reason;
};

struct FacetSets {
  std::vector<FacetSet> sets;
  std::vector<FacetCluster> not_sets;
  std::vector<int> set_of;  // per facet (in FacetSearch::facets order): set index, or -1
  ClusterOptions clustering;
};

FacetSets facet_sets(const FacetSearch& search, const ClusterOptions& clustering = {});

}  // namespace rockface::measure

#pragma once
// Trace proposals (trace_proposals.h) in steps, for a screen that shows the
// first ones while the rest are measured. Its steps are propose_traces'
// own, and are implemented with it (trace_proposals.cpp).
#include <memory>
#include <string>
#include <vector>

#include "core/measure/proposals/trace_proposals.h"

namespace rockface::measure {

// The proposals in steps, for a screen that shows the first ones while
// the rest are measured (issue 45: the tablet's Find traces shows its first
// proposals within 2 s): the cues and their chains first (all of
// propose_traces but the measuring, the facets not needed), then the
// longest chains' proposals, then the whole result. The result is
// propose_traces', whatever was asked for before it.
class ProposalSearch {
 public:
  // The arguments as propose_traces takes them, less the facets; `picker`
  // and `view` must outlive the search (the mesh and photograph need not).
  // Throws as propose_traces does.
  ProposalSearch(const photogrammetry::SurfaceMesh& mesh, const MeshPicker& picker,
                 const PhotoView& view, const cv::Mat& photo, const ProposalOptions& options,
                 Progress& progress, const std::string& where);
  ~ProposalSearch();
  ProposalSearch(const ProposalSearch&) = delete;
  ProposalSearch& operator=(const ProposalSearch&) = delete;

  // The proposals of the `count` longest chains not yet measured, those at
  // or over the minimum confidence, by falling confidence: each is one of
  // finish()'s proposals, there named and linked to its facet (here
  // without a name or facet).
  std::vector<TraceProposal> longest(std::size_t count, Progress& progress);
  // How many chains longest() has not measured yet (0: finish() only ranks).
  std::size_t chains_left() const;
  // Every chain not yet measured, then the facets linked, the proposals
  // ranked and named: propose_traces' result. Once.
  ProposalResult finish(const std::vector<ProposalFacet>& facets, Progress& progress);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace rockface::measure

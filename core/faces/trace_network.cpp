#include "core/faces/trace_network.h"

#include <algorithm>

#include "core/faces/tolerances.h"
#include "core/faces/trace_network_phases.h"

namespace rockface::faces {

bool NetworkEdge::outline() const {
  int boundaries = 0;
  for (const auto& p : patches) boundaries += p.boundary ? 1 : 0;
  return boundaries == 1;
}

int TraceNetwork::next(int h) const {
  const int v = target(h);
  const int back = h ^ 1;
  const auto& around = around_[v].half_edges;
  const int deg = static_cast<int>(around.size());
  return around[(slot_[back] - 1 + deg) % deg];
}

namespace network_phases {

std::vector<std::vector<int>> segments_by_patch(const std::vector<Segment>& segments,
                                                size_t patch_count) {
  std::vector<std::vector<int>> by_patch(patch_count);
  for (size_t i = 0; i < segments.size(); ++i)
    by_patch[segments[i].patch].push_back(static_cast<int>(i));
  return by_patch;
}

}  // namespace network_phases

// The phases (core/faces/trace_network_phases.h) in order; each hands its
// result to the next, notes accumulate in the order the phases find them.
TraceNetwork TraceNetwork::build(const FreeSurface& surface, const std::vector<TraceInput>& traces,
                                 const NetworkOptions& options) {
  using namespace network_phases;
  TraceNetwork net;
  const double tol = options.snap_tolerance;
  const auto& patches = surface.patches();
  net.mapped_.assign(traces.size(), false);
  for (const TraceInput& t : traces) net.trace_points_.push_back(t.points);
  net.snap_tolerance_ = options.snap_tolerance;

  double scale = 0;
  for (const auto& p : patches)
    for (const auto& q : p.polygon) scale = std::max(scale, (q - patches[0].polygon[0]).norm());
  const double slack = kParamSlackRel * std::max(scale, 1.0);

  Stretches stretches = trace_stretches(surface, traces, tol, slack, net.mapped_, net.notes_);
  std::vector<Segment>& segs = stretches.segments;
  lay_onto_patch_edges(segs, surface, tol, slack);
  const auto by_patch = segments_by_patch(segs, patches.size());
  net.groups_ =
      merge_stretches(segs, stretches.groups, by_patch, traces, surface, options, net.notes_);
  const std::vector<Hit> hits = crossings_and_extensions(segs, by_patch, surface, tol, slack);
  Vertices vertices = merge_vertices(segs, hits, surface, tol, slack);
  net.vertices_ = std::move(vertices.points);
  net.edges_ = network_edges(segs, vertices.of_candidate, net.vertices_, surface, tol, net.groups_,
                             net.notes_);
  VertexOrder order = order_around_vertices(net.vertices_, net.edges_, surface);
  net.around_ = std::move(order.around);
  net.slot_ = std::move(order.slot);
  return net;
}

}  // namespace rockface::faces

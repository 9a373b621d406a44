// Incremental analysis of a trace map (issue 17): after one trace is moved
// or added, TraceSession recomputes only the regions whose inputs changed,
// and its blocks are those of the full analysis, bit for bit.
#include "core/faces/trace_session.h"

#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/progress.h"
#include "core/common/units.h"
#include "tests/support/random_slope.h"

namespace rockface::faces {
namespace {

using testing::kSnap;

void put(std::string& s, double x) {
  char t[40];
  std::snprintf(t, sizeof t, "%a ", x);
  s += t;
}

// Everything of a block that the report and the UI use, exactly.
std::string dump(const std::vector<TraceBlock>& blocks) {
  std::string s;
  for (const auto& b : blocks) {
    s += "block " + std::to_string(b.region) + " traces";
    for (int t : b.traces) s += " " + std::to_string(t);
    s += " codes";
    for (const auto& c : b.codes) s += " " + c;
    s += b.convex ? " convex" : " nonconvex";
    s += b.finite ? " finite " : " infinite ";
    const auto& f = b.finiteness;
    put(s, f.jp_margin);
    put(s, f.jp_ep_margin);
    put(s, f.finite.margin);
    put(s, f.removable.margin);
    s += f.removable.value ? "removable " : "keyed ";
    s += f.finite.marginal || f.removable.marginal ? "marginal " : "";
    put(s, b.uncertainty);
    for (const auto& p : b.planes)
      s += p.name + "/" + std::to_string(p.group) + "/" + std::to_string(p.patch) + "/" +
           std::to_string(p.scene_index) + " ";
    for (const auto& x : b.surface_polygon) {
      put(s, x.x());
      put(s, x.y());
      put(s, x.z());
    }
    if (b.polyhedron) {
      s += b.polyhedron->id() + " " + std::to_string(b.polyhedron->vertices().size()) + " ";
      for (const auto& x : b.polyhedron->vertices()) put(s, x.x() + x.y() + x.z());
    }
    if (b.analysis) {
      put(s, b.analysis->mass.volume);
      put(s, b.analysis->fos.value_or(-1));
    }
    for (const auto& n : b.notes) s += n + "; ";
    s += "\n";
  }
  return s;
}

TEST(TraceSession, EditedMapGivesTheFullAnalysisRecomputingOnlyTouchedBlocks) {
  const auto patches = testing::random_slope();
  const FreeSurface surface = FreeSurface::build(patches, kSnap);
  std::vector<TraceInput> traces = testing::random_traces(surface, 300, 11);
  const NetworkOptions net_options{kSnap, deg_to_rad(1.0)};
  TraceBlockOptions options;
  options.snap_tolerance = kSnap;
  options.orientation_uncertainty = deg_to_rad(1.0);
  NoProgress progress;
  auto full = [&](const std::vector<TraceInput>& t) {
    const auto net = TraceNetwork::build(surface, t, net_options);
    const auto loops = SurfaceLoops::find(net, surface);
    return dump(trace_blocks(surface, net, loops, options, progress));
  };

  TraceSession session(patches, net_options, options);
  EXPECT_EQ(dump(session.update(traces, progress)), full(traces));
  const int regions = session.recomputed();
  ASSERT_GT(regions, 20);  // a map with blocks to reuse
  int finite = 0;
  for (const auto& b : session.blocks()) finite += b.finite ? 1 : 0;
  ASSERT_GT(finite, 5);

  // Move one trace of a finite block: 0.2 m sideways on its patch (its
  // joint plane moves with it), for blocks at both ends and in the middle.
  std::vector<int> moved;
  for (const auto& b : session.blocks())
    if (b.finite) moved.push_back(b.traces.front());
  ASSERT_GE(moved.size(), 3u);
  for (int k : {moved.front(), moved[moved.size() / 2], moved.back()}) {
    SCOPED_TRACE("moved trace " + traces[k].id);
    const Eigen::Vector3d p0 = traces[k].points.front();
    const SurfacePatch* on = nullptr;
    for (const auto& P : surface.patches())
      if (std::abs(P.height(p0)) < 0.01 && P.contains(P.to2d(p0), 0.01)) on = &P;
    ASSERT_NE(on, nullptr);
    const Eigen::Vector3d along = (traces[k].points.back() - p0).normalized();
    const Eigen::Vector3d side = on->outward.cross(along).normalized();
    for (auto& p : traces[k].points) p += 0.2 * side;
    EXPECT_EQ(dump(session.update(traces, progress)), full(traces));
    // Only the loops around the trace change; the rest of the map is reused.
    EXPECT_GT(session.recomputed(), 0);
    EXPECT_GT(session.reused(), 0);
    EXPECT_LT(session.recomputed(), regions / 4);
  }

  // Add one (a trace of another random map, renamed).
  TraceInput extra = testing::random_traces(surface, 1, 99).front();
  extra.id = "T-new";
  traces.push_back(extra);
  EXPECT_EQ(dump(session.update(traces, progress)), full(traces));
  EXPECT_GT(session.reused(), 0);
  EXPECT_LT(session.recomputed(), regions / 4);

  // Unchanged traces: everything reused.
  session.update(traces, progress);
  EXPECT_EQ(session.recomputed(), 0);
}

}  // namespace
}  // namespace rockface::faces

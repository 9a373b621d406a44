// Blocks from the trace map on the free surface (issue 5): the scene's
// surface patches and traces become a trace network, its closed loops
// become blocks, and each block gets the same analysis as an explicit one.
// Reported in blocks[] with source "traces" and the loop's trace ids; what
// was left out of the map (and why) goes to the report's notes.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "core/analysis/block_dynamics.h"
#include "core/analysis/block_mechanics.h"
#include "core/analysis/block_report.h"
#include "core/analysis/scene_analysis.h"
#include "core/analysis/scene_effects.h"
#include "core/analysis/trace_map_input.h"
#include "core/common/error.h"
#include "core/common/parallel.h"
#include "core/common/units.h"
#include "core/faces/free_surface.h"
#include "core/faces/surface_loops.h"
#include "core/faces/trace_blocks.h"
#include "core/faces/trace_network.h"
#include "core/geometry/orientation.h"
#include "core/geometry/parallel_planes.h"
#include "core/geometry/tolerances.h"

namespace rockface::analysis {

namespace {

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string s;
  for (size_t i = 0; i < parts.size(); ++i) s += (i ? sep : "") + parts[i];
  return s;
}

// A joint plane of a trace block is known inside the map by its first trace
// (T7); the geologist knows it by its joint (J2). Where one joint gives the
// block a single plane, the report names the plane by the joint; two parallel
// discontinuities of one joint set keep their trace names to stay apart.
void rename_joint_planes(const faces::TraceBlock& b, const faces::TraceNetwork& net,
                         ReportBlock& rb) {
  std::map<std::string, std::string> display;
  std::map<std::string, int> planes_of_joint;
  for (const auto& p : b.planes)
    if (p.kind == blocks::PlaneKind::Joint && net.groups()[p.group].joint)
      ++planes_of_joint[net.groups()[p.group].joint->id];
  for (const auto& p : b.planes)
    if (p.kind == blocks::PlaneKind::Joint && net.groups()[p.group].joint) {
      const std::string& joint = net.groups()[p.group].joint->id;
      if (planes_of_joint[joint] == 1) display[p.name] = joint;
    }
  auto name = [&](const std::string& n) {
    const auto it = display.find(n);
    return it == display.end() ? n : it->second;
  };
  if (rb.mode)
    for (auto& n : rb.mode->planes) n = name(n);
  std::map<std::string, double> areas;
  for (const auto& [n, a] : rb.face_areas) areas[name(n)] += a;
  rb.face_areas = std::move(areas);
  if (rb.rotation)
    for (auto& c : rb.rotation->corners)
      for (auto& n : c.sliding_on) n = name(n);
  if (rb.dynamics) rename_dynamics_planes(*rb.dynamics, name);
}

// Why a block between two joints of one set is removable and marginal:
// it comes out by sliding between them (core/analysis/README.md, "Joints
// taken as parallel"), the joints named as the geologist knows them.
std::string slides_between_note(const faces::TraceBlock& b, const faces::TraceNetwork& net) {
  std::vector<Eigen::Vector3d> normals;
  std::vector<std::string> names;
  for (const auto& bp : b.polyhedron->planes()) {
    if (bp.kind != blocks::PlaneKind::Joint) continue;
    normals.push_back(bp.inward_normal());
    std::string name = bp.name;
    for (const auto& p : b.planes)
      if (p.kind == blocks::PlaneKind::Joint && p.name == bp.name && net.groups()[p.group].joint)
        name += " (joint " + net.groups()[p.group].joint->id + ")";
    names.push_back(name);
  }
  const double tolerance = std::max(b.uncertainty, geometry::kParallelRoundingRad);
  std::vector<std::string> pairs;
  for (const auto& [i, j] : geometry::opposite_pairs(normals, tolerance))
    pairs.push_back(names[i] + " and " + names[j]);
  return "removable only by sliding between " + join(pairs, ", ") +
         ", parallel within the orientation uncertainty (taken as parallel): marginal, as "
         "whether they open or close toward the free face is not measured";
}

ReportBlock report_block(const faces::TraceBlock& b, const AnalysisInput& scene,
                         const faces::TraceNetwork& net, const Eigen::Vector3d& datum,
                         const std::string& id, const kinematics::Effects& effects) {
  ReportBlock rb;
  rb.id = id;
  rb.source = "traces";
  for (int t : b.traces) rb.traces.push_back(scene.traces[t].id);
  rb.code = join(b.codes, "+");
  rb.convex = b.convex;
  std::vector<std::string> names;
  for (const auto& p : b.planes) {
    std::string n = p.name;
    if (p.kind == blocks::PlaneKind::FreeFace)
      n += " (surface patch)";
    else if (net.groups()[p.group].plane.source == faces::TracePlaneSource::Fitted)
      n += " (fitted)";
    else if (net.groups()[p.group].joint)
      n += " (joint " + net.groups()[p.group].joint->id + ")";
    names.push_back(n);
  }
  rb.notes.push_back("code digits: " + join(names, ", ") +
                     (b.codes.size() > 1 ? "; one code per convex piece" : ""));
  const auto& f = b.finiteness;
  rb.finite = f.finite.value;
  rb.removable = f.removable.value;
  rb.margin_deg = rad_to_deg(b.finite ? f.removable.margin : f.finite.margin);
  rb.marginal = f.removable.marginal || f.finite.marginal;
  if (b.polyhedron && b.analysis) {
    if (f.jp_between_parallel && f.removable.value) rb.notes.push_back(slides_between_note(b, net));
    fill_block_report(*b.polyhedron, *b.analysis, scene.analysis, rb);
    if (scene_wants_mechanics(scene) && b.finite)
      analyse_block_mechanics(*b.polyhedron, scene, b.strengths, effects, rb);
    if (scene_wants_dynamics(scene) && b.finite) {
      std::map<std::string, double> friction;  // degrees, from each plane's joint
      for (const auto& p : b.planes)
        if (p.kind == blocks::PlaneKind::Joint && net.groups()[p.group].joint &&
            net.groups()[p.group].joint->friction)
          friction[p.name] = rad_to_deg(*net.groups()[p.group].joint->friction);
      analyse_block_dynamics(*b.polyhedron, scene, effects, rb, nullptr, &friction);
    }
    rename_joint_planes(b, net, rb);
  } else {
    // An infinite block has no corners, and a finite one that is not one
    // polyhedron has no single list of them: its loop on the surface is what
    // is known.
    for (const auto& x : b.surface_polygon) rb.vertices.push_back(x + datum);
    rb.notes.push_back(b.finite ? "vertices: the loop on the free surface (the block is not one "
                                  "polyhedron)"
                                : "vertices: the loop on the free surface (the block has no "
                                  "finite corners)");
  }
  rb.notes.insert(rb.notes.end(), b.notes.begin(), b.notes.end());
  return rb;
}

}  // namespace

void analyse_trace_blocks(const AnalysisInput& scene, Report& report, Progress& progress) {
  if (scene.patches.empty()) {
    report.notes.push_back(
        "traces: the scene has no surface.patches; blocks from traces need the free surface");
    return;
  }
  const TraceMapInput map = trace_map_input(scene);
  const Eigen::Vector3d& datum = map.datum;
  const double tol = map.snap_tolerance;
  const double uncertainty = map.orientation_uncertainty;

  const kinematics::Effects effects = scene_effects(scene);
  faces::FreeSurface surface;
  faces::TraceNetwork net;
  try {
    surface = faces::FreeSurface::build(map.patches, tol);
    net = faces::TraceNetwork::build(surface, map.traces, {tol, uncertainty});
  } catch (const InputError& e) {
    throw InputError(scene.source + ": " + e.where(), e.reason());
  }
  for (const auto& n : net.notes()) report.notes.push_back("traces: " + n);
  const faces::SurfaceLoops loops = faces::SurfaceLoops::find(net, surface);

  faces::TraceBlockOptions options;
  options.snap_tolerance = tol;
  options.orientation_uncertainty = uncertainty;
  options.density = scene.density;
  options.effects = &effects;
  options.datum = datum;
  const auto blocks = faces::trace_blocks(surface, net, loops, options, progress);
  // TB1, TB2, ... skipping ids the scene already gives its own blocks.
  std::set<std::string> taken;
  for (const auto& b : scene.blocks) taken.insert(b.id);
  int number = 0;
  auto next_id = [&] {
    std::string id;
    do id = "TB" + std::to_string(++number);
    while (taken.count(id));
    return id;
  };
  // The blocks' reports (rotation and the remote-axis search are the costly
  // part) on all cores: each from its own block, in the blocks' order, the
  // same numbers as one after the other (core/common/parallel.h).
  std::vector<std::string> ids;
  for (size_t k = 0; k < blocks.size(); ++k) ids.push_back(next_id());
  std::vector<ReportBlock> reported(blocks.size());
  parallel_for(blocks.size(), [&](size_t k) {
    reported[k] = report_block(blocks[k], scene, net, datum, ids[k], effects);
  });
  for (auto& rb : reported) report.blocks.push_back(std::move(rb));
  if (blocks.empty())
    report.notes.push_back("traces: no closed loop of traces on the surface, so no block");
}

}  // namespace rockface::analysis

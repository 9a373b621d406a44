#include "core/analysis/analyse_rotation.h"

#include <string>

#include "core/analysis/preset_options.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/kinematics/remote_axis.h"
#include "core/kinematics/rotation_input.h"
#include "core/kinematics/rotation_space.h"

namespace rockface::analysis {

namespace {

// An axis farther than this (x block size) from the block moves every corner
// in parallel to within 1e-3 rad: a translation in all but name.
constexpr double kTranslationLikeAxisRel = 1e3;

ReportRotation rotation_report(const kinematics::RotationInput& in,
                               const kinematics::RotationAnalysis& a) {
  ReportRotation r;
  for (const auto& c : a.corners) {
    ReportCorner rc;
    rc.vertex = c.vertex;
    rc.rotatable = c.rotatable.value;
    rc.margin_deg = rad_to_deg(c.rotatable.margin);
    rc.marginal = c.rotatable.marginal;
    rc.rotation_edges = c.extreme_rays;
    for (const auto& s : c.sliding) {
      if (!s.feasible.value) continue;
      rc.sliding_on.push_back(in.planes[s.plane].name);
      for (int k : s.also_sliding) rc.sliding_on.push_back(in.planes[k].name);
    }
    r.corners.push_back(std::move(rc));
  }
  for (const auto& e : a.edges) {
    ReportEdge re;
    re.vertices = e.vertices;
    re.rotatable = e.rotatable.value;
    re.margin_deg = rad_to_deg(e.rotatable.margin);
    re.marginal = e.rotatable.marginal;
    r.edges.push_back(re);
  }
  return r;
}

}  // namespace

void analyse_block_rotation(const blocks::Polyhedron& block, const SceneAnalysis& analysis,
                            ReportBlock& out) {
  if (!analysis.rotation && !analysis.remote_axis) return;
  const kinematics::RotationInput in = kinematics::rotation_input(block);
  const double uncertainty = deg_to_rad(analysis.orientation_uncertainty_deg);
  // Corner and edge rotation are cheap (issue 17); the remote-axis search
  // uses them too, so they run whenever either is asked for.
  const kinematics::RotationAnalysis rotation = kinematics::analyse_rotation(in, uncertainty);
  if (analysis.rotation) out.rotation = rotation_report(in, rotation);
  if (analysis.remote_axis) {
    const int starts =
        analysis.remote_axis->starts.value_or(preset_options(analysis.preset).remote_axis_starts);
    if (starts < 1)
      throw InputError("analysis.remote_axis.starts",
                       std::to_string(starts) + " is not a positive number");
    // A block that can rotate about a corner or an edge (firmly: value and
    // not marginal) has an axis, so the search cannot change "found": it is
    // skipped and the axis reported is that one (through the corner, or
    // along the edge), with no starts and no hits.
    if (const auto firm = kinematics::firm_corner_or_edge_axis(rotation)) {
      ReportRemoteAxis ra;
      ra.found = true;
      ra.point = block.absolute_vertex(firm->vertex);
      ra.direction = firm->direction;
      out.remote_axis = ra;
      out.notes.push_back(firm->about_corner
                              ? "remote axis: not searched, the block rotates about corner " +
                                    std::to_string(firm->vertex)
                              : "remote axis: not searched, the block rotates about edge " +
                                    std::to_string(firm->edge[0]) + "-" +
                                    std::to_string(firm->edge[1]));
      return;
    }
    // Otherwise the search stops once an axis is found and the hit rate
    // has settled (kinematics/rotation_tolerances.h: +-0.15 at 95 %); a
    // search that finds nothing runs every start.
    const kinematics::RemoteAxisResult r =
        kinematics::search_remote_axis(in, {starts, analysis.remote_axis->seed, true});
    ReportRemoteAxis ra;
    ra.found = r.found;
    ra.point = r.point + block.datum();
    ra.direction = r.direction;
    ra.starts = r.starts;
    ra.hits = r.hits;
    ra.penalty = r.penalty;
    out.remote_axis = ra;
    if (r.found && r.distance > kTranslationLikeAxisRel * block.size()) {
      out.notes.push_back("remote axis " + format_significant(r.distance, 3, " m") +
                          " from the block: the motion found is essentially a translation");
    }
  }
}

}  // namespace rockface::analysis

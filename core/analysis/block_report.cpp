#include "core/analysis/block_report.h"

#include "core/analysis/analyse_rotation.h"

namespace rockface::analysis {

void fill_block_report(const blocks::Polyhedron& poly, const kinematics::BlockAnalysis& a,
                       const SceneAnalysis& options, ReportBlock& rb) {
  // Vertices in the polyhedron's order: rotation reports index them.
  for (int v = 0; v < static_cast<int>(poly.vertices().size()); ++v)
    rb.vertices.push_back(poly.absolute_vertex(v));
  rb.volume = a.mass.volume;
  rb.mass = a.mass.mass;
  rb.centroid = a.mass.centroid + poly.datum();
  rb.inertia = a.mass.inertia;
  rb.principal_moments = a.mass.principal_moments;
  for (int p = 0; p < static_cast<int>(poly.planes().size()); ++p)
    rb.face_areas[poly.planes()[p].name] += a.mass.plane_areas[p];
  rb.resultant_force = a.force;
  rb.resultant_moment = a.moment;
  if (a.mode) {
    ReportMode m;
    m.type = kinematics::mode_name(a.mode->type);
    for (int p : a.mode->planes) m.planes.push_back(poly.planes()[p].name);
    if (a.mode->type != kinematics::ModeType::None) m.direction = a.mode->direction;
    m.marginal = a.mode->marginal;
    rb.mode = m;
    rb.fos = a.fos;
  }
  rb.notes.insert(rb.notes.end(), a.notes.begin(), a.notes.end());
  // Rotation needs a finite block (its corners); cheap, so it always runs
  // when the scene asks for it.
  if (a.finiteness.finite.value) analyse_block_rotation(poly, options, rb);
}

}  // namespace rockface::analysis

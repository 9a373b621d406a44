#include "core/analysis/block_report.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/analyse_rotation.h"
#include "core/common/number_format.h"
#include "core/common/units.h"

namespace rockface::analysis {

namespace {

// The error a factor of safety carries. For sliding on one plane of dip a
// with friction phi, FoS = tan(phi) / tan(a); an error d in the plane's
// orientation moves it by FoS * 2 d / sin(2 a), never less than 2 d FoS
// (a = 45 deg), and a wedge's FoS moves by the same order. The scene states
// d (analysis.orientation_uncertainty_deg, 1 deg by default: +-3.5 % of the
// FoS). When the scene states no uncertainty (0), a numerical tolerance of
// 1e-6 stays: the FoS is trigonometry of the input angles and small solves
// (~1e-15 relative), but a FoS 1 - 1e-8 is 1 for any purpose (the report
// prints two decimals) and must not read as a confident "fails".
double fos_tolerance(double fos, double orientation_uncertainty_deg) {
  constexpr double kNumerical = 1e-6;
  return std::max(2 * deg_to_rad(std::max(orientation_uncertainty_deg, 0.0)) * fos, kNumerical);
}

}  // namespace

void fill_block_report(const blocks::Polyhedron& poly, const kinematics::BlockAnalysis& a,
                       const SceneAnalysis& options, ReportBlock& rb) {
  // Vertices in the polyhedron's order: rotation reports index them.
  for (int v = 0; v < static_cast<int>(poly.vertices().size()); ++v)
    rb.vertices.push_back(poly.absolute_vertex(v));
  for (const auto& face : poly.faces()) rb.faces.push_back(face.loop);
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
    if (a.fos && std::isfinite(*a.fos)) {
      const double tol = fos_tolerance(*a.fos, options.orientation_uncertainty_deg);
      if (std::abs(*a.fos - 1) <= tol) {
        rb.fos_marginal = true;
        rb.notes.push_back("FoS " + format_significant(*a.fos, 9) + " is within its tolerance (+-" +
                           format_significant(tol, 2) + ", from the orientation uncertainty of " +
                           format_significant(options.orientation_uncertainty_deg, 3, " deg") +
                           ") of 1: marginal, failure is not decided");
      }
    }
  }
  rb.notes.insert(rb.notes.end(), a.notes.begin(), a.notes.end());
  // Rotation needs a finite block (its corners); cheap, so it always runs
  // when the scene asks for it.
  if (a.finiteness.finite.value) analyse_block_rotation(poly, options, rb);
}

}  // namespace rockface::analysis

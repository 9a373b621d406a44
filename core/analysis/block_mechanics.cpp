#include "core/analysis/block_mechanics.h"

#include <cmath>
#include <memory>

#include "core/analysis/preset_options.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/mechanics/equilibrium_path.h"
#include "core/mechanics/joint_law.h"

namespace rockface::analysis {

namespace {

// A joint without effects.joint_law is as stiff as rock joints get in
// shear tests (1e11 Pa/m: 1 mm of closure under 100 MPa). Its elastic
// displacements are then small against the block, and its limit point is
// limit equilibrium's for sliding blocks (tests/integration/cli/joint_law_default_test).
constexpr double kDefaultCoulombStiffness = 1e11;

// The law of one joint face. Without effects.joint_law: Coulomb with the
// joint's own friction and cohesion, stiff and without dilation, as limit
// equilibrium has it; roughness (Barton-Bandis, Grasselli) only when the
// scene asks for it. With it: the scene's model; its Coulomb model takes the
// joint's own friction and cohesion too, phi_b where the joint gives none.
mechanics::JointLawParameters law_parameters(const AnalysisInput& scene,
                                             const kinematics::JointStrength& strength) {
  mechanics::JointLawParameters p;
  if (!scene.effects.joint_law) {
    p.model = mechanics::JointModel::Coulomb;
    p.normal_stiffness = kDefaultCoulombStiffness;
    p.dilation = false;
  } else {
    const SceneJointLaw& law = *scene.effects.joint_law;
    p.model = law.model == "coulomb"     ? mechanics::JointModel::Coulomb
              : law.model == "grasselli" ? mechanics::JointModel::Grasselli
                                         : mechanics::JointModel::BartonBandis;
    p.normal_stiffness = law.normal_stiffness;
    p.poisson_ratio = law.poisson_ratio;
    p.jrc = law.jrc;
    p.jcs = law.jcs;
    p.phi_b = deg_to_rad(law.phi_b);
    if (law.phi_r) p.phi_r = deg_to_rad(*law.phi_r);
    p.lab_length = law.lab_length;
    p.field_length = law.field_length;
    p.dilation = law.dilation;
  }
  p.friction = strength.friction.value_or(p.phi_b);
  p.cohesion = strength.cohesion;
  return p;
}

bool coulomb_law(const AnalysisInput& scene) {
  return !scene.effects.joint_law || scene.effects.joint_law->model == "coulomb";
}

std::string degrees_text(double radians) {
  // To 0.1 degree, without trailing zeros ("30 degrees", "12.5 degrees").
  return format_significant(std::round(rad_to_deg(radians) * 10) / 10, 6, " degrees");
}

ReportRigidMode rigid_mode(const mechanics::RigidMode& m) {
  ReportRigidMode r;
  r.translation = m.translation;
  r.rotation = m.rotation;
  r.kind = m.rotates ? "rotation" : "translation";
  return r;
}

}  // namespace

bool scene_wants_mechanics(const AnalysisInput& scene) {
  return scene.analysis.stability == "equilibrium_path";
}

void analyse_block_mechanics(const blocks::Polyhedron& poly, const AnalysisInput& scene,
                             const std::vector<kinematics::JointStrength>& strengths,
                             const kinematics::Effects& effects, ReportBlock& rb,
                             Progress* progress) {
  mechanics::MechanicsOptions o = preset_options(scene.analysis.preset).mechanics;
  if (scene.analysis.contact_density) o.contact_density = *scene.analysis.contact_density;
  if (scene.analysis.continuation_step) o.step = *scene.analysis.continuation_step;
  if (scene.analysis.max_steps) o.max_steps = *scene.analysis.max_steps;
  if (scene.analysis.lambda_max) o.lambda_max = *scene.analysis.lambda_max;
  o.progress = progress;
  std::vector<std::shared_ptr<const mechanics::JointLaw>> laws(poly.planes().size());
  std::string law_name = scene.effects.joint_law ? std::string() : kDefaultJointLawName;
  std::vector<std::string> without_friction;  // Coulomb planes that fell back to phi_b
  try {
    for (size_t i = 0; i < laws.size(); ++i) {
      const blocks::BlockPlane& bp = poly.planes()[i];
      if (bp.kind != blocks::PlaneKind::Joint) continue;
      const kinematics::JointStrength s =
          i < strengths.size() ? strengths[i] : kinematics::JointStrength{};
      if (coulomb_law(scene) && !s.friction) without_friction.push_back(bp.name);
      laws[i] = mechanics::make_joint_law(law_parameters(scene, s));
      if (scene.effects.joint_law) law_name = laws[i]->name();
    }
    const blocks::MassProperties mass = blocks::mass_properties(poly, scene.density);
    const mechanics::EquilibriumPath r =
        mechanics::equilibrium_path(poly, mass, effects, laws, scene.effects.insitu_stress, o);
    ReportMechanics m;
    m.fos_limit_point = r.fos_limit_point;
    m.outcome = mechanics::outcome_name(r.outcome);
    m.failure_mode = rigid_mode(r.static_mode);
    m.dynamic_mode = rigid_mode(r.dynamic_mode);
    m.stability = mechanics::stability_name(r.stability);
    m.flutter_lambda = r.flutter_lambda;
    for (const mechanics::PathPoint& pt : r.path) m.path.push_back({pt.lambda, pt.displacement});
    m.contacts = r.contacts;
    m.steps = r.steps;
    m.joint_law = law_name;
    rb.mechanics = m;
    for (const std::string& n : r.notes) rb.notes.push_back("mechanics: " + n);
    for (const std::string& n : without_friction)
      rb.notes.push_back("mechanics: plane " + n +
                         " has no friction angle: the Coulomb law takes " +
                         degrees_text(law_parameters(scene, {}).friction) +
                         " (phi_b), limit equilibrium gives it no strength");
  } catch (const InputError& e) {
    // Parameters are checked by the law as "joint_law.<field>" and by the
    // path as "analysis.<field>": name them in the scene.
    const std::string where =
        e.where().rfind("joint_law.", 0) == 0 ? "effects." + e.where() : e.where();
    throw InputError(scene.source + ": " + where, e.reason());
  }
}

}  // namespace rockface::analysis

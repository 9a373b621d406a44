#include "firmware-app/analysis/block_mechanics.h"

#include <memory>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/mechanics/equilibrium_path.h"
#include "core/mechanics/joint_law.h"

namespace rockface::app {

namespace {

mechanics::JointLawParameters law_parameters(const AnalysisInput& scene,
                                             const blocks::BlockPlane& plane) {
  const storage::SceneJointLaw law = scene.effects.joint_law.value_or(storage::SceneJointLaw{});
  mechanics::JointLawParameters p;
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
  // Coulomb: the joint's own friction and cohesion (as limit equilibrium
  // uses them), phi_b where the joint gives none.
  p.friction = p.phi_b;
  p.cohesion = 0;
  if (plane.index >= 0 && plane.index < static_cast<int>(scene.joints.size()) &&
      scene.joints[plane.index].id == plane.name) {
    const storage::SceneJoint& j = scene.joints[plane.index];
    if (j.friction) p.friction = deg_to_rad(*j.friction);
    p.cohesion = j.cohesion.value_or(0.0);
  }
  return p;
}

storage::ReportRigidMode rigid_mode(const mechanics::RigidMode& m) {
  storage::ReportRigidMode r;
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
                             const kinematics::Effects& effects, storage::ReportBlock& rb,
                             Progress* progress) {
  mechanics::MechanicsOptions o = mechanics::mechanics_options(scene.analysis.preset);
  if (scene.analysis.contact_density) o.contact_density = *scene.analysis.contact_density;
  if (scene.analysis.continuation_step) o.step = *scene.analysis.continuation_step;
  if (scene.analysis.max_steps) o.max_steps = *scene.analysis.max_steps;
  if (scene.analysis.lambda_max) o.lambda_max = *scene.analysis.lambda_max;
  o.progress = progress;
  std::vector<std::shared_ptr<const mechanics::JointLaw>> laws(poly.planes().size());
  std::string law_name;
  try {
    for (size_t i = 0; i < laws.size(); ++i) {
      const blocks::BlockPlane& bp = poly.planes()[i];
      if (bp.kind != blocks::PlaneKind::Joint) continue;
      laws[i] = mechanics::make_joint_law(law_parameters(scene, bp));
      law_name = laws[i]->name();
    }
    const blocks::MassProperties mass = blocks::mass_properties(poly, scene.density);
    const mechanics::EquilibriumPath r =
        mechanics::equilibrium_path(poly, mass, effects, laws, scene.effects.insitu_stress, o);
    storage::ReportMechanics m;
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
  } catch (const InputError& e) {
    // Parameters are checked by the law as "joint_law.<field>" and by the
    // path as "analysis.<field>": name them in the scene.
    const std::string where =
        e.where().rfind("joint_law.", 0) == 0 ? "effects." + e.where() : e.where();
    throw InputError(scene.source + ": " + where, e.reason());
  }
}

}  // namespace rockface::app

#include "core/analysis/block_dynamics.h"

#include <cmath>

#include "core/analysis/preset_options.h"
#include "core/blocks/mass_properties.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/mechanics/dynamics/block_dynamics.h"

namespace rockface::analysis {

namespace {

// Why the block's motion is simulated, and the divisor of its joints'
// friction (tan phi / divisor: the limit point's strength reduction);
// nothing when it does not fail.
struct Trigger {
  std::string why;
  double divisor = 1;
};

std::optional<Trigger> trigger(const ReportBlock& rb) {
  if (rb.mechanics) {
    if (rb.mechanics->outcome == "fails under its loads")
      return Trigger{"equilibrium path: no equilibrium under its loads", 1};
    if (rb.mechanics->fos_limit_point)
      return Trigger{"equilibrium path: from its limit point (strengths / " +
                         format_fixed(*rb.mechanics->fos_limit_point, 3) + ")",
                     *rb.mechanics->fos_limit_point};
  }
  if (rb.fos && *rb.fos < 1)
    return Trigger{"limit equilibrium: FoS " + format_fixed(*rb.fos, 2) + " < 1" +
                       (rb.fos_marginal ? " (marginal: within the FoS's tolerance of 1)" : ""),
                   1};
  return std::nullopt;
}

}  // namespace

bool scene_wants_dynamics(const AnalysisInput& scene) {
  return scene.analysis.dynamics.has_value();
}

void rename_dynamics_planes(ReportDynamics& d,
                            const std::function<std::string(const std::string&)>& name) {
  std::map<std::string, double> friction;
  for (const auto& [plane, deg] : d.friction_deg) friction[name(plane)] = deg;
  d.friction_deg = std::move(friction);
  for (ReportMotionEvent& e : d.events) {
    std::vector<std::string> renamed;
    for (const std::string& p : e.planes) renamed.push_back(name(p));
    // Whole names in the text ("slides on T1 and T2", "edge T1-F1").
    std::string text;
    std::string word;
    auto flush = [&] {
      text += word.empty() ? word : name(word);
      word.clear();
    };
    for (char c : e.what) {
      if (c == ' ' || c == '-' || c == ',' || c == '(' || c == ')') {
        flush();
        text += c;
      } else {
        word += c;
      }
    }
    flush();
    e.what = text;
    e.planes = renamed;
  }
}

void analyse_block_dynamics(const blocks::Polyhedron& poly, const AnalysisInput& scene,
                            const kinematics::Effects& effects, ReportBlock& rb, Progress* progress,
                            const std::map<std::string, double>* friction_deg) {
  const SceneDynamics& sd = *scene.analysis.dynamics;
  const std::optional<Trigger> why = trigger(rb);
  if (!why) {
    if (rb.removable)
      rb.notes.push_back(
          "dynamics after failure: block " + rb.id +
          " does not fail under its loads; its motion is not simulated" +
          (rb.fos_marginal ? " (marginal: its FoS is within its tolerance of 1)" : ""));
    return;
  }
  // Friction while sliding: each joint's (as limit equilibrium uses it),
  // else the joint law's residual or basic angle; cohesion is lost.
  std::vector<double> friction(poly.planes().size(), 0.0);
  ReportDynamics d;
  for (size_t i = 0; i < poly.planes().size(); ++i) {
    const blocks::BlockPlane& bp = poly.planes()[i];
    if (bp.kind != blocks::PlaneKind::Joint) continue;
    std::optional<double> phi;
    if (bp.index >= 0 && bp.index < static_cast<int>(scene.joints.size()) &&
        scene.joints[bp.index].id == bp.name)
      phi = scene.joints[bp.index].friction;
    else if (const SceneJoint* j = scene.joint(bp.name))
      phi = j->friction;
    if (!phi && friction_deg && friction_deg->count(bp.name)) phi = friction_deg->at(bp.name);
    if (!phi && scene.effects.joint_law)
      phi = scene.effects.joint_law->phi_r.value_or(scene.effects.joint_law->phi_b);
    if (!phi) {
      rb.notes.push_back("dynamics after failure: joint " + bp.name +
                         " has no friction angle (joints[].friction or effects.joint_law): "
                         "the motion of block " +
                         rb.id + " is not simulated");
      return;
    }
    const double reduced = rad_to_deg(std::atan(std::tan(deg_to_rad(*phi)) / why->divisor));
    friction[i] = reduced;
    d.friction_deg[bp.name] = reduced;
  }
  mechanics::DynamicsOptions o = preset_options(scene.analysis.preset).dynamics;
  o.duration = sd.duration_s;
  o.sample = sd.sample_s;
  if (sd.abs_tol) o.abs_tol = *sd.abs_tol;
  if (sd.rel_tol) o.rel_tol = *sd.rel_tol;
  if (sd.max_step_s) o.max_step = *sd.max_step_s;
  o.progress = progress;
  const Eigen::Vector3d datum = poly.datum();
  if (sd.floor) {
    mechanics::DynamicsFloor f;
    f.point = sd.floor->point - datum;
    f.normal = geometry::plane_normal_deg(sd.floor->dip, sd.floor->dipdir);
    o.floor = f;
    d.floor = std::make_pair(sd.floor->point, f.normal);
  }
  mechanics::BlockDynamics r;
  try {
    const blocks::MassProperties mass = blocks::mass_properties(poly, scene.density);
    r = mechanics::simulate_block_motion(poly, mass, effects, friction, o);
  } catch (const InputError& e) {
    throw InputError(scene.source + ": " + e.where(), e.reason());
  }
  d.trigger = why->why;
  d.strength_divisor = why->divisor;
  d.outcome = r.outcome;
  d.stopped = r.stopped;
  for (const mechanics::MotionEvent& e : r.events)
    d.events.push_back({e.time, e.kind, e.what, e.planes});
  for (const mechanics::MotionSample& s : r.samples) {
    ReportMotionSample m;
    m.time_s = s.time;
    m.position = s.centroid + datum;
    m.orientation =
        Eigen::Vector4d(s.orientation.w(), s.orientation.x(), s.orientation.y(), s.orientation.z());
    m.velocity = s.velocity;
    m.angular_velocity = s.angular_velocity;
    m.kinetic_translational = s.kinetic_translational;
    m.kinetic_rotational = s.kinetic_rotational;
    m.work = s.work;
    m.dissipated = s.dissipated;
    d.path.push_back(m);
  }
  if (r.landing) {
    ReportLanding l;
    l.time_s = r.landing->time;
    l.point = r.landing->point + datum;
    l.centroid = r.landing->centroid + datum;
    l.speed = r.landing->speed;
    l.corner_speed = r.landing->corner_speed;
    l.angular_speed = r.landing->angular_speed;
    l.kinetic_translational = r.landing->kinetic_translational;
    l.kinetic_rotational = r.landing->kinetic_rotational;
    l.distance_from_start = r.landing->distance_from_start;
    l.distance_from_face = r.landing->distance_from_face;
    l.face = r.landing->face;
    d.landing = l;
  }
  d.duration_s = o.duration;
  d.sample_s = o.sample;
  d.end_time_s = r.end_time;
  d.abs_tol = o.abs_tol;
  d.rel_tol = o.rel_tol;
  d.max_step_s = o.max_step;
  d.steps = r.steps;
  d.rejected_steps = r.rejected_steps;
  d.evaluations = r.evaluations;
  d.drift_before_m = r.drift_before;
  d.drift_after_m = r.drift_after;
  d.drift_bound_m = r.drift_bound;
  d.notes = r.notes;
  d.notes.push_back("cohesion is taken as lost once the block fails; friction only while sliding");
  rb.dynamics = std::move(d);
}

}  // namespace rockface::analysis

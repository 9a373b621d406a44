#include "core/mechanics/dynamics/block_dynamics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include <boost/numeric/odeint.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/mechanics/block_loads.h"
#include "core/mechanics/dynamics/block_dynamics_phases.h"
#include "core/mechanics/dynamics/block_motion.h"
#include "core/mechanics/dynamics/contact_mode.h"
#include "core/mechanics/dynamics/tolerances.h"

namespace rockface::mechanics {

namespace {

namespace odeint = boost::numeric::odeint;

using dynamics_phases::pack;
using dynamics_phases::Physical;
using dynamics_phases::Scales;
using dynamics_phases::State;
using dynamics_phases::unpack;

class MotionSystem {
 public:
  MotionSystem(const BlockMotion& motion, const Scales& k, int& evaluations)
      : motion_(motion), k_(k), evaluations_(evaluations) {}
  void operator()(const State& s, State& ds, double /*tau*/) const {
    ++evaluations_;
    const Physical p = unpack(s, k_);
    const ContactSolution sol = motion_.solve(p.pose, p.velocity);
    const double power = motion_.applied(p.pose, p.velocity).power;
    // q' = 1/2 (0, w) q for w in global axes; d/dtau = T d/dt.
    const Eigen::Quaterniond qs(s[3], s[4], s[5], s[6]);
    const Eigen::Quaterniond wq(0, p.velocity.w(0), p.velocity.w(1), p.velocity.w(2));
    const Eigen::Quaterniond dq = wq * qs;
    const double t = k_.time;
    const Eigen::Vector3d du = p.velocity.v * t / k_.length;
    const Eigen::Vector3d dv = sol.acceleration * t / k_.speed;
    const Eigen::Vector3d dw = sol.angular_acceleration * t * t;
    ds = {du(0),
          du(1),
          du(2),
          0.5 * t * dq.w(),
          0.5 * t * dq.x(),
          0.5 * t * dq.y(),
          0.5 * t * dq.z(),
          dv(0),
          dv(1),
          dv(2),
          dw(0),
          dw(1),
          dw(2),
          power * t / k_.energy};
  }

 private:
  const BlockMotion& motion_;
  Scales k_;
  int& evaluations_;
};

double lowest_height(const BlockMotion& m, const BlockPose& pose, const DynamicsFloor& floor,
                     int* vertex = nullptr) {
  double low = INFINITY;
  for (int v = 0; v < static_cast<int>(m.geometry().arms().size()); ++v) {
    const double h = floor.normal.dot(m.geometry().vertex(pose, v) - floor.point);
    if (h < low) {
      low = h;
      if (vertex) *vertex = v;
    }
  }
  return low;
}

double deepest_gap(const BlockMotion& m, const BlockPose& pose) {
  double low = INFINITY;
  for (const JointContact& c : m.geometry().contacts(pose, 0.0)) low = std::min(low, c.gap);
  return low;
}

MotionSample sample_at(const BlockMotion& m, const Physical& p, double time) {
  MotionSample s;
  s.time = time;
  s.centroid = m.centroid() + p.pose.u;
  s.orientation = p.pose.q;
  s.velocity = p.velocity.v;
  s.angular_velocity = p.velocity.w;
  s.kinetic_translational = m.kinetic_translational(p.velocity);
  s.kinetic_rotational = m.kinetic_rotational(p.pose, p.velocity);
  s.work = p.work;
  s.dissipated = p.work - s.kinetic_translational - s.kinetic_rotational;
  return s;
}

void check_options(const DynamicsOptions& o) {
  auto positive = [](double v, const char* field) {
    if (!(v > 0) || !std::isfinite(v))
      throw InputError(std::string("analysis.dynamics.") + field, "must be a positive number");
  };
  positive(o.duration, "duration_s");
  positive(o.sample, "sample_s");
  positive(o.abs_tol, "abs_tol");
  positive(o.rel_tol, "rel_tol");
  positive(o.max_step, "max_step_s");
  if (o.duration / o.sample > 100000)
    throw InputError("analysis.dynamics.sample_s", "more than 100000 samples over the duration");
  if (o.duration / o.max_step > kMaxDynamicsStepsAsked)
    throw InputError("analysis.dynamics.max_step_s",
                     format_significant(o.max_step, 6) + " s over duration_s " +
                         format_significant(o.duration, 6) + " s is " +
                         format_significant(o.duration / o.max_step, 6) + " steps; at most " +
                         format_significant(kMaxDynamicsStepsAsked, 6) +
                         " are integrated (a longer max_step_s or a shorter duration_s)");
  if (!(o.max_evaluations > 0) || !(o.max_events > 0))
    throw InputError("analysis.dynamics", "the step budget and the event limit must be positive");
}

}  // namespace

DynamicsOptions dynamics_options(Preset preset) {
  DynamicsOptions o;
  switch (preset) {
    case Preset::fast:
      o.abs_tol = 1e-8;
      o.rel_tol = 1e-6;
      o.max_step = 0.02;
      break;
    case Preset::standard:
      o.abs_tol = 1e-10;
      o.rel_tol = 1e-8;
      o.max_step = 0.01;
      break;
    case Preset::precise:
      o.abs_tol = 1e-12;
      o.rel_tol = 1e-10;
      o.max_step = 0.005;
      break;
  }
  return o;
}

namespace dynamics_phases {

Physical unpack(const State& s, const Scales& k) {
  Physical p;
  p.pose.u = Eigen::Vector3d(s[0], s[1], s[2]) * k.length;
  p.pose.q = Eigen::Quaterniond(s[3], s[4], s[5], s[6]).normalized();
  p.velocity.v = Eigen::Vector3d(s[7], s[8], s[9]) * k.speed;
  p.velocity.w = Eigen::Vector3d(s[10], s[11], s[12]) / k.time;
  p.work = s[13] * k.energy;
  return p;
}

State pack(const Physical& p, const Scales& k) {
  State s;
  const Eigen::Vector3d u = p.pose.u / k.length, v = p.velocity.v / k.speed,
                        w = p.velocity.w * k.time;
  const Eigen::Quaterniond q = p.pose.q;
  s = {u(0), u(1), u(2), q.w(), q.x(), q.y(), q.z(),
       v(0), v(1), v(2), w(0),  w(1),  w(2),  p.work / k.energy};
  return s;
}

Scales block_scales(const BlockMotion& motion) {
  Scales k;
  k.length = motion.length();
  k.time = std::sqrt(k.length / motion.gravity());
  k.speed = k.length / k.time;
  k.energy = motion.load_scale() * k.length;
  return k;
}

std::optional<DynamicsFloor> usable_floor(const std::optional<DynamicsFloor>& given,
                                          const BlockMotion& motion, const Scales& k,
                                          std::vector<std::string>& notes) {
  std::optional<DynamicsFloor> floor = given;
  if (floor) {
    floor->normal.normalize();
    if (lowest_height(motion, BlockPose{}, *floor) < -kContactGapRel * k.length) {
      notes.push_back("the floor lies above the block's lowest corner: no landing computed");
      floor.reset();
    }
  }
  return floor;
}

void record_event(std::vector<MotionEvent>& events, double t, const std::string& kind,
                  const std::string& what, std::vector<std::string> planes) {
  MotionEvent e;
  e.time = t;
  e.kind = kind;
  e.what = what;
  e.planes = std::move(planes);
  events.push_back(std::move(e));
}

void record_mode_change(std::vector<MotionEvent>& events, const ContactMode& from,
                        const ContactMode& to, double t) {
  for (const std::string& p : from.planes)
    if (std::find(to.planes.begin(), to.planes.end(), p) == to.planes.end())
      record_event(events, t, "leaves", "leaves " + p, {p});
  const char* kind = to.kind == ModeKind::FreeFall  ? "free_fall"
                     : to.kind == ModeKind::Sliding ? "slides"
                     : to.kind == ModeKind::Rest    ? "rest"
                                                    : "rotates";
  if (from.describe() != to.describe() || from.kind != to.kind)
    record_event(events, t, kind, to.describe(), to.planes);
}

EventTime locate_event(const State& x_end, double step, const std::function<State(double)>& advance,
                       const std::function<bool(const State&)>& happened) {
  double lo = 0, hi = step;
  State at_hi = x_end;
  while (hi - lo > kEventTimeRel) {
    const double mid = 0.5 * (lo + hi);
    const State xm = advance(mid);
    if (happened(xm)) {
      hi = mid;
      at_hi = xm;
    } else {
      lo = mid;
    }
  }
  return {at_hi, hi};
}

double flight_end(double tau, double tau_end_contact, const Scales& k) {
  return std::max(tau_end_contact, std::min(tau + (kMaxFlightSeconds / k.time),
                                            tau_end_contact + kMaxFlightSeconds / k.time));
}

void project_step(const BlockMotion& motion, const Scales& k, double tau, State& x,
                  BlockDynamics& out) {
  const double penetration = -kContactGapRel * k.length;
  Physical p = unpack(x, k);
  const BlockMotion::Projection pr = motion.project(p.pose, p.velocity);
  out.drift_before = std::max(out.drift_before, pr.drift_before);
  out.drift_after = std::max(out.drift_after, pr.drift_after);
  if (pr.impact_speed > 1e-4 * k.speed) {
    std::vector<std::string> hit;
    for (const JointContact& c : motion.geometry().contacts(p.pose, -penetration))
      hit.push_back(motion.geometry().surfaces()[c.surface].name);
    std::sort(hit.begin(), hit.end());
    hit.erase(std::unique(hit.begin(), hit.end()), hit.end());
    std::string names;
    for (const auto& n : hit) names += (names.empty() ? "" : " and ") + n;
    record_event(out.events, tau * k.time, "hits",
                 "hits " + names + " at " + format_fixed(pr.impact_speed, 2, " m/s"), hit);
  }
  x = pack(p, k);
}

Stepper::Stepper(const BlockMotion& motion, const Scales& k, int& evaluations,
                 const DynamicsOptions& options)
    : system_(MotionSystem(motion, k, evaluations)),
      abs_tol_(options.abs_tol),
      rel_tol_(options.rel_tol) {}

bool Stepper::try_step(State& x, double& tau, double& h) const {
  // A fresh stepper each time: the state may have been projected since the
  // last step, so no stale first derivative is kept.
  auto controlled =
      odeint::make_controlled(abs_tol_, rel_tol_, odeint::runge_kutta_dopri5<State>());
  return controlled.try_step(system_, x, tau, h) != odeint::fail;
}

State Stepper::advance(const State& x0, double t0, double h) const {
  odeint::runge_kutta_dopri5<State> plain;
  State dx0, x1, dx1;
  system_(x0, dx0, t0);
  plain.do_step(system_, x0, dx0, t0, x1, dx1, h);
  return x1;
}

ContactMode mode_of(const BlockMotion& motion, const Scales& k, const State& s) {
  const Physical p = unpack(s, k);
  return contact_mode(motion, p.pose, p.velocity, motion.solve(p.pose, p.velocity));
}

Integration start_integration(const BlockMotion& motion, const Scales& k,
                              const DynamicsOptions& options, BlockDynamics& out) {
  Integration in;
  const Physical now;
  in.x = pack(now, k);
  in.tau_end_contact = options.duration / k.time;
  in.tau_end = in.tau_end_contact;
  in.tau_sample = options.sample / k.time;
  in.tau_max_step = options.max_step / k.time;
  in.dt = std::min(in.tau_max_step, 1e-3);
  in.mode = contact_mode(motion, now.pose, now.velocity, motion.solve(now.pose, now.velocity));
  if (in.mode.kind == ModeKind::FreeFall)
    record_event(out.events, 0.0, "free_fall", "free fall (no joint holds it)", {});
  else
    record_mode_change(out.events, ContactMode{}, in.mode, 0.0);
  return in;
}

std::optional<std::string> budget_spent(const Integration& in, const Scales& k,
                                        const DynamicsOptions& options, const BlockDynamics& out) {
  const std::string at = " at t = " + format_significant(in.tau * k.time, 3, " s");
  if (out.evaluations >= options.max_evaluations)
    return "the step budget (" + std::to_string(options.max_evaluations) +
           " evaluations of the equations of motion) ran out" + at +
           ": the motion needs steps too short to follow it to the end";
  if (static_cast<int>(out.events.size()) >= options.max_events)
    return "the event limit (" + std::to_string(options.max_events) + " events) was reached" + at +
           ": the contacts change faster than the motion can be followed";
  return std::nullopt;
}

void sample_up_to(const BlockMotion& motion, const Scales& k, Integration& in, BlockDynamics& out) {
  // A sample due now (within rounding of k x sample) is the state itself.
  while (in.next_sample <= in.tau + 1e-9 * in.tau_sample) {
    out.samples.push_back(sample_at(motion, unpack(in.x, k), in.next_sample * k.time));
    in.next_sample += in.tau_sample;
  }
}

void sample_within_step(const BlockMotion& motion, const Scales& k, const Stepper& sampler,
                        Integration& in, BlockDynamics& out) {
  // The samples the step passed over: one step of the same method from the
  // step's start to each, so the step itself stays as the error control
  // and the events chose it (issue 40: sampling never changes the motion).
  // A sample at the step's end is left to sample_up_to, after projection.
  while (in.next_sample < in.tau - 1e-9 * in.tau_sample) {
    const State at = sampler.advance(in.x0, in.t0, in.next_sample - in.t0);
    out.samples.push_back(sample_at(motion, unpack(at, k), in.next_sample * k.time));
    in.next_sample += in.tau_sample;
  }
}

bool controlled_step(const Stepper& stepper, const Scales& k, Integration& in, BlockDynamics& out) {
  // The step is the error control's, at most max_step, and ends at the end
  // of the duration; never cut to a sample time (sample_within_step).
  double h = std::min({in.dt, in.tau_max_step, in.tau_end - in.tau});
  in.x0 = in.x;
  in.t0 = in.tau;
  if (!stepper.try_step(in.x, in.tau, h)) {
    ++out.rejected_steps;
    in.dt = h;
    if (h < kStepFloorRel)
      in.stopped =
          "the step size fell below the step floor (" + format_significant(kStepFloorRel, 2) +
          " of the block's free-fall time) at t = " + format_significant(in.t0 * k.time, 3, " s") +
          ": the error control (abs_tol, rel_tol) cannot be met within the rounding of "
          "this motion";
    return false;
  }
  ++out.steps;
  in.dt = h;
  return true;
}

ContactMode cut_at_event(const BlockMotion& motion, const Scales& k,
                         const std::optional<DynamicsFloor>& floor, const Stepper& stepper,
                         Integration& in) {
  const double penetration = -kContactGapRel * k.length;
  auto impact_at = [&](const State& s) {
    return deepest_gap(motion, unpack(s, k).pose) < penetration;
  };
  auto lands_at = [&](const State& s) {
    return floor && lowest_height(motion, unpack(s, k).pose, *floor) < 0;
  };
  ContactMode new_mode = mode_of(motion, k, in.x);
  const bool impact = impact_at(in.x), lands = lands_at(in.x);
  if (impact || lands || new_mode != in.mode) {
    const State x0 = in.x0;
    const double t0 = in.t0;
    const EventTime event = locate_event(
        in.x, in.tau - t0, [&](double after) { return stepper.advance(x0, t0, after); },
        [&](const State& s) {
          return impact_at(s) || lands_at(s) || mode_of(motion, k, s) != in.mode;
        });
    in.x = event.state;
    in.tau = t0 + event.after;
    new_mode = mode_of(motion, k, in.x);
    if (lands_at(in.x)) in.landed = true;
  }
  return new_mode;
}

void finish_step(const BlockMotion& motion, const Scales& k,
                 const std::optional<DynamicsFloor>& floor, ContactMode new_mode, Integration& in,
                 BlockDynamics& out) {
  const double q_error =
      std::abs(Eigen::Quaterniond(in.x[3], in.x[4], in.x[5], in.x[6]).norm() - 1.0);
  out.quaternion_error = std::max(out.quaternion_error, q_error);
  if (!in.landed) {
    project_step(motion, k, in.tau, in.x, out);
    new_mode = mode_of(motion, k, in.x);
  }
  if (new_mode != in.mode) {
    record_mode_change(out.events, in.mode, new_mode, in.tau * k.time);
    in.mode = new_mode;
  }
  // Free flight goes on to the floor beyond the duration.
  if (in.mode.kind == ModeKind::FreeFall && floor)
    in.tau_end = flight_end(in.tau, in.tau_end_contact, k);
}

Integration integrate(const BlockMotion& motion, const Scales& k,
                      const std::optional<DynamicsFloor>& floor, const DynamicsOptions& options,
                      BlockDynamics& out) {
  const Stepper stepper(motion, k, out.evaluations, options);
  // The samples' evaluations are not the integration's: they are counted
  // apart, so that the step budget does not depend on sampling either.
  int sample_evaluations = 0;
  const Stepper sampler(motion, k, sample_evaluations, options);
  Integration in = start_integration(motion, k, options, out);
  while (in.tau < in.tau_end - 1e-12 * in.tau_end && !in.landed) {
    if (auto spent = budget_spent(in, k, options, out)) {
      in.stopped = *spent;
      break;
    }
    if (options.progress && (out.steps % 64) == 0)
      options.progress->step("dynamics", std::min(1.0, in.tau / in.tau_end));
    sample_up_to(motion, k, in, out);
    if (!controlled_step(stepper, k, in, out)) {
      if (!in.stopped.empty()) break;  // the step floor
      continue;
    }
    // Events inside the step: a contact closing into the rock, the floor,
    // a change of the contact mode. The earliest is found by bisection.
    const ContactMode new_mode = cut_at_event(motion, k, floor, stepper, in);
    sample_within_step(motion, k, sampler, in, out);
    // Projection: drift back onto the loaded contacts; a closing contact
    // stops (plastic impact).
    finish_step(motion, k, floor, new_mode, in, out);
  }
  return in;
}

Landing landing_of(const blocks::Polyhedron& block, const BlockMotion& motion, const Physical& last,
                   const DynamicsFloor& floor, double end_time) {
  Landing l;
  int v = 0;
  lowest_height(motion, last.pose, floor, &v);
  l.time = end_time;
  l.point = motion.geometry().vertex(last.pose, v);
  l.centroid = motion.centroid() + last.pose.u;
  l.speed = last.velocity.v.norm();
  l.corner_speed = (last.velocity.v + last.velocity.w.cross(l.point - l.centroid)).norm();
  l.angular_speed = last.velocity.w.norm();
  l.kinetic_translational = motion.kinetic_translational(last.velocity);
  l.kinetic_rotational = motion.kinetic_rotational(last.pose, last.velocity);
  Eigen::Vector3d d = last.pose.u;
  d -= d.dot(Eigen::Vector3d::UnitZ()) * Eigen::Vector3d::UnitZ();
  l.distance_from_start = d.norm();
  // "The face": of the block's steep free faces (dip > 10 degrees), the
  // one it moved out through (the largest horizontal part of its outward
  // normal along the centroid's horizontal travel).
  double best = -INFINITY;
  for (const blocks::BlockPlane& bp : block.planes()) {
    if (bp.kind != blocks::PlaneKind::FreeFace) continue;
    const Eigen::Vector3d n = bp.outward_normal();
    const double horizontal = std::hypot(n(0), n(1));
    if (horizontal <= std::sin(10.0 * M_PI / 180.0)) continue;
    const double along =
        d.norm() > 0 ? Eigen::Vector3d(n(0), n(1), 0).dot(d) / (horizontal * d.norm()) : 0.0;
    if (along <= best) continue;
    best = along;
    l.face = bp.name;
    // Horizontal distance of the landing centroid in front of the plane.
    const int plane = static_cast<int>(&bp - block.planes().data());
    const Eigen::Vector3d& on_plane =
        block.vertices()[block.faces()[block.faces_on_plane(plane)[0]].loop[0]];
    l.distance_from_face = n.dot(l.centroid - on_plane) / horizontal;
    Eigen::Vector3d foot = on_plane;
    for (const int f : block.faces_on_plane(plane))
      for (const int v : block.faces()[f].loop)
        if (block.vertices()[v].z() < foot.z()) foot = block.vertices()[v];
    const Eigen::Vector2d out(n(0) / horizontal, n(1) / horizontal);
    l.distance_from_foot = out.dot((l.centroid - foot).head<2>());
    l.drop_below_foot = foot.z() - l.point.z();
  }
  return l;
}

std::string landing_text(const Landing& l) {
  if (l.distance_from_foot && l.drop_below_foot) {
    const double out = *l.distance_from_foot, drop = *l.drop_below_foot;
    return "lands " + format_fixed(std::abs(out), 1, " m") + (out >= 0 ? " out from" : " behind") +
           " the foot of the face " + l.face + ", " + format_fixed(std::abs(drop), 1, " m") +
           (drop >= 0 ? " below" : " above") + " it, at " + format_fixed(l.speed, 1, " m/s");
  }
  return "lands " +
         format_fixed(l.distance_from_face ? *l.distance_from_face : l.distance_from_start, 1,
                      " m") +
         " from " + (l.distance_from_face ? "the face " + l.face : "where it started") + " at " +
         format_fixed(l.speed, 1, " m/s");
}

std::string outcome_of(bool landed, const ContactMode& mode, FloorGiven floor) {
  if (landed) return "lands";
  if (mode.kind == ModeKind::Rest) return "at rest";
  if (mode.kind == ModeKind::FreeFall) switch (floor) {
      case FloorGiven::usable:
        return "in free flight when the time ran out";
      case FloorGiven::above_block:
        return "in free flight (the floor given lies above the block: no landing computed)";
      case FloorGiven::none:
        return "in free flight (no floor given)";
    }
  return "moving at the end";
}

}  // namespace dynamics_phases

BlockDynamics simulate_block_motion(const blocks::Polyhedron& block,
                                    const blocks::MassProperties& mass,
                                    const kinematics::Effects& effects,
                                    const std::vector<double>& friction_deg,
                                    const DynamicsOptions& options) {
  using namespace dynamics_phases;
  check_options(options);
  BlockDynamics out;
  BlockLoads loads = block_loads(block, mass, effects);
  out.effects_used = loads.effects_used;
  out.notes = loads.notes;
  out.mass = mass.mass;
  out.friction_deg = friction_deg;
  const BlockMotion motion(block, mass, std::move(loads), friction_deg);
  const Scales k = block_scales(motion);
  out.drift_bound = kDriftBoundRel * k.length;
  const std::optional<DynamicsFloor> floor = usable_floor(options.floor, motion, k, out.notes);

  const Integration end = integrate(motion, k, floor, options, out);

  const Physical last = unpack(end.x, k);
  out.end_time = end.tau * k.time;
  if (out.samples.empty() || out.samples.back().time < out.end_time - 1e-9 * k.time)
    out.samples.push_back(sample_at(motion, last, out.end_time));
  if (end.landed) {
    out.landing = landing_of(block, motion, last, *floor, out.end_time);
    record_event(out.events, out.end_time, "lands", landing_text(*out.landing), {});
  }
  out.outcome = outcome_of(end.landed, end.mode,
                           floor           ? FloorGiven::usable
                           : options.floor ? FloorGiven::above_block
                                           : FloorGiven::none);
  if (!end.stopped.empty()) {
    out.stopped = end.stopped;
    out.outcome = "stopped before the end of the duration";
  }
  return out;
}

}  // namespace rockface::mechanics

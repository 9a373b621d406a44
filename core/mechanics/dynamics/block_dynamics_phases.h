#pragma once
// The phases of simulate_block_motion (block_dynamics.h), each a function
// of its own input, declared here so that each can be read and tested on
// its own:
//   1. block_scales: the block's own units (length, time, speed, energy);
//   2. usable_floor: the floor, unless it lies above the block;
//   3. integrate: start_integration, then for each step budget_spent,
//        sample_up_to, controlled_step, cut_at_event (locate_event: the
//        earliest event inside it, by bisection), sample_within_step,
//        finish_step
//        (project_step: drift back onto the loaded contacts, impacts;
//        record_mode_change; flight_end: free flight goes on to the floor);
//   4. landing_of, landing_text, outcome_of: how the motion ended.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/blocks/polyhedron.h"
#include "core/mechanics/dynamics/block_dynamics.h"
#include "core/mechanics/dynamics/block_motion.h"
#include "core/mechanics/dynamics/contact_mode.h"

namespace rockface::mechanics::dynamics_phases {

// Scaled state: centroid displacement / L, quaternion (w, x, y, z),
// velocity / sqrt(g L), angular velocity x T, work of the loads / (W L).
using State = std::array<double, 14>;

// The block's own units: length L = its size, time T = sqrt(L / g), speed
// L / T, energy its weight times L.
struct Scales {
  double length = 1, time = 1, speed = 1, energy = 1;
};
Scales block_scales(const BlockMotion& motion);

// The state in physical units.
struct Physical {
  BlockPose pose;
  BlockVelocity velocity;
  double work = 0;
};
Physical unpack(const State& s, const Scales& k);
State pack(const Physical& p, const Scales& k);

// The floor with a unit normal, or none (said in notes) when it lies above
// the block's lowest corner at rest by more than the contact tolerance.
std::optional<DynamicsFloor> usable_floor(const std::optional<DynamicsFloor>& floor,
                                          const BlockMotion& motion, const Scales& k,
                                          std::vector<std::string>& notes);

void record_event(std::vector<MotionEvent>& events, double t, const std::string& kind,
                  const std::string& what, std::vector<std::string> planes);
// The events of a change of contact mode at time t: each plane left, then
// the new mode (when it differs in kind or in words).
void record_mode_change(std::vector<MotionEvent>& events, const ContactMode& from,
                        const ContactMode& to, double t);

// The earliest event inside a step that ended (after `step`, scaled time)
// in x_end with one: bisection to kEventTimeRel of advance(h), the state h
// after the step's start, where happened() first holds. Returns that state
// and h.
struct EventTime {
  State state{};
  double after = 0;
};
EventTime locate_event(const State& x_end, double step, const std::function<State(double)>& advance,
                       const std::function<bool(const State&)>& happened);

// The end of the simulated time (scaled) while the block flies freely: on
// to the floor, at most kMaxFlightSeconds beyond now and beyond the
// duration.
double flight_end(double tau, double tau_end_contact, const Scales& k);

// After a step (not a landing): the pose drifted back onto the loaded
// contacts and a closing contact stopped (a plastic impact, recorded as a
// "hits" event at tau when fast); the drift kept in out.
void project_step(const BlockMotion& motion, const Scales& k, double tau, State& x,
                  BlockDynamics& out);

// Where and how fast the block (`last`, at end_time) lands on the floor, and
// the steep free face it moved out through.
Landing landing_of(const blocks::Polyhedron& block, const BlockMotion& motion, const Physical& last,
                   const DynamicsFloor& floor, double end_time);
// "lands 3.2 m out from the foot of the face F, 14.8 m below it, at 7.1
// m/s"; "lands 2.0 m from where it started at 7.1 m/s" without a steep face.
std::string landing_text(const Landing& l);

// Whether a floor was given, and whether it lies below the block (usable).
enum class FloorGiven { none, above_block, usable };
// "lands", "at rest", "in free flight ..." (saying why no landing was
// computed: no floor, or one above the block) or "moving at the end".
std::string outcome_of(bool landed, const ContactMode& mode, FloorGiven floor);

// The equations of motion in the block's units and the Dormand-Prince
// 5(4) stepper on them; every evaluation is counted in `evaluations`.
class Stepper {
 public:
  Stepper(const BlockMotion& motion, const Scales& k, int& evaluations,
          const DynamicsOptions& options);
  // One controlled step from (x, tau) of at most h: false when rejected
  // (h then holds the shorter step to try), else x, tau and h advanced.
  bool try_step(State& x, double& tau, double& h) const;
  // One plain step of length h from (x0, t0): the bisection's probe of a
  // step that an event cuts short.
  State advance(const State& x0, double t0, double h) const;

 private:
  std::function<void(const State&, State&, double)> system_;
  double abs_tol_ = 0, rel_tol_ = 0;
};

// The contact mode of the block in scaled state s.
ContactMode mode_of(const BlockMotion& motion, const Scales& k, const State& s);

// The integration as it goes: state and scaled time, the step's start,
// the ends of the simulated time, the next sample, the contact mode.
struct Integration {
  State x{};
  double tau = 0;
  State x0{};  // at the start of the current step
  double t0 = 0;
  double tau_end_contact = 0, tau_end = 0;  // the duration; on to the floor in free flight
  double tau_sample = 0, next_sample = 0, tau_max_step = 0;
  double dt = 0;  // the next step to try
  ContactMode mode;
  bool landed = false;
  std::string stopped;  // why it stopped before its end (the budget, the step floor), or empty
};

// The phases of integrate, in the order of one step:
// start_integration: the block at rest, its first contact mode (an event);
// budget_spent: why the integration must stop now (the evaluations of the
//   options' step budget or its event limit spent), or none;
// sample_up_to: the samples due at the current time;
// controlled_step: one step (false: rejected, a shorter one is next, or
//   none below the step floor: `stopped` says so), of the error control's
//   length, never shortened to meet a sample;
// cut_at_event: the step cut at its earliest event (impact, landing, a
//   change of contact mode); returns the contact mode there;
// sample_within_step: the samples inside the step just taken, each one
//   step of the same method from the step's start (`sampler`: a stepper
//   whose evaluations are not the integration's budget);
// finish_step: drift projected back, the mode change recorded, free flight
//   extended to the floor.
Integration start_integration(const BlockMotion& motion, const Scales& k,
                              const DynamicsOptions& options, BlockDynamics& out);
std::optional<std::string> budget_spent(const Integration& in, const Scales& k,
                                        const DynamicsOptions& options, const BlockDynamics& out);
void sample_up_to(const BlockMotion& motion, const Scales& k, Integration& in, BlockDynamics& out);
bool controlled_step(const Stepper& stepper, const Scales& k, Integration& in, BlockDynamics& out);
ContactMode cut_at_event(const BlockMotion& motion, const Scales& k,
                         const std::optional<DynamicsFloor>& floor, const Stepper& stepper,
                         Integration& in);
void sample_within_step(const BlockMotion& motion, const Scales& k, const Stepper& sampler,
                        Integration& in, BlockDynamics& out);
void finish_step(const BlockMotion& motion, const Scales& k,
                 const std::optional<DynamicsFloor>& floor, ContactMode new_mode, Integration& in,
                 BlockDynamics& out);

// The motion integrated from rest (events, samples, steps and drift into
// out) until the duration ends, it lands, or the budget is spent (said in
// stopped). Returns where it ended.
Integration integrate(const BlockMotion& motion, const Scales& k,
                      const std::optional<DynamicsFloor>& floor, const DynamicsOptions& options,
                      BlockDynamics& out);

}  // namespace rockface::mechanics::dynamics_phases

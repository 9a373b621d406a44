#pragma once
// The phases of simulate_block_motion (block_dynamics.h), each a function
// of its own input, declared here so that each can be read and tested on
// its own:
//   1. block_scales: the block's own units (length, time, speed, energy);
//   2. usable_floor: the floor, unless it lies above the block;
//   3. integrate: the time steps, with for each step
//        locate_event (the earliest event inside it, by bisection),
//        project_step (drift back onto the loaded contacts, impacts),
//        record_mode_change (the events of a change of contact mode),
//        flight_end (free flight goes on to the floor);
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
// "lands 3.2 m from the face F at 7.1 m/s".
std::string landing_text(const Landing& l);

// "lands", "at rest", "in free flight ..." or "moving at the end".
std::string outcome_of(bool landed, const ContactMode& mode, bool has_floor);

// The motion integrated from rest (events, samples, steps and drift into
// out). Returns the last state and scaled time, whether it landed, and
// the contact mode at the end.
struct IntegrationEnd {
  State x{};
  double tau = 0;
  bool landed = false;
  ContactMode mode;
};
IntegrationEnd integrate(const BlockMotion& motion, const Scales& k,
                         const std::optional<DynamicsFloor>& floor, const DynamicsOptions& options,
                         BlockDynamics& out);

}  // namespace rockface::mechanics::dynamics_phases

#pragma once
// The block's motion after failure (issue 29; DESIGN.md "Effects": dynamics
// after failure): the rigid block (block_motion.h) on its joint contacts
// (joint_contacts.h) under gravity and the scene's effects, integrated in
// time with Boost.Odeint's Dormand-Prince 5(4) controlled stepper, from
// rest at its place in the rock until the scene's duration ends or, once
// it has left its last contact, until it lands on the floor.
//
// Between steps: contacts that carry load are projected back onto their
// planes (drift bound kDriftBoundRel x L), a contact that closes is an
// impact (perfectly plastic), the floor is hit. Contact switches, impacts
// and the landing are located by bisection of the step (to kEventTimeRel
// x T) and reported as events: "slides on J1", "slides on J1 and J2",
// "rotates about edge J2-J3", "rotates about a corner on J1", "leaves J1",
// "free fall", "hits J1", "lands", "at rest".
//
// The integration runs in the block's own units (length L = its diameter,
// the largest distance between two of its corners, whatever its frame;
// time T = sqrt(L / g), its weight): the tolerances mean the same for a
// chip and a slab, and survey coordinates (datum-relative, moved to the
// centroid) lose nothing.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/blocks/mass_properties.h"
#include "core/blocks/polyhedron.h"
#include "core/common/preset.h"
#include "core/common/progress.h"
#include "core/kinematics/effects/effect.h"
#include "core/mechanics/dynamics/tolerances.h"

namespace rockface::mechanics {

// A plane the block lands on (datum-relative): the floor of the
// excavation, a bench, or the tunnel's invert.
struct DynamicsFloor {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, up (into the air)
};

struct DynamicsOptions {
  double duration = 2.0;  // s of motion simulated (free flight then goes on to the floor)
  // s between the path's samples: taken between the integration's steps
  // (one step of the same method from a step's start), never changing them.
  double sample = 0.2;
  // Error control of the stepper, per unit of the block's size and of
  // sqrt(L g) (positions, velocities; the quaternion is dimensionless).
  double abs_tol = 1e-10, rel_tol = 1e-8;
  double max_step = 0.01;  // s
  std::optional<DynamicsFloor> floor;
  // The integration always ends: at most this many evaluations of the
  // equations of motion (a step budget, free of the wall clock) and this
  // many events; past either, or where the error control asks for a step
  // below the step floor (tolerances.h), it stops and says why
  // (BlockDynamics::stopped).
  int max_evaluations = kDynamicsEvaluationBudget;
  int max_events = kMaxDynamicsEvents;
  Progress* progress = nullptr;
};

// The time-step knobs of `preset` (DESIGN.md "Accuracy costs time").
DynamicsOptions dynamics_options(Preset preset);

struct MotionSample {
  double time = 0;                                                  // s
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();               // datum-relative
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // from rest
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();               // m/s
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();       // rad/s, global axes
  double kinetic_translational = 0, kinetic_rotational = 0;         // J
  double work = 0;        // J, done by gravity and the effects since rest
  double dissipated = 0;  // J, work - kinetic energy: friction and impacts
};

struct MotionEvent {
  double time = 0;                  // s
  std::string kind;                 // slides | rotates | leaves | free_fall | hits | lands | rest
  std::string what;                 // "leaves J1", "rotates about edge J2-J3"
  std::vector<std::string> planes;  // the planes it names
};

struct Landing {
  double time = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();           // the corner that touches first
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();        // datum-relative
  double speed = 0;                                          // m/s, of the centroid
  double corner_speed = 0;                                   // m/s, of the corner that touches
  double angular_speed = 0;                                  // rad/s
  double kinetic_translational = 0, kinetic_rotational = 0;  // J
  double distance_from_start = 0;                            // m, horizontal, of the centroid
  std::optional<double> distance_from_face;                  // m, horizontal, in front of the face
  std::string face;                                          // that free face
  // From the face's foot (the lowest corner of the block's face on it, at
  // rest): the landing centroid's horizontal distance out in front of it
  // (negative: behind, under an overhang) and how far the touching corner
  // lies below it. What a reader pictures: "12.3 m out from the foot of the
  // face F1, 14.8 m below it" (the face plane itself, extended down to the
  // floor, can pass in front of a block that lands beyond its foot).
  std::optional<double> distance_from_foot, drop_below_foot;  // m
};

struct BlockDynamics {
  std::vector<MotionEvent> events;
  std::vector<MotionSample> samples;
  std::optional<Landing> landing;
  std::string outcome;  // "lands", "at rest", "in free flight (no floor given)", "moving at the
                        // end", "stopped before the end of the duration"
  std::string stopped;  // why it stopped before its end (the step budget, the event limit)
  double end_time = 0;
  double mass = 0;
  std::vector<double> friction_deg;  // per polyhedron plane used while sliding
  // Constraint drift: the largest gap of a loaded contact (or penetration)
  // before and after the projections, and of |q| - 1.
  double drift_before = 0, drift_after = 0, drift_bound = 0, quaternion_error = 0;
  int steps = 0, rejected_steps = 0, evaluations = 0;
  std::vector<std::string> effects_used;
  std::vector<std::string> notes;
};

// friction_deg: per polyhedron plane (joints), the friction angle while
// sliding; cohesion is taken as lost. Throws InputError for bad options
// ("analysis.dynamics.<field>").
BlockDynamics simulate_block_motion(const blocks::Polyhedron& block,
                                    const blocks::MassProperties& mass,
                                    const kinematics::Effects& effects,
                                    const std::vector<double>& friction_deg,
                                    const DynamicsOptions& options);

}  // namespace rockface::mechanics

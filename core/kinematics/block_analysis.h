#pragma once
// Everything about one block before rotations and mechanics: mass
// properties, finiteness and removability (Goodman & Shi, with the theorem
// for non-convex blocks), the translational mode and the limit-equilibrium
// factor of safety under the effects the scene lists.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/mass_properties.h"
#include "core/blocks/polyhedron.h"
#include "core/geometry/cone.h"
#include "core/geometry/verdict.h"
#include "core/kinematics/effects/effect.h"
#include "core/kinematics/sliding_mode.h"

namespace rockface::kinematics {

// Strength of a joint plane (free faces have none).
struct JointStrength {
  std::optional<double> friction;  // radians; none: no limit equilibrium on it
  double cohesion = 0;             // Pa
};

// Finiteness and removability with margins.
struct Finiteness {
  geometry::Cone joint_pyramid;  // intersection of the joint half-spaces
  std::vector<geometry::Cone>
      excavation_pyramids;      // EP = their union (one for a convex free surface)
  double jp_margin = 0;         // radians, signed: > 0 JP has an interior
  double jp_ep_margin = 0;      // radians, signed: > 0 JP cap EP open (infinite block)
  geometry::Verdict finite;     // JP cap EP empty
  geometry::Verdict removable;  // finite and JP not empty
  // Joint faces on both sides of planes within the orientation uncertainty
  // of parallel (two joints of one set bounding a slab): JP has no width
  // across them, and its ordinary margin's sign is rounding. JP is then
  // decided within their plane (on the line of two such pairs), by
  // jp_in_plane_margin (radians, signed: > 0 the block can slide out
  // between them); a removable verdict so decided is marginal (whether the
  // planes open or close toward the free face cannot be told), never a flip
  // (core/geometry/parallel_planes.h, core/analysis/README.md, "Joints taken as parallel").
  bool jp_between_parallel = false;
  double jp_in_plane_margin = 0;
  // The planes JP cap EP was decided with as parallel (the caller's pairs,
  // halfspace_finiteness): their widest angle, radians; 0 for none.
  double parallel_angle = 0;
};

// From the planes of a block: joints give JP, free faces give the EP. Free
// faces meeting at a reflex edge of the block belong to different convex
// parts of the free surface (each part: a maximal set of free planes with no
// reflex edge between two of them); EP is the union of the parts' pyramids,
// each the intersection of its faces' rock-side half-spaces (Goodman & Shi's
// theorem for non-convex blocks). A block with no free face has EP = the
// whole space: JP cap EP = JP, finite only when JP is empty, so it is never
// removable (a block inside the rock mass).
Finiteness block_finiteness(const blocks::Polyhedron& block, double uncertainty);

// The same for half-spaces alone (a convex block that may be unbounded):
// joint and free-face block-side normals; the free faces form one EP.
// parallel: pairs of planes (indices into the joints, then the free faces)
// the caller takes as exactly parallel from where they are (two planes of a
// slab that meet only far beyond the block): JP cap EP is then decided
// within their plane, by the angle it is open or shut there. Without them
// only JP is (see Finiteness): whether two near-parallel planes meet at the
// block or far from it is not in the normals.
Finiteness halfspace_finiteness(const std::vector<Eigen::Vector3d>& joint_inward_normals,
                                const std::vector<Eigen::Vector3d>& free_inward_normals,
                                double uncertainty,
                                const std::vector<std::pair<int, int>>& parallel = {});

// Removability from JP and the signed margin by which JP cap EP is shut
// (> 0: finite), the uncertainty behind them (radians): JP decided within
// the plane of joints taken as parallel where it has some (see Finiteness).
// Sets removable, jp_margin, jp_between_parallel and jp_in_plane_margin.
void decide_removability(Finiteness& f, double shut_margin, double uncertainty);

struct BlockAnalysisInput {
  double density = 2700;                 // kg/m^3
  std::vector<JointStrength> strengths;  // per polyhedron plane (ignored for free faces)
  const Effects* effects = nullptr;      // must include gravity to have weight
  double uncertainty = 0;                // radians, orientation uncertainty
};

struct BlockAnalysis {
  blocks::MassProperties mass;
  Finiteness finiteness;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // active resultant, N
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // about the centroid, N m
  std::vector<std::string> effects_used;             // names of the effects that act on it
  std::optional<SlidingMode> mode;  // removable (or marginally removable) blocks only
  std::optional<double> fos;        // with friction and cohesion x contact area
  // Joint planes (indices into planes()) whose water pressure exceeds the
  // compression the rest of the loads put on them: they open, and their
  // friction and cohesion do not count.
  std::vector<int> opened_planes;
  std::vector<std::string> notes;
};

// The complete single-block analysis.
BlockAnalysis analyse_block(const blocks::Polyhedron& block, const BlockAnalysisInput& input);

// The block's joint planes as contacts for sliding_mode(): block-side
// normal, friction and cohesion x the plane's contact area on the block.
std::vector<ContactPlane> block_contacts(const blocks::Polyhedron& block,
                                         const blocks::MassProperties& mass,
                                         const std::vector<JointStrength>& strengths);

}  // namespace rockface::kinematics

#pragma once
// From the loops of the trace map to blocks, assuming the joints persist into
// the rock.
//
// A loop's planes are the joint planes of its stretches, each with the side
// the loop's inside lies on, and the patches it covers, with their rock side
// (plus a neighbouring patch whose plane the block could otherwise cut
// through, where the rock behind it is salient).
//   - Convex case (no reflex corner between two joints, the rock behind the
//     covered patches convex): the block is the intersection of these
//     half-spaces.
//   - Otherwise the block is the union of the convex cells of the planes'
//     arrangement that lie behind the loop: behind each part of the loop cut
//     out by the joint lines, and at re-entrant patch edges and corners also
//     behind the edge (where the rock is the union of the patches' rock
//     sides). Cells meet face to face, so the union is assembled by dropping
//     the faces two cells share. This is Goodman & Shi's non-convex block as
//     a union of convex blocks; the joints of a reflex corner meet along
//     their line of intersection inside the rock.
//   - An island of traces inside the loop bounds its own block (its region
//     is a loop of its own); the block around it is the outer block cut by
//     the island's joint planes into cells, all kept but those behind the
//     island: the outer block without the island's block, one solid.
// Each block then gets the same analysis as an explicit block: mass
// properties, finiteness (theorem for non-convex blocks), removability with
// margins, mode and factor of safety.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/polyhedron.h"
#include "core/common/progress.h"
#include "core/faces/free_surface.h"
#include "core/faces/surface_loops.h"
#include "core/faces/trace_network.h"
#include "core/kinematics/block_analysis.h"

namespace rockface::faces {

struct TraceBlockOptions {
  double snap_tolerance = 0.05;        // m
  double orientation_uncertainty = 0;  // radians (fitted planes add their own)
  double density = 2700;               // kg/m^3
  const kinematics::Effects* effects = nullptr;
  // Absolute position of the coordinates' origin: polyhedra carry it so that
  // effects given at absolute points (water, forces, bolts) find the block.
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
};

// A plane of a trace block: a joint (a plane group of the network) or a patch.
struct TraceBlockPlane {
  std::string name;  // the group's first trace id, or the patch id
  blocks::PlaneKind kind = blocks::PlaneKind::Joint;
  geometry::Plane plane;
  int group = -1;  // network plane group (joints)
  int patch = -1;  // surface patch (free faces)
  // The plane's index for the analysis (BlockPlane::index): the caller's
  // joint index for a joint plane (so that effects naming joints, such as
  // water, find it), -1 for a patch or a fitted plane.
  int scene_index = -1;
};

struct TraceBlock {
  int region = -1;                               // index into SurfaceLoops::regions()
  std::vector<int> traces;                       // input trace indices, loop order
  std::vector<Eigen::Vector3d> surface_polygon;  // outer loop corners, datum-relative
  std::vector<TraceBlockPlane> planes;           // the digits of the codes, in order
  // One code per convex piece (digits 0 upper, 1 lower, 2 not involved); one
  // code for a convex block.
  std::vector<std::string> codes;
  bool convex = true;
  bool finite = false;
  kinematics::Finiteness finiteness;
  std::optional<blocks::Polyhedron> polyhedron;       // finite blocks
  std::optional<kinematics::BlockAnalysis> analysis;  // finite blocks
  // Per polyhedron plane, the joints' friction and cohesion the analysis
  // took (finite blocks): the equilibrium path takes the same.
  std::vector<kinematics::JointStrength> strengths;
  double uncertainty = 0;  // radians behind the verdicts (scene's, or worse for fitted planes)
  std::vector<std::string> notes;
};

// Blocks of all closed loops, ordered by the position of their surface
// polygon (west to east, south to north, low to high) so that the order does
// not depend on the order of the traces. Checks progress between loops.
std::vector<TraceBlock> trace_blocks(const FreeSurface& surface, const TraceNetwork& network,
                                     const SurfaceLoops& loops, const TraceBlockOptions& options,
                                     Progress& progress);

// The block of one region (loops.regions()[r]), as trace_blocks() makes it;
// none when the region has no loop or every piece behind it is empty.
std::optional<TraceBlock> trace_block(const FreeSurface& surface, const TraceNetwork& network,
                                      const SurfaceLoops& loops, int r,
                                      const TraceBlockOptions& options);

// The order of trace_blocks() (by the position of the surface polygon).
void order_trace_blocks(std::vector<TraceBlock>& blocks);

}  // namespace rockface::faces

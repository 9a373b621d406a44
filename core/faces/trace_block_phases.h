#pragma once
// The phases of trace_block (trace_blocks.h), each a function of its own
// input, declared here so that each can be read and tested on its own:
//   1. loop_planes: the block's planes (the loop's joints by name, the
//      covered patches, the salient neighbouring patches behind it);
//   2. loop_shape: the sides of the joints along the loop, reflex corners,
//      whether the rock behind the covered patches is convex;
//   3. island_joints: the joints of traces inside the outer loop only;
//   4. convex_piece or nonconvex_pieces: the half-space codes of the block's
//      convex pieces (nonconvex_pieces cuts out the islands' blocks with
//      cut_out_islands);
//   5. build_piece_cells: each piece's convex polyhedron (or why none);
//   6. analyse_cells: the union of the cells as one polyhedron and its
//      analysis, or the verdicts of the union from its pieces.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/blocks/polyhedron.h"
#include "core/faces/free_surface.h"
#include "core/faces/surface_loops.h"
#include "core/faces/trace_blocks.h"
#include "core/faces/trace_network.h"
#include "core/geometry/plane.h"

namespace rockface::faces::trace_block_phases {

// The planes of a region's block, in the order of the digits of its codes.
struct LoopPlanes {
  std::vector<TraceBlockPlane> planes;  // joints by name, covered patches, neighbouring patches
  std::map<int, int> plane_of_group;    // the network's plane group -> index into planes
  int n_joints = 0;                     // planes[0, n_joints) are the joints
  std::vector<int> covered;             // the patches the region covers
  double uncertainty = 0;               // radians: the options', or a fitted plane's when worse
  std::vector<std::string> notes;       // one per fitted plane
};
LoopPlanes loop_planes(const FreeSurface& surface, const TraceNetwork& net,
                       const SurfaceLoops& loops, const SurfaceRegion& region,
                       const TraceBlockOptions& options);

// The patches next to the covered ones (a corner within tol) whose plane
// the block could cut through: the rock behind them and the covered
// patches is salient, and the region's footprint lies behind them.
std::vector<int> neighbouring_patches(const FreeSurface& surface, const SurfaceLoops& loops,
                                      const TraceNetwork& net, const SurfaceRegion& region,
                                      double tol);

struct LoopShape {
  std::vector<std::set<geometry::HalfSpace>> joint_sides;  // per joint: where the inside lies
  bool reflex = false;      // a reflex joint corner, or more than one loop
  bool rock_convex = true;  // no two covered patches with the rock their union
  bool one_side = true;     // every joint has the inside on one side only
  bool convex() const { return !reflex && rock_convex && one_side; }
};
LoopShape loop_shape(const FreeSurface& surface, const TraceNetwork& net, const SurfaceLoops& loops,
                     const SurfaceRegion& region, const LoopPlanes& planes, double tol);

// The joints whose traces lie only on loops inside the outer one.
struct Islands {
  std::vector<bool> island;  // per joint plane
  std::vector<int> planes;   // the island joints' plane indices, ascending
};
Islands island_joints(const TraceNetwork& net, const SurfaceRegion& region,
                      const LoopPlanes& planes);

// A convex piece of a block: one side per block plane.
struct Piece {
  std::vector<geometry::HalfSpace> sides;  // one per block plane
  bool may_be_empty = false;               // a cell of island planes: empty ones are expected
  std::string code() const;
};

// The one piece of a convex loop (LoopShape::convex()): each joint on the
// loop's inside, each patch on its rock side.
Piece convex_piece(const FreeSurface& surface, const LoopPlanes& planes, const LoopShape& shape);

// The convex cells of the planes' arrangement behind a non-convex loop,
// islands cut out; notes say how the block was assembled.
struct NonConvexPieces {
  std::vector<Piece> pieces;
  std::vector<std::string> notes;
};
NonConvexPieces nonconvex_pieces(const FreeSurface& surface, const TraceNetwork& net,
                                 const SurfaceLoops& loops, const SurfaceRegion& region,
                                 const LoopPlanes& planes, const Islands& islands, double tol);

// Every cell of the island planes in each outer piece, but those whose
// island sides are in `behind_islands` (the islands' own blocks); each may
// be empty. The same code once.
std::vector<Piece> cut_out_islands(
    const std::vector<Piece>& pieces, const std::vector<int>& island_planes,
    const std::set<std::vector<geometry::HalfSpace>>& behind_islands);

// The name of a region's block: "loop along" its outer loop's first joint.
std::string block_id(const TraceNetwork& net, const SurfaceRegion& region);

// The convex polyhedra of the pieces (block.planes, in order). Writes the
// notes of empty and unbounded pieces into block, its finiteness when a
// piece is unbounded or cannot be assembled, and the redundant planes of a
// convex block's code.
struct PieceCells {
  std::vector<blocks::Polyhedron> cells;  // the bounded, non-empty pieces
  double shut_margin = 0;                 // the least recession margin of the pieces, radians
  bool unbounded = false;
  bool geometry_failed = false;
};
PieceCells build_piece_cells(const std::string& id, const std::vector<Piece>& pieces,
                             const TraceBlockOptions& options, TraceBlock& block);

// The block of the cells (their union when several) and its analysis with
// the joints' strengths; when the union is no polyhedron, its verdicts from
// its pieces.
void analyse_cells(const std::string& id, std::vector<blocks::Polyhedron>& cells,
                   double shut_margin, const TraceNetwork& net, const TraceBlockOptions& options,
                   TraceBlock& block);

}  // namespace rockface::faces::trace_block_phases

// The pieces behind a non-convex loop of traces, and the block around
// islands cut out of them (trace_block_phases.h): the search over the
// cells of the loop's joints on each covered patch.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/common/error.h"
#include "core/faces/patch_cells.h"
#include "core/faces/tolerances.h"
#include "core/faces/trace_block_phases.h"

namespace rockface::faces {

namespace {

using geometry::HalfSpace;

// Cutting the block around an island into the cells of the island's planes
// takes 2^n of them per piece: enough for any island a geologist marks.
constexpr size_t kMaxIslandPlanes = 10;

HalfSpace opposite(HalfSpace h) {
  return h == HalfSpace::Upper ? HalfSpace::Lower : HalfSpace::Upper;
}

using trace_block_phases::LoopPlanes;
using trace_block_phases::Piece;

HalfSpace side_of(const geometry::Plane& pl, const Eigen::Vector3d& x) {
  return pl.signed_distance(x) > 0 ? HalfSpace::Upper : HalfSpace::Lower;
}

// The pieces found behind a non-convex loop so far, each code once.
class PieceCollector {
 public:
  PieceCollector(const FreeSurface& surface, const LoopPlanes& planes, double tol)
      : surface_(surface), planes_(planes), tol_(tol) {}

  // The piece of the joints' cell around cell_centre, on the rock side of
  // the patches that contain `at` or lie above it.
  void add(const Eigen::Vector3d& cell_centre, const Eigen::Vector3d& at,
           const std::vector<int>& containing) {
    const auto& patches = surface_.patches();
    const int n_joints = planes_.n_joints;
    const int n_planes = static_cast<int>(planes_.planes.size());
    Piece p;
    for (int j = 0; j < n_joints; ++j)
      p.sides.push_back(side_of(planes_.planes[j].plane, cell_centre));
    for (int k = n_joints; k < n_planes; ++k) {
      const SurfacePatch& Q = patches[planes_.planes[k].patch];
      const bool contains = std::find(containing.begin(), containing.end(),
                                      planes_.planes[k].patch) != containing.end();
      const bool rock = contains || Q.height(at) <= tol_;
      p.sides.push_back(rock ? Q.rock_side : opposite(Q.rock_side));
    }
    if (seen_.insert(p.code()).second) pieces_.push_back(p);
  }
  std::vector<Piece>& pieces() { return pieces_; }

 private:
  const FreeSurface& surface_;
  const LoopPlanes& planes_;
  double tol_;
  std::set<std::string> seen_;
  std::vector<Piece> pieces_;
};

// The region's faces on one patch (2D, patch frame): the region proper, and
// the outsides of islands (what they enclose is the islands' block).
struct RegionOnPatch {
  std::vector<std::vector<Eigen::Vector2d>> region, holes;
};
RegionOnPatch region_on_patch(const TraceNetwork& net, const SurfaceLoops& loops,
                              const SurfaceRegion& region, int pi, const SurfacePatch& P,
                              bool has_islands) {
  RegionOnPatch out;
  for (int f : region.faces) {
    if (loops.faces()[f].patch != pi) continue;
    std::vector<Eigen::Vector2d> poly;
    for (int h : loops.faces()[f].half_edges) poly.push_back(P.to2d(net.vertices()[net.origin(h)]));
    const bool hole = has_islands && loops.faces()[f].area <= 0;
    (hole ? out.holes : out.region).push_back(std::move(poly));
  }
  return out;
}

Eigen::Vector2d centroid_of(const std::vector<Eigen::Vector2d>& cell) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& x : cell) c += x;
  c /= static_cast<double>(cell.size());
  return c;
}

// The island planes' sides behind each hole: the patch cut by the island
// joints; a hole's edges are such cuts, so each cell lies wholly inside or
// outside a hole.
void sides_behind_holes(const SurfacePatch& P, const std::vector<TraceBlockPlane>& planes,
                        const std::vector<int>& island_planes,
                        const std::vector<std::vector<Eigen::Vector2d>>& holes,
                        std::set<std::vector<HalfSpace>>& island_cells) {
  for (const auto& cell : cut_by_planes(P, planes, island_planes)) {
    const Eigen::Vector2d c = centroid_of(cell);
    int w = 0;
    for (const auto& poly : holes) w += winding_number(poly, c);
    if (w == 0) continue;
    std::vector<HalfSpace> sides;
    for (int j : island_planes) sides.push_back(side_of(planes[j].plane, P.to3d(c)));
    island_cells.insert(sides);
  }
}

// The thickest cell inside the region so far (its piece is the block when
// every cell is thinner than the tolerance).
struct ThickestCell {
  double thickness = -1;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  int patch = -1;
};

// The pieces behind the cells of the outer joints on patch pi that lie in
// the region, and behind their edges and corners that lie on other covered
// patches too.
void pieces_behind_cells(const SurfacePatch& P, int pi,
                         const std::vector<std::vector<Eigen::Vector2d>>& cells,
                         const std::vector<std::vector<Eigen::Vector2d>>& region_polys,
                         const FreeSurface& surface, const std::vector<int>& covered, double tol,
                         PieceCollector& collect, ThickestCell& thickest) {
  const auto& patches = surface.patches();
  for (const auto& cell : cells) {
    const Eigen::Vector2d c = centroid_of(cell);
    int w = 0;
    for (const auto& poly : region_polys) w += winding_number(poly, c);
    if (w == 0) continue;
    const double thickness = 2 * polygon_area(cell) / polygon_perimeter(cell);
    const Eigen::Vector3d c3 = P.to3d(c);
    if (thickness > thickest.thickness) {
      thickest.thickness = thickness;
      thickest.centre = c3;
      thickest.patch = pi;
    }
    if (thickness < kThinCellInTolerances * tol) continue;
    collect.add(c3, c3, {pi});
    // Behind edges and corners of the cell that lie on other covered patches too.
    for (size_t k = 0; k < cell.size(); ++k) {
      for (const Eigen::Vector3d& x :
           {P.to3d(cell[k]), P.to3d((cell[k] + cell[(k + 1) % cell.size()]) / 2)}) {
        std::vector<int> containing;
        for (int q : covered) {
          const SurfacePatch& Q = patches[q];
          if (std::abs(Q.height(x)) <= tol && Q.contains(Q.to2d(x), tol)) containing.push_back(q);
        }
        if (containing.size() >= 2) collect.add(c3, x, containing);
      }
    }
  }
}

}  // namespace

namespace trace_block_phases {

std::vector<Piece> cut_out_islands(const std::vector<Piece>& pieces,
                                   const std::vector<int>& island_planes,
                                   const std::set<std::vector<HalfSpace>>& behind_islands) {
  std::vector<Piece> cut;
  std::set<std::string> seen;
  const unsigned combos = 1u << island_planes.size();
  for (const Piece& outer : pieces)
    for (unsigned m = 0; m < combos; ++m) {
      std::vector<HalfSpace> sides;
      for (size_t i = 0; i < island_planes.size(); ++i)
        sides.push_back(m >> i & 1u ? HalfSpace::Lower : HalfSpace::Upper);
      if (behind_islands.count(sides)) continue;
      Piece p = outer;
      for (size_t i = 0; i < island_planes.size(); ++i) p.sides[island_planes[i]] = sides[i];
      p.may_be_empty = true;
      if (seen.insert(p.code()).second) cut.push_back(std::move(p));
    }
  return cut;
}

NonConvexPieces nonconvex_pieces(const FreeSurface& surface, const TraceNetwork& net,
                                 const SurfaceLoops& loops, const SurfaceRegion& region,
                                 const LoopPlanes& planes, const Islands& islands, double tol) {
  const auto& patches = surface.patches();
  PieceCollector collect(surface, planes, tol);
  std::set<std::vector<HalfSpace>> island_cells;  // sides of island planes behind an island
  ThickestCell thickest;
  std::vector<int> outer_planes;  // the outer block's cells first
  for (int j = 0; j < planes.n_joints; ++j)
    if (!islands.island[j]) outer_planes.push_back(j);
  for (int pi : planes.covered) {
    const SurfacePatch& P = patches[pi];
    const auto cells = cut_by_planes(P, planes.planes, outer_planes);
    const RegionOnPatch on = region_on_patch(net, loops, region, pi, P, !islands.planes.empty());
    if (!on.holes.empty())
      sides_behind_holes(P, planes.planes, islands.planes, on.holes, island_cells);
    pieces_behind_cells(P, pi, cells, on.region, surface, planes.covered, tol, collect, thickest);
  }
  if (collect.pieces().empty() && thickest.patch >= 0)
    collect.add(thickest.centre, thickest.centre, {thickest.patch});
  NonConvexPieces out;
  out.pieces = std::move(collect.pieces());
  if (!islands.planes.empty() && islands.planes.size() <= kMaxIslandPlanes) {
    out.pieces = cut_out_islands(out.pieces, islands.planes, island_cells);
    out.notes.push_back(
        "the traces inside the loop bound a block of their own, cut out of this one");
  } else if (!islands.planes.empty()) {
    out.pieces.clear();
    out.notes.push_back(
        "block geometry not assembled: the islands of traces inside the loop have " +
        std::to_string(islands.planes.size()) + " joints (at most " +
        std::to_string(kMaxIslandPlanes) + " are cut out)");
  }
  out.notes.push_back("non-convex: the union of " + std::to_string(out.pieces.size()) +
                      " convex pieces");
  return out;
}

}  // namespace trace_block_phases

}  // namespace rockface::faces

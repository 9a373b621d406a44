#pragma once
// Building blocks: a convex block as the intersection of half-spaces, and a
// possibly non-convex block from vertices and face loops.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/polyhedron.h"

namespace rockface::blocks {

// One half-space of a convex block: the plane (datum-relative, upward unit
// normal), the side the block lies on, and who the plane is.
struct HalfSpaceInput {
  int index = -1;    // caller's plane index (scene order)
  std::string name;  // caller's plane id
  PlaneKind kind = PlaneKind::Joint;
  geometry::Plane plane;
  geometry::HalfSpace side = geometry::HalfSpace::Upper;  // Upper or Lower
};

enum class ConvexOutcome {
  Bounded,    // a finite convex polyhedron with volume
  Unbounded,  // the half-spaces leave a direction open: an infinite block
  Empty       // no common interior (or only a plane, line or point of it)
};

struct ConvexConstruction {
  ConvexOutcome outcome = ConvexOutcome::Empty;
  std::optional<Polyhedron> polyhedron;  // Bounded only
  // Signed angle (radians) of the recession cone {d : inward_i . d >= 0}:
  // < 0 shut (bounded) by that angle, >= 0 open (unbounded). For Unbounded,
  // `open_direction` is a unit direction in which the block never ends.
  double recession_margin = 0;
  Eigen::Vector3d open_direction = Eigen::Vector3d::Zero();
  // Input indices (into the half-space list) of planes that bound no face:
  // they touch the block at most along an edge or at a corner, or miss it.
  std::vector<int> redundant;
  // Input indices of planes moved (along their normals, by at most the
  // survey's precision) so that four or more meet in one corner, and the
  // largest move (m).
  std::vector<int> snapped;
  double snap_move = 0;
};

// The intersection of the half-spaces: a box around its corners cut by each
// half-space in turn (core/blocks/convex_clipping.h), so that its faces stay
// consistent however close its corners come. Corners where four or more
// planes meet (exactly or within kVertexMergeRel x block size) become one
// vertex; corners further apart are joined by a short edge.
// survey_precision (m, 0: none) ties that to how well the planes' points
// are known: four or more planes that pass within it of one corner of the
// block (and within kSurveySnapRel x size) are moved along their normals,
// each by at most that, to pass through their least-squares point, so they
// meet in one vertex whatever the survey's rounding; `snapped` says which.
// Planes that miss each other by more keep their places. Throws
// InputError naming the block for fewer than 4 half-spaces or a plane with a
// zero normal; unbounded or empty input is an outcome, not an error. Throws
// Error naming the block in the unforeseen case that the cuts do not close
// (callers report that block alone and go on).
ConvexConstruction build_convex_block(const std::string& block_id,
                                      const std::vector<HalfSpaceInput>& halfspaces,
                                      const Eigen::Vector3d& datum = Eigen::Vector3d::Zero(),
                                      double survey_precision = 0);

// A face of a block given by vertices: the plane it lies on and its loop.
struct FaceInput {
  int index = -1;    // caller's plane index
  std::string name;  // caller's plane id
  PlaneKind kind = PlaneKind::Joint;
  // Upward normal of the named plane (from its orientation), if known: it
  // fixes the half-space code of the face. Without it the code refers to
  // the face's fitted normal turned upward.
  std::optional<Eigen::Vector3d> reference_normal;
  std::vector<int> loop;  // counter-clockwise seen from outside
};

// A possibly non-convex block from vertices (datum-relative) and face loops.
// Each face's plane is fitted to its vertices; faces naming the same plane
// that are coplanar and on the same side share one BlockPlane. Validated as
// in Polyhedron::assemble (errors name the block and the face by its index
// and plane id, or the vertex).
Polyhedron build_block_from_faces(const std::string& block_id,
                                  std::vector<Eigen::Vector3d> vertices,
                                  const std::vector<FaceInput>& faces,
                                  const Eigen::Vector3d& datum = Eigen::Vector3d::Zero(),
                                  double planarity_tolerance = -1);

}  // namespace rockface::blocks

#pragma once
// Corner and edge rotatability of any polyhedral block (Mauldon & Goodman's
// vector analysis, generalised to any number of faces after Tonon).
//
// An infinitesimal rotation by angle w > 0 about the axis through a static
// point R with unit direction u (right-hand sense) moves a corner C by
// w u x (C - R). It is feasible at C when the motion does not enter the
// rock behind any joint through C: (u x (C - R)) . n >= 0 for the block-side
// normal n of each such joint, that is u . ((C - R) x n) >= 0. So every
// (corner, joint) pair gives a limit plane through the origin of axis space
// with normal n x (R - C) (normalised), and the rotation space of R, the set
// of feasible axis directions u, is the cone of all limit half-spaces: a
// geometry::Cone, with the same exact angular margin as the joint pyramids.
// Free faces constrain nothing; a corner on free faces only gives no limit
// plane.
//
// Decisions where the vector formula degenerates:
//   - C - R parallel to n (R straight above C on the block side of the
//     joint): u x (C - R) is tangent to the joint for every u, and the
//     second-order displacement w^2/2 u x (u x (C - R)) has the component
//     |C - R| (1 - (u . n)^2) >= 0 along n: the corner lifts off. The limit
//     plane is void (dropped). Where C - R is within the orientation
//     uncertainty of n, the limit plane's orientation is not determined by
//     the measurements: the verdict is computed with it and flagged marginal
//     when dropping it would change the verdict.
//   - Corners on the rotation axis do not move: no limit plane.
//
// Static points are the corners on the boundary between joints and free
// faces. The block is corner-rotatable about R when the rotation space of R
// has an interior (margin > 0). It is edge-rotatable about an edge R1 R2 of
// that boundary when one sense u of the edge direction satisfies the limit
// planes of every corner off the axis: u lies in the rotation spaces of both
// end corners (the limit planes of R2 seen from R1 contain u exactly, and
// vice versa, so they are left out rather than counted as tight). Its margin
// is how far u is inside the remaining half-spaces.
//
// Sliding rotation: rotation about the block-side normal n_J of a joint J
// through R turns the face J in its own plane, so the block keeps sliding
// contact with J (and with any joint parallel to J). n_J lies on the limit
// planes of J's own corners by construction, so the verdict is decided by
// the other limit planes: n_J inside all of them (margin > 0) means the
// rotation space contains n_J and the block can rotate while sliding on J.
//
// Margins are in radians: how far the axis direction can tilt and stay
// feasible (> 0) or how far every limit half-space would have to open (< 0).
// Verdicts come from geometry::decide with the orientation uncertainty.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/cone.h"
#include "core/geometry/verdict.h"
#include "core/kinematics/rotation_input.h"

namespace rockface::kinematics {

// One limit half-space u . normal >= 0 of a rotation space.
struct LimitPlane {
  int corner = -1;                                   // the constrained corner C
  int plane = -1;                                    // the joint through C
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit: (C - R) x n normalised
  // sin of the angle between C - R and the joint's normal: how well the
  // limit plane's orientation is determined (0: void).
  double conditioning = 0;
};

// The limit planes for rotation about an axis through `pivot` (any point):
// one per (corner, joint through it), skipping corners listed in `exclude`,
// corners within kOnAxisRel x size of the pivot, and void limit planes.
// `void_count`, when given, receives the number of void limit planes.
std::vector<LimitPlane> limit_planes(const RotationInput& in, const RotationTopology& topology,
                                     const Eigen::Vector3d& pivot,
                                     const std::vector<int>& exclude = {},
                                     int* void_count = nullptr);

struct SlidingRotation {
  int plane = -1;  // the joint J through R the block slides on
  geometry::Verdict feasible;
  double signed_margin = 0;       // radians: n_J inside (> 0) or outside the other limit planes
  std::vector<int> also_sliding;  // other joints parallel to J that stay in contact
};

struct CornerRotation {
  int vertex = -1;  // the static point R
  std::vector<LimitPlane> limits;
  geometry::Cone space;      // the rotation space: feasible axis directions u
  double signed_margin = 0;  // radians, of the space (cone margin)
  Eigen::Vector3d best_axis = Eigen::Vector3d::UnitZ();  // the axis direction achieving it
  geometry::Verdict rotatable;
  std::vector<Eigen::Vector3d> extreme_rays;  // edges of the space, where they exist
  std::vector<SlidingRotation> sliding;       // one per joint through R
  int void_limits = 0;                        // limit planes dropped as void
};

struct EdgeRotation {
  std::array<int, 2> vertices{};  // ascending
  // The sense of the edge direction with the better margin (unit; the
  // rotation is right-handed about it).
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double signed_margin = 0;  // radians
  geometry::Verdict rotatable;
};

struct RotationAnalysis {
  std::vector<CornerRotation> corners;  // every static point, by vertex index
  std::vector<EdgeRotation> edges;      // every joint / free-face edge
};

// The rotation space of one corner R (any vertex) and its verdict.
CornerRotation corner_rotation(const RotationInput& in, const RotationTopology& topology,
                               int vertex, double uncertainty_rad);

// Rotation about the line through vertices a and b (normally an edge).
EdgeRotation edge_rotation(const RotationInput& in, const RotationTopology& topology, int a, int b,
                           double uncertainty_rad);

// Corner and edge rotatability of a block about its static points and its
// joint / free-face edges. uncertainty_rad: orientation uncertainty of the
// planes (verdicts inside it are marginal).
RotationAnalysis analyse_rotation(const RotationInput& in, double uncertainty_rad);

// A block that rotates firmly (verdict true and not marginal) about a corner
// or an edge has a rotation axis, so a remote-axis search could not change
// "found" and is skipped (issue 17): the first such corner, else the first
// such edge. `vertex` lies on the axis; for a corner `edge` is {vertex, -1}.
struct FirmAxis {
  bool about_corner = true;
  int vertex = -1;
  std::array<int, 2> edge{-1, -1};
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit
};
std::optional<FirmAxis> firm_corner_or_edge_axis(const RotationAnalysis& rotation);

}  // namespace rockface::kinematics

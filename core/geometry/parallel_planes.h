#pragma once
// Half-spaces on both sides of (nearly) parallel planes: two joints of one
// set bounding a slab. Their cone lies in the planes' common plane, or
// within the hair of an angle the two planes make: its ordinary margin
// (cone.h) is zero or that hair, and its sign - finite or not, removable or
// not - follows the last hundredth of a degree of the measurements, a flip
// a block-theory engineer never makes. Taken as exactly parallel, the pair
// pins the cone to their plane (two pairs of different planes: to the line
// the planes share), and the other half-spaces decide it there, by the
// angle the cone is open or shut within that plane (DESIGN.md, margins;
// core/analysis/README.md, "Joints taken as parallel").
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/cone.h"

namespace rockface::geometry {

// Pairs (i < j) of normals within `tolerance` (radians) of opposite.
std::vector<std::pair<int, int>> opposite_pairs(const std::vector<Eigen::Vector3d>& normals,
                                                double tolerance);

// The planes the pairs stand for, each group of parallel ones once.
struct ParallelReduction {
  // One unit normal per group of planes taken as parallel (a pair's
  // planes, and other pairs within `tolerance` of them).
  std::vector<Eigen::Vector3d> axes;
  // Per normal: one of those planes' (within `tolerance` of an axis, either
  // sense): every direction in the common plane keeps to it.
  std::vector<bool> member;
  double widest = 0;  // radians: the largest angle between two planes of a pair
};
ParallelReduction parallel_reduction(const std::vector<Eigen::Vector3d>& normals,
                                     const std::vector<std::pair<int, int>>& pairs,
                                     double tolerance);

// The cone's margin with the reduction's planes exactly parallel: the
// largest angle min_k asin(n_k . d) over the other half-spaces k, for unit
// d in the plane normal to the one axis (on the line normal to two; pi / 2
// when no other half-space constrains d). Three axes that share no line
// leave only the origin: then, and with no axes, the ordinary margin
// (negative for the shut origin). Normals are normalised here.
ConeMargin margin_with_parallel_planes(const std::vector<Eigen::Vector3d>& normals,
                                       const ParallelReduction& reduction);

}  // namespace rockface::geometry

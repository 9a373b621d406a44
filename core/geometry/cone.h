#pragma once
// Cones through the origin given as intersections of half-spaces n_i . d >= 0
// (plane pyramids in Goodman & Shi's sense: joint, excavation, space and
// rotation pyramids are all Cones).
//
// Emptiness is decided by the angular margin, never by the signs of pairwise
// intersections: the margin is max over unit d of min_i asin(n_i . d), the
// largest angle by which a direction can stay inside every half-space. It is
// positive when the cone has an interior, zero when it is a plane, a line or
// only the origin by a hair, and negative by the angle every half-space would
// have to open for the cone to get an interior. It is continuous in the
// normals, so nearly parallel planes give a small margin, not a flip.
#include <initializer_list>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rockface::geometry {

struct ConeMargin {
  double angle = 0;                                      // radians, see above
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // a unit direction achieving it
  double sine = 1;  // min over the half-spaces of n . direction (angle = its asin)
};

class Cone {
 public:
  Cone() = default;
  // Each normal points into its half-space; it is normalised here. A zero
  // normal has no half-space and throws std::invalid_argument.
  explicit Cone(const std::vector<Eigen::Vector3d>& inward_normals);
  // Normals that are unit already (to rounding, as from v / v.norm()) are
  // taken as they are, without normalising them again; non-finite ones or
  // ones off unit length by more than 1e-12 throw std::invalid_argument.
  static Cone from_unit_normals(std::vector<Eigen::Vector3d> unit_inward_normals);

  void add(const Eigen::Vector3d& inward_normal);
  const std::vector<Eigen::Vector3d>& normals() const { return normals_; }
  bool unconstrained() const { return normals_.empty(); }

  // Intersection: all half-spaces of both.
  Cone intersect(const Cone& other) const;

  // The cone's margin (exact: the optimum of the max-min problem lies where
  // one, two or three half-spaces are equally tight, and all such candidates
  // are evaluated; O(m^4) for m half-spaces, fine for the m <= ~20 of blocks).
  ConeMargin margin() const;

  // min_i asin(n_i . d / |d|): how far d is inside (> 0) or outside (< 0).
  double margin_of(const Eigen::Vector3d& d) const;

  // Extreme rays (unit) of a cone with an interior or a lower-dimensional
  // pointed cone; empty for a shut cone. A cone containing a whole line (one
  // or two half-spaces, parallel planes) has edges only where they exist.
  std::vector<Eigen::Vector3d> edges() const;
  // The same when the caller already has the cone's margin angle (the
  // margin is the costly part: O(m^4) in the number of planes).
  std::vector<Eigen::Vector3d> edges(double known_margin) const;

 private:
  std::vector<Eigen::Vector3d> normals_;
};

// The margin of Cone::margin() for half-spaces added one at a time, for
// searches that grow a set of half-spaces (rotation spaces with many limit
// planes). The optimum lies where one, two or three half-spaces are equally
// tight (the candidates of Cone::margin()), and at the optimum no other
// half-space is tighter than they are. A candidate that another half-space
// cuts below its own tight value (the least of its makers' dot products) by
// more than the rounding of its direction can therefore never be the
// optimum, now or after more half-spaces join (they only cut more): it is
// dropped for good. The live candidates are few (about the facets of the
// normals' convex hull), and a new candidate is usually cut by the first few
// half-spaces it meets, so adding the k-th half-space costs about O(k^2)
// instead of the O(k^4) of a fresh search. The live triples are (about)
// the facets of the convex hull of the normals; a new normal makes new
// facets only with the edges of the facets it sees (the horizon, as in an
// incremental convex hull), so only those pairs make new triples. The margin is Cone::margin()'s
// for the same half-spaces to rounding; where candidates tie, the direction
// may be another one of equal margin.
class IncrementalMargin {
 public:
  void add(const Eigen::Vector3d& inward_normal);  // normalised here; zero throws
  // Back to no half-spaces, keeping the memory (for searches run many times).
  void clear();
  ConeMargin margin() const;
  // margin() without its angle (left 0) for searches that need only the
  // sine and the direction at each step.
  ConeMargin margin_sine() const;
  size_t size() const { return normals_.size(); }

 private:
  struct Candidate {
    Eigen::Vector3d d;
    double value;                // min over the normals of n . d
    double cut;                  // dropped when value < cut (-inf: never)
    int i = -1, j = -1, k = -1;  // the three normals of a triple candidate
  };
  // Evaluates raw against all normals; keeps it unless it is cut. makers:
  // the normals that made it (none: a rare candidate, never dropped).
  // Returns whether it was a candidate at all (not degenerate).
  bool consider(const Eigen::Vector3d& raw, std::initializer_list<const Eigen::Vector3d*> makers);
  // Both senses of the triple candidate of normals i, j, k (in the
  // direction raw and its opposite).
  bool consider_triple(const Eigen::Vector3d& raw, int i, int j, int k);
  std::vector<Eigen::Vector3d> normals_;
  std::vector<Candidate> live_;
  std::vector<Eigen::Vector3d> opposite_axes_;  // u of each pair of opposite normals
  // A triple was degenerate (too short a cross product): its face of the
  // hull is not among the candidates, so every pair makes triples from then on.
  bool all_pairs_ = false;
  std::vector<char> edge_;                  // scratch: pairs that make new triples
  std::vector<std::pair<int, int>> pairs_;  // scratch: those pairs, listed
  // While a half-space is added: the margin before it (+ slack); new
  // candidates cut above it are skipped.
  double ceiling_ = std::numeric_limits<double>::infinity();
};

// The margin of Cone::margin() (the same value to rounding), by active sets:
// the exact search on a growing subset of the half-spaces, certified against
// all of them (see cone.cpp). For cones with many half-spaces (rotation
// spaces: ~50) it is far cheaper than the O(m^4) search; up to
// `direct_up_to` half-spaces the direct search is used.
ConeMargin active_set_margin(const Cone& cone, size_t direct_up_to = 12);

// Whether A intersected with the union of the cones B_k is empty (that is,
// A cap B_k is empty for every k). margin > 0: shut by that angle (the least
// shut intersection); margin < 0: open by -margin, through B[open_index].
struct UnionEmptiness {
  bool empty = true;
  double margin = 0;    // radians
  int open_index = -1;  // the B_k whose intersection with A is most open
};
UnionEmptiness intersection_with_union_empty(const Cone& a, const std::vector<Cone>& b);

}  // namespace rockface::geometry

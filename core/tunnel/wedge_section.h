#pragma once
// The excavation's cross-section as the wedge search sees it: the design
// profile (design_profile.h) drawn as a convex polygon in (u, v), arcs as
// chords of bounded sagitta, each edge knowing the profile segment it lies
// on, each vertex whether it is a corner of the design (where the outline
// turns, e.g. a horseshoe's wall meeting its invert) and its arc length.
//
// The excavation is the prism of this polygon along the tunnel's axis. A
// wedge is a block of rock outside the prism, so a re-entrant (non-convex)
// part of a profile cannot hold a wedge face: such a profile is replaced by
// its convex hull, and the section says so in its notes. Lines drawn in
// many pieces with no corner between them (a circle as 5000 chords) are
// merged into chords of the given sagitta, as an arc is drawn (noted).
// The chords keep the profile's own straight joins and corners.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/design_profile.h"

namespace rockface::tunnel {

struct SectionVertex {
  Eigen::Vector2d p{0, 0};  // (u, v), m
  std::size_t segment = 0;  // profile segment of the edge that starts here
  bool corner = false;      // the design outline turns here (kWedgeCornerRad)
  double s = 0;             // arc length along the polygon from vertex 0
  // A chord that replaces lines of several profile segments (merged, see
  // below): where along it (0..1 from this vertex) each later segment
  // begins, and that segment.
  std::vector<std::pair<double, std::size_t>> joins;
};

struct SectionPolygon {
  std::vector<SectionVertex> vertices;     // counter-clockwise; edge i: vertex i -> i + 1
  std::vector<std::string> segment_kinds;  // per profile segment: "line" or "arc"
  double perimeter = 0;
  bool hull_used = false;
  std::vector<std::string> notes;

  std::size_t size() const { return vertices.size(); }
  const Eigen::Vector2d& at(std::size_t i) const { return vertices[i % size()].p; }
  // Unit outward normal of edge i (toward the rock).
  Eigen::Vector2d outward_normal(std::size_t i) const;
  // Distance from a point outside to the polygon.
  double distance(const Eigen::Vector2d& q) const;
  bool contains(const Eigen::Vector2d& q) const;
  // The profile segments under the part of edge i from a to b (points on
  // it): one, or several where the edge is a merged chord.
  std::vector<std::size_t> segments_under(std::size_t i, const Eigen::Vector2d& a,
                                          const Eigen::Vector2d& b) const;
};

// Throws InputError(where, ...) for a profile that does not validate or
// encloses no area. sagitta_m: the largest gap between an arc and its chords.
SectionPolygon section_polygon(const DesignProfile& profile, double sagitta_m,
                               const std::string& where);

}  // namespace rockface::tunnel

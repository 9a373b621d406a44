#pragma once
// The phases of analyse_wedges (wedge_analysis.h), each a function of its
// own input, declared here so that each can be read and tested on its own:
//   1. check_sets: three sets or more, each with an orientation;
//      distinct_sets: sets within the uncertainty of each other are one;
//   2. face_excavation_pyramid: the face's EP (rock ahead of it);
//   3. for each three sets: parallel_sets (they bound no pyramid), then
//      for each of the eight pyramids set_pyramid, and face_wedge or
//      perimeter_wedge (apex_at_trace_limit, lay_out_on_perimeter);
//   4. order_wedges: roof, walls, floor, face, each by volume.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/cone.h"
#include "core/kinematics/effects/effect.h"
#include "core/tunnel/wedge_analysis.h"
#include "core/tunnel/wedge_geometry.h"

namespace rockface::tunnel::wedge_phases {

// What every wedge of one analysis reads.
struct Context {
  const SectionPolygon& section;
  const TunnelFrame& frame;
  const Eigen::Vector3d& datum;
  const std::vector<WedgeJointSet>& sets;
  const WedgeOptions& options;
  const kinematics::Effects& loads;
  Eigen::Vector2d centre;  // of the profile's rays
};

// Throws InputError for fewer than three sets ("sets") or one without an
// orientation ("sets[i]").
void check_sets(const std::vector<WedgeJointSet>& sets);

// The sets that differ: a set whose pole lies within the orientation
// uncertainty (at least kWedgeSameSetRad) of an earlier set's is that set
// (listed twice, or measured twice) and is left out, said in notes.
// Throws InputError ("sets") for fewer than three distinct sets or more
// than kMaxWedgeSets (support_ranges.h).
struct DistinctSets {
  std::vector<int> kept;  // indices into sets, in their order
  std::vector<std::string> notes;
};
DistinctSets distinct_sets(const std::vector<WedgeJointSet>& sets, double uncertainty);

// The face's excavation pyramid: the rock lies ahead of it, along the drive.
geometry::Cone face_excavation_pyramid(const TunnelFrame& frame);

// The code of n sets with the sets idx on the sides of sign (> 0: upper,
// '0'), the others not involved ('2').
std::string code_text(std::size_t n, const std::vector<int>& idx, const std::vector<double>& sign);

// Why sets idx (three) bound no pyramid, when two are parallel or all
// three meet in one line (the triple product under sin(uncertainty) 1e-3).
std::optional<NoWedge> parallel_sets(const std::vector<WedgeJointSet>& sets,
                                     const std::array<int, 3>& idx, double uncertainty);

// The pyramid of sets idx on the sides of sign (+1: upper): its planes,
// their inward normals and its code.
struct SetPyramid {
  std::vector<int> idx;
  std::vector<std::string> ids;
  std::vector<double> sign;
  std::vector<WedgePlane> planes;
  std::vector<Eigen::Vector3d> inward;
  std::string code;
};
SetPyramid set_pyramid(const std::vector<WedgeJointSet>& sets, const std::array<int, 3>& idx,
                       int combination);

// A pyramid's wedge, or why there is none; neither when the pyramid is not
// of that kind or the options do not ask for it.
struct FoundWedge {
  std::optional<Wedge> wedge;
  std::optional<NoWedge> none;
};
// A wedge found whose solid could not be made, as an honest marginal "no
// wedge": no margin claimed, the apex's distance from the excavation
// (apex_out, m) and the pyramid's two closest sets with their angle said
// (near-parallel sets are the usual cause: their planes meet at a grazing
// angle far out), and why the solid failed, in words that keep "could not
// be built" (issue 40).
NoWedge unbuilt_wedge(const SetPyramid& p, double apex_out, const std::string& why);

// The largest wedge of a pyramid that opens toward the tunnel, on the face.
FoundWedge face_wedge(const Context& c, const SetPyramid& p,
                      const std::vector<Eigen::Vector3d>& edges, const geometry::Cone& face_ep);
// The largest wedge of a pyramid around the perimeter (scaled down to the
// trace-length limit); jp_margin: the joint pyramid's margin (radians).
FoundWedge perimeter_wedge(const Context& c, const SetPyramid& p,
                           const std::vector<Eigen::Vector3d>& edges, double jp_margin);

// The apex on the way from the base's middle to q_max (the largest
// wedge's) at which the longest trace is the limit (bisection: first to
// the outline, then to kWedgeTraceRel); longest_trace_at(q): the wedge's
// longest trace with its apex at q.
Eigen::Vector2d apex_at_trace_limit(
    const SectionPolygon& section, const std::vector<BasePiece>& base, const Eigen::Vector2d& q_max,
    double limit, const std::function<double(const Eigen::Vector2d&)>& longest_trace_at);

// A perimeter wedge's face on the section, apex q: its outline, the
// profile's segments and corners it spans; returns the length-weighted
// centre of its face.
Eigen::Vector2d lay_out_on_perimeter(const SectionPolygon& section,
                                     const std::vector<BasePiece>& base, const Eigen::Vector2d& q,
                                     Wedge& w);

// Roof, right wall, left wall, floor, face; each by falling volume (the
// caller names them W1, W2, ... in that order).
void order_wedges(std::vector<Wedge>& wedges);

// Length of each joint's trace on the excavation (edges between a joint
// face and a free face), in the order of the block's planes; the longest.
std::vector<std::pair<std::string, double>> traces_of(const blocks::Polyhedron& b);
double longest(const std::vector<std::pair<std::string, double>>& t);

// The place around the section of a wedge at angle_deg (0 right, 90 up).
WedgePlace place_of(double angle_deg);

// Mass, mode, factors of safety and support of a built wedge
// (wedge_verdict.cpp).
void analyse_wedge(const Context& c, Wedge& w, const std::vector<WedgePlane>& planes,
                   const Eigen::Vector3d& apex_local);

}  // namespace rockface::tunnel::wedge_phases

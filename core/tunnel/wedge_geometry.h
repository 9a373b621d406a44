#pragma once
// The shapes of the wedges around an excavation, on block theory: for one
// joint pyramid JP (three joint half-spaces, core/kinematics/joint_pyramids.h)
// the block is the apex plus JP, cut by the excavation:
//
// - Perimeter wedges. The excavation is the prism of the section polygon
//   (wedge_section.h) along the axis. Seen along the axis, JP projects to a
//   sector of the cross-section; a wedge exists only where that sector is
//   narrower than a half-plane (else it would run along the tunnel without
//   end: the margin is half of what the sector lacks of 180 degrees). Each
//   ray of the block from the apex leaves the rock where it meets the
//   excavation, so the block is finite while every ray of the sector hits
//   the section: the largest wedge has both sector edges touching the
//   section (Hoek & Brown's construction, UnWedge's maximum wedge). The
//   wedge is the union of convex pieces, one per excavation facet the
//   sector sees (joints, that facet, and the two planes through the apex
//   and the axis that bound the facet's part), built by
//   core/blocks/construction.h and joined into one polyhedron.
// - Face wedges. JP opening back out of the face (into the tunnel) gives a
//   tetrahedron on the face plane: its largest size is the largest triangle
//   of JP's shape on the face that fits inside the section.
//
// Coordinates are datum-relative; the frame's origin is on the axis where
// the section (and the face) lie.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/polyhedron.h"
#include "core/tunnel/alignment.h"
#include "core/tunnel/wedge_section.h"

namespace rockface::tunnel {

// One joint plane of a wedge: its scene index, id, upward unit normal and
// the sign (+1 upper, -1 lower) of the half-space the wedge lies in.
struct WedgePlane {
  int index = -1;
  std::string id;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double sign = 1;
  Eigen::Vector3d inward() const { return sign * normal; }
};

// The projection of JP on the cross-section.
struct PyramidSector {
  bool pointed = false;                // narrower than a half-plane (a perimeter wedge exists)
  double margin = 0;                   // radians: (pi - span) / 2, signed
  double span = 0;                     // radians
  Eigen::Vector2d d1{0, 0}, d2{0, 0};  // unit edge directions, the sector runs CCW d1 -> d2
};
// edges: JP's extreme rays (unit, 3D).
PyramidSector pyramid_sector(const std::vector<Eigen::Vector3d>& edges, const TunnelFrame& frame);

// One piece of a perimeter wedge's face on the excavation: from a to b (u, v)
// along polygon edge `edge`.
struct BasePiece {
  Eigen::Vector2d a{0, 0}, b{0, 0};
  std::size_t edge = 0;
};

// The apex (u, v) of the largest perimeter wedge of the sector.
Eigen::Vector2d largest_apex(const SectionPolygon& section, const PyramidSector& sector);
// The part of the section the sector from apex q sees, as pieces ordered
// from the d1 side to the d2 side, each running from its d1 side (a) to its
// d2 side (b): base[k].b is base[k + 1].a.
std::vector<BasePiece> visible_base(const SectionPolygon& section, const PyramidSector& sector,
                                    const Eigen::Vector2d& q);

// The perimeter wedge with apex (q, along-position w) over the given base.
// Free faces are named "E<edge>" with plane index first_free_index + edge.
// Throws std::runtime_error when the pieces do not join into a valid solid.
blocks::Polyhedron perimeter_wedge_block(const std::string& id, const TunnelFrame& frame,
                                         const Eigen::Vector3d& datum,
                                         const std::vector<WedgePlane>& joints,
                                         const SectionPolygon& section,
                                         const std::vector<BasePiece>& base,
                                         const Eigen::Vector2d& q, double w, int first_free_index);

// Face wedges: the triangle JP cuts from the face plane for an apex one
// metre ahead of it (in the rock), its corners (u, v) relative to the
// apex's (u, v); edges as above, each with a negative component along the
// drive (JP opens back into the tunnel).
std::vector<Eigen::Vector2d> face_unit_triangle(const std::vector<Eigen::Vector3d>& edges,
                                                const TunnelFrame& frame);
// The largest scale s and offset t with t + s T_i inside the section.
struct FaceFit {
  double scale = 0;
  Eigen::Vector2d offset{0, 0};
};
FaceFit largest_face_triangle(const SectionPolygon& section,
                              const std::vector<Eigen::Vector2d>& unit_triangle);
// The face wedge: apex at (offset, depth `scale` ahead of the face); the
// face plane (rock ahead) is named "face" with plane index face_index.
blocks::Polyhedron face_wedge_block(const std::string& id, const TunnelFrame& frame,
                                    const Eigen::Vector3d& datum,
                                    const std::vector<WedgePlane>& joints, const FaceFit& fit,
                                    int face_index);

}  // namespace rockface::tunnel

#pragma once
// Support of a wedge (UnWedge's pattern bolts and shotcrete) and its
// factor of safety with support.
//
// Pattern bolts: a square pattern of the given spacing over the excavation
// surface (developed along the section polygon's outline and the axis; the
// pattern is centred on the crown and the section's origin), each bolt
// normal to the surface, into the rock. A bolt whose head lies on a wedge's
// exposed face acts on it as core/kinematics' BoltEffect with its capacity,
// but only if it reaches past the wedge: its length beyond the point where
// it leaves the wedge through a joint face is its anchorage, and a bolt
// without anchorage (shorter than the wedge is deep along it) holds nothing.
// Where a bond strength is given, the capacity is also limited to the bond
// strength times the anchorage (pull-out).
//
// Factor of safety with support (UnWedge's passive support): the wedge's
// failure mode is that of the wedge under its loads (gravity, water,
// seismic; core/kinematics/sliding_mode.h). Support does not change the
// mode; it resists it. With the loads' resultant r, the support's resultant
// S and the mode's direction s and sliding planes (block-side normals n_i):
//   falling / lifting:  FoS = (-S . s) / (r . s)
//   sliding:            r + S = t s - sum N_i n_i  (N_i >= 0, a plane the
//                       support lifts off carries nothing)
//                       FoS = (sum N_i tan(phi_i) + c_i A_i - S . s) / (r . s)
// Without support these are sliding_mode's factors of safety.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/polyhedron.h"
#include "core/kinematics/sliding_mode.h"
#include "core/tunnel/alignment.h"
#include "core/tunnel/wedge_section.h"

namespace rockface::tunnel {

// Where on the excavation a support is installed.
struct SupportPlaces {
  bool roof = true, walls = true, floor = false, face = false;
};

struct PatternBolts {
  double length = 0;                    // m
  double spacing = 0;                   // m, square pattern
  double capacity = 0;                  // N per bolt (tensile / plate)
  std::optional<double> bond_strength;  // N per m of anchorage; none: not limiting
  SupportPlaces places;
};

struct Shotcrete {
  double thickness = 0;       // m
  double shear_strength = 0;  // Pa
  SupportPlaces places{true, true, false, true};
};

// One bolt of the pattern that meets a wedge.
struct WedgeBolt {
  Eigen::Vector3d head = Eigen::Vector3d::Zero();       // absolute
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // unit, into the rock
  double depth_in_wedge = 0;                            // m, head to where it leaves the wedge
  double anchorage = 0;                                 // m beyond the wedge (<= 0: none)
  double force = 0;                                     // N it holds (0 when not anchored)
};

// The place of an outline edge by its outward normal: "roof" (within 45
// degrees of up), "floor" (of down), else "walls".
bool supports_edge(const SupportPlaces& places, const Eigen::Vector2d& outward_normal);

// The pattern's bolts whose heads lie on the wedge's exposed faces.
// apex / inward: the wedge's apex and its joints' block-side normals
// (datum-relative), to find where each bolt leaves it. face_wedge: the
// pattern on the face plane instead of the perimeter.
std::vector<WedgeBolt> pattern_bolts_on_wedge(const PatternBolts& bolts,
                                              const blocks::Polyhedron& wedge,
                                              const SectionPolygon& section,
                                              const TunnelFrame& frame, bool face_wedge,
                                              const Eigen::Vector3d& apex,
                                              const std::vector<Eigen::Vector3d>& inward);

struct SupportedFos {
  std::optional<double> fos;       // none: a sliding plane has no friction angle
  std::vector<int> lifted_planes;  // sliding planes the support lifts off
};
// contacts: the wedge's joint contacts (block_contacts); loads: the loads'
// resultant; support: the support's resultant (N).
SupportedFos supported_fos(const kinematics::SlidingMode& mode,
                           const std::vector<kinematics::ContactPlane>& contacts,
                           const Eigen::Vector3d& loads, const Eigen::Vector3d& support);

}  // namespace rockface::tunnel

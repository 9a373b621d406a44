#pragma once
// Wedges around an excavation (UnWedge's question, answered with block
// theory): for an excavation of a given cross-section and axis and three or
// more joint sets, every removable wedge that three of the sets form with
// the roof, the walls, the floor and the face, at its largest size for
// joints of unlimited persistence (or scaled down to a trace-length limit),
// with its volume, weight, apex height, joint pyramid code, failure mode,
// limit-equilibrium factor of safety under the loads asked for (gravity,
// water, seismic) and the support asked for (pattern bolts, shotcrete), and
// the bolt length that reaches past its apex.
//
// Every triple of sets and each of its 2^3 joint pyramids is tried
// (core/kinematics/joint_pyramids.h decides emptiness and, on the face,
// removability; wedge_geometry.h gives the wedge; core/kinematics'
// analyse_block its mass, mode and factor of safety; wedge_support.h the
// support). A pyramid that gives no wedge for a reason the geologist should
// see (a set along the axis, parallel sets) is listed with the reason.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/mass_properties.h"
#include "core/blocks/polyhedron.h"
#include "core/common/preset.h"
#include "core/geometry/verdict.h"
#include "core/kinematics/sliding_mode.h"
#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/wedge_section.h"
#include "core/tunnel/wedge_support.h"

namespace rockface::tunnel {

struct WedgeJointSet {
  std::string id;                                     // "J1", "S2"
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit upward normal
  std::optional<double> friction;                     // radians
  double cohesion = 0;                                // Pa
};

struct WedgeWater {
  double unit_weight = 9810;                                   // N/m^3
  Eigen::Vector3d phreatic_point = Eigen::Vector3d::Zero();    // absolute
  Eigen::Vector3d phreatic_normal = Eigen::Vector3d::UnitZ();  // upward unit
  std::vector<int> sets;                                       // set indices; empty: all
};

struct WedgeOptions {
  double density = 2700;                 // kg/m^3
  Eigen::Vector3d gravity{0, 0, -9.81};  // m/s^2
  std::optional<WedgeWater> water;
  std::optional<Eigen::Vector3d> seismic;  // m/s^2, pseudo-static
  std::optional<PatternBolts> bolts;
  std::optional<Shotcrete> shotcrete;
  std::optional<double> trace_length_limit;   // m
  bool perimeter = true, face = true;         // which wedges to look for
  double uncertainty = 0.017453292519943295;  // radians (1 degree)
  double sagitta_m = 0.002;                   // chords of the profile's arcs
};

// The chords' sagitta of each preset (the knob beside its component, issue
// 37): fast 10 mm, standard 2 mm, precise 0.5 mm (docs/accuracy-cost.md,
// "Wedges around the excavation").
double wedge_sagitta(Preset preset);

enum class WedgePlace { roof, right_wall, left_wall, floor, face };
const char* wedge_place_name(WedgePlace p);  // "roof", "right wall", ...

struct Wedge {
  std::string id;                 // "W1", in the order of the list
  std::string code;               // one digit per set (2: not involved)
  std::vector<std::string> sets;  // the three sets' ids
  WedgePlace place = WedgePlace::roof;
  double position_deg = 0;  // direction of its face's centre from the section's centre
                            // (counter-clockwise from right, looking along the drive)
  blocks::Polyhedron block;
  blocks::MassProperties mass;
  double weight = 0;                               // N
  Eigen::Vector3d apex = Eigen::Vector3d::Zero();  // absolute
  double apex_height = 0;          // m, apex above the chord of its face (perimeter) / the face
  double bolt_length_to_apex = 0;  // m, from the excavation to the apex along the normal
  double face_area = 0;            // m^2, on the excavation
  double face_perimeter = 0;       // m, outline of that face
  std::vector<std::pair<std::string, double>> trace_lengths;  // per set, m on the excavation
  bool scaled = false;          // scaled down to the trace-length limit
  double scale = 1;             // linear size against the largest wedge
  geometry::Verdict removable;  // with its margin (radians)
  std::optional<kinematics::SlidingMode> mode;
  std::optional<double> fos;            // with the loads, without support
  std::optional<double> fos_supported;  // with the support asked for
  // The loads' resultant (N) and the joint contacts its modes were found
  // with: what another support is checked against (core/analysis'
  // support check) without building the wedge again.
  Eigen::Vector3d load_resultant = Eigen::Vector3d::Zero();
  std::vector<kinematics::ContactPlane> contacts;
  std::vector<std::string> effects_used;  // what acted on it
  std::vector<WedgeBolt> bolts;           // pattern bolts on its face
  int bolts_anchored = 0;
  double bolt_force = 0;        // N, sum of the anchored bolts'
  double shotcrete_force = 0;   // N
  double support_pressure = 0;  // Pa, support force over the face area
  double weight_pressure = 0;   // Pa, weight over the face area
  // Seen along the axis (u, v): perimeter wedges the apex and then their
  // face's outline from one end to the other; face wedges their triangle
  // on the face.
  std::vector<Eigen::Vector2d> outline;
  std::vector<std::size_t> segments;  // profile segments its face lies on
  std::vector<std::string> corners;   // the profile's corners it spans, in words
  std::vector<std::string> notes;
};

struct NoWedge {
  std::string code;
  std::vector<std::string> sets;
  double margin = 0;  // radians, signed (<= 0: no wedge); 0 when unbuilt
  std::string reason;
  // Its wedge was found but its solid could not be built: no margin is
  // claimed for it, and it is marginal (issue 40).
  bool unbuilt = false;
  // The margin is inside the orientation uncertainty (or the wedge is
  // unbuilt): whether there is a wedge is in doubt.
  bool marginal = false;
};

struct WedgeAnalysis {
  SectionPolygon section;
  TunnelFrame frame;
  std::vector<Wedge> wedges;  // roof, right wall, left wall, floor, face; each by volume
  std::vector<NoWedge> none;
  std::vector<std::string> effects_simulated;
  std::vector<std::string> notes;
};

// frame: the section at the origin (datum-relative), the drive along
// frame.along; datum: absolute position of the frame's coordinates' origin.
// The wedges' blocks are built about the section (their datum() is
// datum + frame.origin, their vertices relative to it), so the same
// section gives the same wedges at the datum and 10^6 m away from it;
// apexes and bolt heads are absolute.
// Throws InputError naming the field for fewer than three sets ("sets"), a
// degenerate profile ("profile"), a bad support value.
WedgeAnalysis analyse_wedges(const DesignProfile& profile, const TunnelFrame& frame,
                             const Eigen::Vector3d& datum, const std::vector<WedgeJointSet>& sets,
                             const WedgeOptions& options);

// The tunnel frame of an axis given by trend and plunge (radians, plunge
// positive down) through `origin` (datum-relative). Throws InputError(where)
// for a vertical axis.
TunnelFrame axis_frame(double trend, double plunge, const Eigen::Vector3d& origin,
                       const std::string& where);

}  // namespace rockface::tunnel

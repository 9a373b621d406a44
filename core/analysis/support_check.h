#pragma once
// The check of a support class on this face (issue 44): the class's
// pattern (bolts, shotcrete) on the wedges around the excavation, and its
// face support on the face's blocks that move.
//
// Wedges: the wedge analysis is run with the class's pattern
// (with_class_support; core/tunnel/wedge_support.h counts each bolt that
// reaches past the wedge and its shotcrete), and the wedges of the face a
// second time with the class's face support (with_class_face_support: the
// face bolts along the drive and the face shotcrete, on the face only; a
// face wedge's exposed face is the face, which the pattern of the roof and
// walls does not reach). Each removable wedge gets its
// FoS with the support, whether the bolts reach past its apex, the bolt
// length that would (the apex's depth plus kMinBoltAnchorageM, or the bond
// length of the bolt's capacity when a bond strength is given), and the
// capacity per bolt at the class's spacing that would bring it to the
// target FoS with every bolt on it anchored. A wedge left below the target
// is flagged with what would fix it.
//
// Blocks: a block of the face that moves (a removable block with a mode)
// under the class's face bolts (along the drive, into the rock) and face
// shotcrete. The bolts are loads as core/kinematics' BoltEffect applies
// them (force along the bolt; the stored block has no polyhedron to hand
// the effect itself), as many as the pattern puts on its exposed
// face (area / spacing^2, whole bolts), each holding only when it reaches
// past the block; the shotcrete is ShotcreteEffect's capacity over the
// outline of the exposed face, against the block's motion. The FoS with
// support is wedge_support's passive-support FoS (the mode is the
// unsupported block's).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/analysis/support_classes.h"
#include "core/kinematics/sliding_mode.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::analysis {

// Anchorage a bolt needs beyond the wedge or block it holds when no bond
// strength says more: 1 m, the common rule of thumb for bolts through a
// wedge (a grouted bar develops its capacity over well under a metre in
// sound rock; the metre covers the apex's uncertainty and a loosened zone).
inline constexpr double kMinBoltAnchorageM = 1.0;

struct WedgeSupportCheck {
  std::string id, place;  // "W3", "roof"
  double volume_m3 = 0, weight_n = 0;
  double apex_depth_m = 0;  // along the bolts, from the excavation
  std::string mode;         // "falling", "sliding", ...
  std::optional<double> fos_unsupported, fos_supported;
  int bolts = 0, bolts_anchored = 0;
  bool bolts_reach_past_apex = true;
  double required_bolt_length_m = 0;
  // Per bolt at the class's spacing, every bolt on it anchored; none when
  // no capacity reaches the target (or no bolt lies on it).
  std::optional<double> required_capacity_n;
  bool below_target = false;
  std::vector<std::string> fixes;
};

// A block of the face that moves, as the block analysis left it.
struct MovingBlock {
  std::string id;
  kinematics::SlidingMode mode;                     // without support
  std::vector<kinematics::ContactPlane> contacts;   // its sliding planes (mode.planes' indices)
  Eigen::Vector3d loads = Eigen::Vector3d::Zero();  // active resultant without support, N
  std::optional<double> fos;                        // without support
  double exposed_area_m2 = 0;
  double exposed_outline_m = 0;  // 0: unknown (face shotcrete not counted)
  Eigen::Vector3d bolt_direction = Eigen::Vector3d::UnitY();  // unit, into the rock
  double depth_m = 0;  // the block's extent along bolt_direction from its exposed face
};

struct BlockSupportCheck {
  std::string id;
  std::string mode;
  std::optional<double> fos_unsupported, fos_supported;
  int bolts = 0, bolts_anchored = 0;
  double bolt_force_n = 0, shotcrete_force_n = 0;
  double required_bolt_length_m = 0;
  // The face support along the bolts (N, in total) that brings it to the
  // target; none when no force along the bolts does.
  std::optional<double> required_face_force_n;
  bool below_target = false;
  std::vector<std::string> fixes, notes;
};

struct SupportCheck {
  std::string class_name;
  double target_fos = kDefaultTargetFos;
  std::vector<WedgeSupportCheck> wedges;
  std::vector<BlockSupportCheck> blocks;
  int below_target = 0;  // wedges and blocks
  std::vector<std::string> notes;
};

// The wedge options with the class's pattern bolts and shotcrete (roof and
// walls) in place of base's support.
tunnel::WedgeOptions with_class_support(tunnel::WedgeOptions base, const SupportClass& c);

// The wedge options with the class's face support (its face bolts and face
// shotcrete, on the face only) in place of base's support, and only the
// face's wedges looked for. Whether the class has any face support to
// count: has_face_support.
tunnel::WedgeOptions with_class_face_support(tunnel::WedgeOptions base, const SupportClass& c);
bool has_face_support(const SupportClass& c);

// w: a wedge of the analysis run with with_class_support's options, or a
// face wedge of the one run with with_class_face_support's; a face wedge is
// checked against the class's face bolts, the others against its pattern.
WedgeSupportCheck check_wedge(const tunnel::Wedge& w, const SupportClass& c);

BlockSupportCheck check_block(const MovingBlock& b, const SupportClass& c);

// Both, with the count below the target. face_supported: the face wedges
// with the class's face support (with_class_face_support's run); a face
// wedge of `supported` is checked as it stands there (matched by its sets
// and code), and without it when the class has face support and that run
// is missing (said in the notes).
SupportCheck check_support(const SupportClass& c, const tunnel::WedgeAnalysis* supported,
                           const std::vector<MovingBlock>& blocks,
                           const tunnel::WedgeAnalysis* face_supported = nullptr);

}  // namespace rockface::analysis

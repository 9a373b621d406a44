#pragma once
// What the block is doing on its contacts, in the words of the report:
// which joint surfaces carry it, and whether the loaded contacts span a
// face (sliding on one or two planes), lie on one line (rotation about an
// edge) or at one point (rotation about a corner); no loaded contact is
// free fall, all contacts sticking with the block still is rest.
#include <string>
#include <vector>

#include "core/mechanics/dynamics/block_motion.h"

namespace rockface::mechanics {

enum class ModeKind { FreeFall, Sliding, Edge, Corner, Rest };

struct ContactMode {
  ModeKind kind = ModeKind::FreeFall;
  std::vector<std::string> planes;  // joint surfaces in contact, scene order
  std::string pivot;                // "J2-J3" for an edge, the corner's planes for a corner
  bool operator==(const ContactMode& o) const {
    return kind == o.kind && planes == o.planes && pivot == o.pivot;
  }
  bool operator!=(const ContactMode& o) const { return !(*this == o); }
  // "slides on J1 and J2", "rotates about edge J2-J3", "free fall", ...
  std::string describe() const;
};

ContactMode contact_mode(const BlockMotion& motion, const BlockPose& pose,
                         const BlockVelocity& velocity, const ContactSolution& solution);

}  // namespace rockface::mechanics

#include "core/mechanics/dynamics/contact_mode.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/mechanics/dynamics/tolerances.h"

namespace rockface::mechanics {

namespace {

std::string joined(const std::vector<std::string>& names, const char* sep) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) out += (i ? sep : "") + names[i];
  return out;
}

double line_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                     const Eigen::Vector3d& dir) {
  const Eigen::Vector3d d = p - a;
  return (d - d.dot(dir) * dir).norm();
}

}  // namespace

std::string ContactMode::describe() const {
  switch (kind) {
    case ModeKind::FreeFall:
      return "free fall";
    case ModeKind::Rest:
      return "at rest on " + joined(planes, " and ");
    case ModeKind::Sliding:
      return "slides on " + joined(planes, " and ");
    case ModeKind::Edge:
      // A pivot that is no edge of the block or the rock is said as a line.
      return pivot.rfind("a line", 0) == 0 ? "rotates about " + pivot
                                           : "rotates about edge " + pivot;
    case ModeKind::Corner:
      return "rotates about a corner (" + pivot + ")";
  }
  return "?";
}

ContactMode contact_mode(const BlockMotion& motion, const BlockPose& pose,
                         const BlockVelocity& velocity, const ContactSolution& solution) {
  ContactMode mode;
  const double length = motion.length();
  const double loaded = kLoadedForceRel * motion.load_scale();
  const auto& surfaces = motion.geometry().surfaces();
  std::vector<Eigen::Vector3d> points;
  std::vector<int> point_surface;
  std::set<int> in_contact;
  std::vector<double> per_surface(surfaces.size(), 0.0);
  bool slipping = false;
  for (size_t i = 0; i < solution.contacts.size(); ++i) {
    per_surface[solution.contacts[i].surface] += solution.normal[i];
    if (solution.normal[i] <= loaded) continue;
    points.push_back(solution.contacts[i].point);
    point_surface.push_back(solution.contacts[i].surface);
    slipping = slipping || solution.slipping[i];
  }
  for (size_t s = 0; s < surfaces.size(); ++s)
    if (per_surface[s] > loaded) {
      in_contact.insert(static_cast<int>(s));
      mode.planes.push_back(surfaces[s].name);
    }
  if (points.empty()) {  // free fall
    mode.planes.clear();
    return mode;
  }
  const double rest = kRestSpeedRel * std::sqrt(motion.gravity() * length);
  const double speed = velocity.v.norm() + velocity.w.norm() * length;
  const double accel = solution.acceleration.norm() + solution.angular_acceleration.norm() * length;
  if (!slipping && speed <= 10 * rest && accel <= kLcpRel * 1e3 * motion.gravity()) {
    mode.kind = ModeKind::Rest;
    return mode;
  }
  // Spread of the loaded points: one point, one line, or a face.
  const double tol = kPivotSpreadRel * length;
  size_t far = 0;
  double far_d = 0;
  for (size_t i = 0; i < points.size(); ++i)
    if ((points[i] - points[0]).norm() > far_d) {
      far_d = (points[i] - points[0]).norm();
      far = i;
    }
  if (far_d <= tol) {
    mode.kind = ModeKind::Corner;
    mode.pivot = joined(mode.planes, ", ");
    (void)pose;
    return mode;
  }
  const Eigen::Vector3d dir = (points[far] - points[0]) / far_d;
  bool on_line = true;
  for (const auto& p : points) on_line = on_line && line_distance(p, points[0], dir) <= tol;
  if (!on_line) {
    mode.kind = ModeKind::Sliding;
    return mode;
  }
  // A block turning about an edge turns with its angular velocity along
  // the edge; one whose points still lie on a line but that turns away
  // from it is lifting off that line's far end: it turns about a corner.
  const double turning = velocity.w.norm() * length;
  if (turning > 10 * rest && std::abs(velocity.w.normalized().dot(dir)) < std::cos(kAxisAngleRad)) {
    mode.kind = ModeKind::Corner;
    mode.pivot = joined(mode.planes, ", ");
    return mode;
  }
  mode.kind = ModeKind::Edge;
  // The line the loaded points lie on names the edge: an edge of a loaded
  // surface's face (the rock's lip, or the block's own edge on it) whose
  // points all lie on it. Two loaded surfaces alone do not make their
  // line of intersection the pivot: a block pivoting over the lip of J1
  // at the face still carries a little on J2's corner (issue 39: "rotates
  // about edge J1-J2" while it turned about J1's edge at the face).
  for (const int si : in_contact) {
    const JointSurface& s = surfaces[si];
    for (size_t pi = 0; pi < s.polygons.size(); ++pi)
      for (size_t k = 0; k < s.polygons[pi].size(); ++k) {
        const Eigen::Vector2d a2 = s.polygons[pi][k];
        const Eigen::Vector2d b2 = s.polygons[pi][(k + 1) % s.polygons[pi].size()];
        const Eigen::Vector3d a = s.origin + a2(0) * s.e1 + a2(1) * s.e2;
        const Eigen::Vector3d b = s.origin + b2(0) * s.e1 + b2(1) * s.e2;
        const Eigen::Vector3d e = (b - a).normalized();
        bool all = true;
        for (const auto& p : points) all = all && line_distance(p, a, e) <= tol;
        if (!all) {
          const Eigen::Vector3d ba = motion.geometry().vertex(pose, s.loops[pi][k]);
          const Eigen::Vector3d bb =
              motion.geometry().vertex(pose, s.loops[pi][(k + 1) % s.loops[pi].size()]);
          const Eigen::Vector3d be = (bb - ba).normalized();
          all = true;
          for (const auto& p : points) all = all && line_distance(p, ba, be) <= tol;
        }
        if (all) {
          mode.pivot = s.name + "-" + s.edge_planes[pi][k];
          return mode;
        }
      }
  }
  // No face edge holds every point: the line where two loaded surfaces
  // meet, when the points' line runs along it.
  for (auto i = in_contact.begin(); i != in_contact.end(); ++i)
    for (auto j = std::next(i); j != in_contact.end(); ++j) {
      const Eigen::Vector3d along = surfaces[*i].normal.cross(surfaces[*j].normal);
      if (along.norm() < 1e-9) continue;
      if (std::abs(along.normalized().dot(dir)) >= std::cos(kPivotAngleRad)) {
        mode.pivot = surfaces[*i].name + "-" + surfaces[*j].name;
        return mode;
      }
    }
  // A line across the loaded surfaces that is none of their edges.
  mode.pivot = "a line across " + joined(mode.planes, " and ");
  return mode;
}

}  // namespace rockface::mechanics

#include "core/tunnel/wedge_support.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <Eigen/Dense>

#include "core/blocks/point_location.h"

namespace rockface::tunnel {

namespace {

constexpr double kCos45 = 0.70710678118654752;

// Where a bolt from x along d leaves the cone of the wedge's joints.
double depth_in_wedge(const Eigen::Vector3d& x, const Eigen::Vector3d& d,
                      const Eigen::Vector3d& apex, const std::vector<Eigen::Vector3d>& inward) {
  double t = std::numeric_limits<double>::infinity();
  for (const auto& m : inward) {
    const double md = m.dot(d);
    if (md < 0) t = std::min(t, std::max(0.0, m.dot(x - apex)) / -md);
  }
  return t;
}

WedgeBolt make_bolt(const PatternBolts& b, const blocks::Polyhedron& wedge,
                    const Eigen::Vector3d& head, const Eigen::Vector3d& dir,
                    const Eigen::Vector3d& apex, const std::vector<Eigen::Vector3d>& inward) {
  WedgeBolt bolt;
  bolt.head = head + wedge.datum();
  bolt.direction = dir;
  bolt.depth_in_wedge = depth_in_wedge(head, dir, apex, inward);
  bolt.anchorage = b.length - bolt.depth_in_wedge;
  if (bolt.anchorage > 0) {
    bolt.force = b.capacity;
    if (b.bond_strength) bolt.force = std::min(bolt.force, *b.bond_strength * bolt.anchorage);
  }
  return bolt;
}

}  // namespace

bool supports_edge(const SupportPlaces& places, const Eigen::Vector2d& n) {
  if (n.y() > kCos45) return places.roof;
  if (n.y() < -kCos45) return places.floor;
  return places.walls;
}

std::vector<WedgeBolt> pattern_bolts_on_wedge(const PatternBolts& bolts,
                                              const blocks::Polyhedron& wedge,
                                              const SectionPolygon& section,
                                              const TunnelFrame& frame, bool face_wedge,
                                              const Eigen::Vector3d& apex,
                                              const std::vector<Eigen::Vector3d>& inward) {
  std::vector<WedgeBolt> out;
  const double S = bolts.spacing;
  if (!(S > 0)) return out;
  auto on_wedge = [&](const Eigen::Vector3d& x) {
    return blocks::locate_point(wedge, x) != blocks::PointLocation::Outside;
  };
  if (face_wedge) {
    if (!bolts.places.face) return out;
    double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
    for (const auto& v : section.vertices) {
      umin = std::min(umin, v.p.x());
      umax = std::max(umax, v.p.x());
      vmin = std::min(vmin, v.p.y());
      vmax = std::max(vmax, v.p.y());
    }
    for (int i = static_cast<int>(std::ceil(umin / S)); i * S <= umax; ++i)
      for (int j = static_cast<int>(std::ceil(vmin / S)); j * S <= vmax; ++j) {
        const Eigen::Vector3d x = frame.to_local(i * S, j * S, 0);
        if (on_wedge(x)) out.push_back(make_bolt(bolts, wedge, x, frame.along, apex, inward));
      }
    return out;
  }
  // The edges the wedge has a face on ("E<k>" planes, k from 1).
  std::set<std::size_t> edges;
  for (const auto& p : wedge.planes())
    if (p.kind == blocks::PlaneKind::FreeFace && p.name.size() > 1 && p.name[0] == 'E')
      edges.insert(static_cast<std::size_t>(std::stoul(p.name.substr(1))) - 1);
  double wmin = 1e300, wmax = -1e300;
  for (const auto& v : wedge.vertices()) {
    const double w = (v - frame.origin).dot(frame.along);
    wmin = std::min(wmin, w);
    wmax = std::max(wmax, w);
  }
  // The pattern is centred on the crown: where the outline crosses the
  // vertical through the axis (u = 0) highest, else its highest vertex.
  double crown = 0, top = -1e300;
  for (std::size_t i = 0; i < section.size(); ++i) {
    const Eigen::Vector2d a = section.at(i);
    if (a.y() > top) {
      top = a.y();
      crown = section.vertices[i].s;
    }
  }
  top = -1e300;
  for (std::size_t i = 0; i < section.size(); ++i) {
    const Eigen::Vector2d a = section.at(i), b = section.at(i + 1);
    if ((a.x() <= 0 && b.x() > 0) || (a.x() > 0 && b.x() <= 0)) {
      const double t = a.x() / (a.x() - b.x());
      const double v = a.y() + t * (b.y() - a.y());
      if (v > top) {
        top = v;
        crown = section.vertices[i].s + t * (b - a).norm();
      }
    }
  }
  for (std::size_t e : edges) {
    const Eigen::Vector2d n = section.outward_normal(e);
    if (!supports_edge(bolts.places, n)) continue;
    const double s0 = section.vertices[e].s;
    const Eigen::Vector2d a = section.at(e), b = section.at(e + 1);
    const double len = (b - a).norm();
    // Pattern positions s = crown + k S, k S within half the perimeter of
    // the crown either way (the two halves meet opposite the crown).
    const double half = 0.5 * section.perimeter;
    for (int k = static_cast<int>(std::ceil(-half / S)); k * S <= half; ++k) {
      if (k * S <= -half) continue;
      const double s = std::fmod(std::fmod(crown + k * S, section.perimeter) + section.perimeter,
                                 section.perimeter);
      if (s < s0 || s >= s0 + len) continue;
      const Eigen::Vector2d uv = a + ((s - s0) / len) * (b - a);
      for (int j = static_cast<int>(std::ceil(wmin / S)); j * S <= wmax; ++j) {
        const Eigen::Vector3d x = frame.to_local(uv.x(), uv.y(), j * S);
        if (on_wedge(x))
          out.push_back(
              make_bolt(bolts, wedge, x, n.x() * frame.right + n.y() * frame.up, apex, inward));
      }
    }
  }
  return out;
}

SupportedFos supported_fos(const kinematics::SlidingMode& mode,
                           const std::vector<kinematics::ContactPlane>& contacts,
                           const Eigen::Vector3d& loads, const Eigen::Vector3d& support) {
  SupportedFos out;
  const double inf = std::numeric_limits<double>::infinity();
  if (mode.type == kinematics::ModeType::None) {
    out.fos = inf;
    return out;
  }
  const Eigen::Vector3d s = mode.direction;
  const double driving = loads.dot(s);
  if (!(driving > 0)) {
    out.fos = inf;
    return out;
  }
  const double direct = -support.dot(s);
  if (mode.type != kinematics::ModeType::Sliding) {
    out.fos = direct / driving;
    return out;
  }
  std::vector<const kinematics::ContactPlane*> planes;
  for (int p : mode.planes)
    for (const auto& c : contacts)
      if (c.plane == p) planes.push_back(&c);
  for (const auto* c : planes)
    if (!c->friction) return out;  // no friction angle: no factor of safety
  const Eigen::Vector3d r = loads + support;
  auto resisting = [&](const kinematics::ContactPlane& c, double n) {
    return n * std::tan(*c.friction) + c.cohesion_force;
  };
  double resist = 0;
  if (planes.size() == 2) {
    Eigen::Matrix3d m;
    m.col(0) = s;
    m.col(1) = -planes[0]->block_normal;
    m.col(2) = -planes[1]->block_normal;
    const Eigen::Vector3d x = m.colPivHouseholderQr().solve(r);
    if (x(1) >= 0 && x(2) >= 0) {
      out.fos = (resisting(*planes[0], x(1)) + resisting(*planes[1], x(2)) + direct) / driving;
      return out;
    }
    // The support lifts the wedge off one plane: it rests on the other alone.
    for (int k = 0; k < 2; ++k)
      if (x(1 + k) < 0) out.lifted_planes.push_back(planes[k]->plane);
    if (x(2) < 0) planes.pop_back();
    if (x(1) < 0) planes.erase(planes.begin());
  }
  for (const auto* c : planes) {
    const double n = -r.dot(c->block_normal);
    if (n >= 0)
      resist += resisting(*c, n);
    else
      out.lifted_planes.push_back(c->plane);
  }
  out.fos = (resist + direct) / driving;
  return out;
}

}  // namespace rockface::tunnel

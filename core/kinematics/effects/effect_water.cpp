#include "core/kinematics/effects/effect_water.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/blocks/triangulation.h"
#include "core/common/error.h"

namespace rockface::kinematics {

namespace {

// A phreatic plane closer to vertical than this (z component of its unit
// normal) gives heights above points that blow up: it is rejected.
constexpr double kVerticalPhreatic = 1e-9;

struct Integral {
  double force = 0;                                  // integral of p dA
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // integral of p x dA
};

// Exact integral of the linear pressure over a triangle: the integral of
// a linear f is A mean(f_i); of f x it is A / 12 (sum f_i x_i + sum f_i sum x_i).
void add_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  double pa, double pb, double pc, Integral& out) {
  const double area = 0.5 * (b - a).cross(c - a).norm();
  out.force += area * (pa + pb + pc) / 3.0;
  out.moment += area / 12.0 * (pa * a + pb * b + pc * c + (pa + pb + pc) * (a + b + c));
}

}  // namespace

WaterEffect::WaterEffect(double unit_weight, const Eigen::Vector3d& phreatic_point,
                         const Eigen::Vector3d& phreatic_normal, std::vector<int> joints)
    : unit_weight_(unit_weight), point_(phreatic_point), joints_(std::move(joints)) {
  if (!(unit_weight > 0) || !std::isfinite(unit_weight))
    throw InputError("effects.water.unit_weight", "must be a positive number of N/m^3");
  const double len = phreatic_normal.norm();
  if (!(len > 0)) throw InputError("effects.water.phreatic_surface", "has no orientation");
  normal_ = phreatic_normal / len;
  if (normal_.z() < 0) normal_ = -normal_;
  if (!(normal_.z() > kVerticalPhreatic))
    throw InputError("effects.water.phreatic_surface.dip",
                     "a vertical phreatic surface has no height above a point");
}

double WaterEffect::pressure_at(const Eigen::Vector3d& x) const {
  // Height of the plane above x along the vertical: n . (x + h e_z - P) = 0.
  const double h = -normal_.dot(x - point_) / normal_.z();
  return unit_weight_ * std::max(h, 0.0);
}

bool WaterEffect::carries_water(const blocks::BlockPlane& plane) const {
  if (plane.kind != blocks::PlaneKind::Joint) return false;  // free faces are open to the air
  return joints_.empty() || std::find(joints_.begin(), joints_.end(), plane.index) != joints_.end();
}

EffectLoad WaterEffect::load(const blocks::Polyhedron& block,
                             const blocks::MassProperties& mass) const {
  EffectLoad l;
  const auto& x = block.vertices();
  const Eigen::Vector3d P = point_ - block.datum();
  // Signed head (m) at a datum-relative point: linear, positive below the plane.
  auto head = [&](const Eigen::Vector3d& p) { return -normal_.dot(p - P) / normal_.z(); };
  bool any_joint = false;
  for (int f = 0; f < static_cast<int>(block.faces().size()); ++f) {
    const blocks::BlockPlane& bp = block.planes()[block.faces()[f].plane];
    if (!carries_water(bp)) continue;
    any_joint = true;
    Integral in;
    for (const blocks::Triangle& t : blocks::triangulate_face(block, f)) {
      // Clip the triangle to the wetted side (head >= 0): the pressure is
      // linear there, and zero above the phreatic plane.
      std::vector<Eigen::Vector3d> poly{x[t[0]], x[t[1]], x[t[2]]}, clipped;
      for (size_t k = 0; k < poly.size(); ++k) {
        const Eigen::Vector3d& a = poly[k];
        const Eigen::Vector3d& b = poly[(k + 1) % poly.size()];
        const double ha = head(a), hb = head(b);
        if (ha >= 0) clipped.push_back(a);
        if ((ha >= 0) != (hb >= 0)) clipped.push_back(a + ha / (ha - hb) * (b - a));
      }
      for (size_t k = 1; k + 1 < clipped.size(); ++k) {
        const Eigen::Vector3d &a = clipped[0], &b = clipped[k], &c = clipped[k + 1];
        add_triangle(a, b, c, unit_weight_ * std::max(head(a), 0.0),
                     unit_weight_ * std::max(head(b), 0.0), unit_weight_ * std::max(head(c), 0.0),
                     in);
      }
    }
    if (!(in.force > 0)) continue;
    FaceLoad fl;
    fl.face = f;
    fl.plane = block.faces()[f].plane;
    fl.normal = in.force;
    // Water pushes the block off the joint: along the block-side normal.
    fl.force = in.force * bp.inward_normal();
    fl.point = in.moment / in.force;
    l.force += fl.force;
    l.moment += (fl.point - mass.centroid).cross(fl.force);
    l.faces.push_back(fl);
  }
  l.acts = !l.faces.empty();
  if (!l.acts)
    l.notes.push_back(any_joint ? "water does not act on block " + block.id() +
                                      ": its joint faces lie above the phreatic surface"
                                : "water does not act on block " + block.id() +
                                      ": none of its faces is a joint carrying water");
  return l;
}

}  // namespace rockface::kinematics

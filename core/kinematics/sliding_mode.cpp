#include "core/kinematics/sliding_mode.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

#include "core/geometry/tolerances.h"

namespace rockface::kinematics {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double angle_of(double sine) {
  return std::asin(std::clamp(sine, -1.0, 1.0));
}

// Smallest angle (radians, signed) by which unit direction s is inside the
// half-spaces of all contacts except the ones listed.
double inside_margin(const Eigen::Vector3d& s, const std::vector<ContactPlane>& contacts,
                     int skip_a, int skip_b) {
  double m = std::numbers::pi / 2;
  for (int k = 0; k < static_cast<int>(contacts.size()); ++k)
    if (k != skip_a && k != skip_b) m = std::min(m, angle_of(contacts[k].block_normal.dot(s)));
  return m;
}

std::optional<double> resisting(const std::vector<ContactPlane>& contacts,
                                const std::vector<int>& idx, const std::vector<double>& normal) {
  double r = 0;
  for (size_t i = 0; i < idx.size(); ++i) {
    const auto& c = contacts[idx[i]];
    if (!c.friction) return std::nullopt;
    r += normal[i] * std::tan(*c.friction) + c.cohesion_force;
  }
  return r;
}

}  // namespace

const char* mode_name(ModeType t) {
  switch (t) {
    case ModeType::Falling:
      return "falling";
    case ModeType::Lifting:
      return "lifting";
    case ModeType::Sliding:
      return "sliding";
    case ModeType::None:
      return "none";
  }
  return "none";
}

SlidingMode sliding_mode(const Eigen::Vector3d& resultant,
                         const std::vector<ContactPlane>& contacts, double uncertainty) {
  SlidingMode out;
  const double r_len = resultant.norm();
  const double tol = std::max(uncertainty, geometry::kAngleEpsRad);
  if (!(r_len > 0)) {
    out.fos = kInf;
    out.margin = 0;
    out.marginal = true;
    return out;
  }
  const Eigen::Vector3d r = resultant / r_len;
  const int n = static_cast<int>(contacts.size());
  // For the verdict "none": the smallest violation among the modes that did
  // not apply, each measured by its worst-violated condition (an estimate of
  // how far r must turn before some mode starts).
  double closest_failure = std::numbers::pi / 2;
  auto failed = [&](std::initializer_list<double> violations) {
    closest_failure = std::min(closest_failure, std::max(violations));
  };

  // Falling / lifting: r inside the pyramid.
  {
    const double m = inside_margin(r, contacts, -1, -1);
    if (m >= -geometry::kAngleEpsRad) {
      out.type = r.z() <= 0 ? ModeType::Falling : ModeType::Lifting;
      out.direction = r;
      out.driving_force = r_len;
      out.fos = 0.0;
      out.margin = std::max(m, 0.0);
      out.marginal = out.margin < tol;
      return out;
    }
    failed({-m});
  }

  // Sliding on one plane.
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d& ni = contacts[i].block_normal;
    const double press = -r.dot(ni);  // sine of the angle r makes with the plane, toward it
    if (press < -geometry::kAngleEpsRad) continue;
    const Eigen::Vector3d tangential = r + press * ni;
    const double t_len = tangential.norm();
    if (!(t_len > geometry::kParallelCross))
      continue;  // r normal to the plane: no sliding on it alone
    const Eigen::Vector3d s = tangential / t_len;
    const double m = inside_margin(s, contacts, i, -1);
    if (m < -geometry::kAngleEpsRad) continue;
    out.type = ModeType::Sliding;
    out.planes = {contacts[i].plane};
    out.direction = s;
    out.normal_forces = {std::max(press, 0.0) * r_len};
    out.driving_force = t_len * r_len;
    const auto res = resisting(contacts, {i}, out.normal_forces);
    if (res) out.fos = *res / out.driving_force;
    out.margin = std::min(std::max(m, 0.0), std::max(angle_of(press), 0.0));
    out.marginal = out.margin < tol;
    return out;
  }

  // Sliding on two planes, along their intersection.
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const Eigen::Vector3d& ni = contacts[i].block_normal;
      const Eigen::Vector3d& nj = contacts[j].block_normal;
      Eigen::Vector3d s = ni.cross(nj);
      const double s_len = s.norm();
      if (!(s_len > geometry::kParallelCross)) continue;
      s /= s_len;
      if (s.dot(r) < 0) s = -s;
      const double m = inside_margin(s, contacts, i, j);
      // r - (r.s) s = -(Ni ni + Nj nj): solve the 2x2 normal equations.
      const Eigen::Vector3d normal_part = -(r - r.dot(s) * s);
      Eigen::Matrix2d g;
      g << 1, ni.dot(nj), ni.dot(nj), 1;
      const Eigen::Vector2d rhs(ni.dot(normal_part), nj.dot(normal_part));
      const Eigen::Vector2d nn = g.ldlt().solve(rhs);
      // Normal reactions as sines of r's pressing angle on each plane; a
      // slightly negative one within tolerance is contact that just holds.
      // The intersection must also carry r forward: r perpendicular to it
      // (a horizontal line under gravity) drives nothing.
      const double along = r.dot(s);
      if (m < -geometry::kAngleEpsRad || nn.minCoeff() < -geometry::kAngleEpsRad ||
          along <= geometry::kAngleEpsRad) {
        failed({-m, -angle_of(std::clamp(nn.minCoeff(), -1.0, 0.0)), -angle_of(along)});
        continue;
      }
      out.type = ModeType::Sliding;
      out.planes = {contacts[i].plane, contacts[j].plane};
      out.direction = s;
      out.normal_forces = {std::max(nn[0], 0.0) * r_len, std::max(nn[1], 0.0) * r_len};
      out.driving_force = r.dot(s) * r_len;
      const auto res = resisting(contacts, {i, j}, out.normal_forces);
      if (res) out.fos = *res / out.driving_force;
      out.margin =
          std::min({std::max(m, 0.0), angle_of(std::max(nn.minCoeff(), 0.0)), angle_of(r.dot(s))});
      out.marginal = out.margin < tol;
      return out;
    }

  // r pushes the block into the rock.
  out.type = ModeType::None;
  out.fos = kInf;
  out.margin = std::max(closest_failure, 0.0);
  out.marginal = out.margin < tol;
  return out;
}

}  // namespace rockface::kinematics

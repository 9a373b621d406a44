#include "core/kinematics/remote_axis.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "core/common/error.h"
#include "core/kinematics/rotation_tolerances.h"

namespace rockface::kinematics {

namespace {

// The block in local coordinates: corners relative to the centroid, divided
// by the bounding radius, so that the minimiser's parameters are O(1) for
// any block size and any datum.
struct AxisProblem {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double scale = 1;                     // bounding radius, m
  std::vector<Eigen::Vector3d> corner;  // per constraint, local
  std::vector<Eigen::Vector3d> normal;  // per constraint, block-side unit normal
  double on_axis = 0;                   // local distance below which a corner does not move
};

AxisProblem make_problem(const RotationInput& in) {
  const RotationTopology topology = rotation_topology(in);
  AxisProblem p;
  p.centroid = topology.centroid;
  p.scale = 0;
  for (const auto& x : in.vertices) p.scale = std::max(p.scale, (x - p.centroid).norm());
  if (!(p.scale > 0)) throw InputError("block " + in.block, "all corners coincide");
  for (int v = 0; v < static_cast<int>(in.vertices.size()); ++v)
    for (int pl : topology.vertex_planes[v])
      if (in.planes[pl].joint) {
        p.corner.push_back((in.vertices[v] - p.centroid) / p.scale);
        p.normal.push_back(in.planes[pl].inward_normal);
      }
  p.on_axis = kOnAxisRel * topology.size / p.scale;
  return p;
}

// Per constraint: the violation angle delta (>= 0) and the signed angle of
// the displacement above the joint plane (for the clearance); on-axis
// corners give neither.
struct ConstraintAngles {
  double violation = 0;
  double elevation = 0;
  bool moves = false;
};

ConstraintAngles angles(const AxisProblem& p, size_t k, const Eigen::Vector3d& u,
                        const Eigen::Vector3d& q) {
  ConstraintAngles a;
  const Eigen::Vector3d d = u.cross(p.corner[k] - q);
  const double len = d.norm();
  if (!(len > p.on_axis)) return a;
  a.moves = true;
  a.elevation = std::asin(std::clamp(d.dot(p.normal[k]) / len, -1.0, 1.0));
  a.violation = std::max(0.0, -a.elevation);
  return a;
}

AxisFeasibility feasibility(const AxisProblem& p, const Eigen::Vector3d& u,
                            const Eigen::Vector3d& q) {
  AxisFeasibility f;
  f.clearance = std::numbers::pi / 2;
  for (size_t k = 0; k < p.corner.size(); ++k) {
    const ConstraintAngles a = angles(p, k, u, q);
    if (!a.moves) continue;
    f.penalty += 1 - std::cos(a.violation);
    f.max_violation = std::max(f.max_violation, a.violation);
    f.clearance = std::min(f.clearance, a.elevation);
  }
  return f;
}

// A chart of axes near (u0 through p0): x = (a, b, s, t) gives the direction
// u0 + a e1 + b e2 (normalised) through the point p0 + s e1 + t e2 of the
// plane across u0. It covers the hemisphere around u0 without singularity.
struct AxisChart {
  Eigen::Vector3d u0, p0, e1, e2;
  AxisChart(const Eigen::Vector3d& u, const Eigen::Vector3d& p) : u0(u.normalized()), p0(p) {
    e1 = u0.unitOrthogonal();
    e2 = u0.cross(e1);
  }
  Eigen::Vector3d direction(const Eigen::VectorXd& x) const {
    return (u0 + x[0] * e1 + x[1] * e2).normalized();
  }
  Eigen::Vector3d point(const Eigen::VectorXd& x) const { return p0 + x[2] * e1 + x[3] * e2; }
};

// Residuals r_k = 2 sin(delta_k / 2): sum r^2 / 2 = sum (1 - cos delta_k).
// Padded with zeros to at least 4 (Levenberg-Marquardt wants m >= n).
struct AxisResiduals {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const AxisProblem* problem = nullptr;
  const AxisChart* chart = nullptr;

  int inputs() const { return 4; }
  int values() const { return std::max<int>(4, static_cast<int>(problem->corner.size())); }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    const Eigen::Vector3d u = chart->direction(x);
    const Eigen::Vector3d q = chart->point(x);
    r.setZero(values());
    for (size_t k = 0; k < problem->corner.size(); ++k)
      r[k] = 2 * std::sin(angles(*problem, k, u, q).violation / 2);
    return 0;
  }
};

// Uniform in (0, 1) from the raw 32-bit output: the same numbers with every
// standard library (std::uniform_real_distribution is not portable).
double unit_uniform(std::mt19937& gen) {
  return (static_cast<double>(gen()) + 0.5) / 4294967296.0;
}

struct LocalAxis {
  Eigen::Vector3d u = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d q = Eigen::Vector3d::Zero();  // the axis point nearest the centroid (local)
  AxisFeasibility f;
};

Eigen::Vector3d nearest_to_origin(const Eigen::Vector3d& q, const Eigen::Vector3d& u) {
  return q - q.dot(u) * u;
}

// One start: Levenberg-Marquardt in a chart around the start, re-centred
// on the current axis when the chart has been stretched (a step of more
// than ~45 degrees of direction), a few times at most.
LocalAxis minimise_from(const AxisProblem& p, Eigen::Vector3d u, Eigen::Vector3d q) {
  constexpr int kCharts = 4;
  LocalAxis best{u, nearest_to_origin(q, u), feasibility(p, u, q)};
  for (int round = 0; round < kCharts && best.f.max_violation > kRemoteAxisHitRad; ++round) {
    const AxisChart chart(best.u, best.q);
    AxisResiduals residuals;
    residuals.problem = &p;
    residuals.chart = &chart;
    Eigen::NumericalDiff<AxisResiduals, Eigen::Central> numdiff(residuals);
    Eigen::LevenbergMarquardt<Eigen::NumericalDiff<AxisResiduals, Eigen::Central>> lm(numdiff);
    lm.parameters.factor = 1;    // first step bound ~ 1 chart unit (45 degrees, one radius)
    lm.parameters.maxfev = 200;  // per chart
    lm.parameters.ftol = 1e-14;  // reach the tangent (sliding) solutions, not just near them
    lm.parameters.xtol = 1e-14;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
    lm.minimize(x);
    const Eigen::Vector3d u1 = chart.direction(x);
    const Eigen::Vector3d q1 = nearest_to_origin(chart.point(x), u1);
    const AxisFeasibility f1 = feasibility(p, u1, q1);
    const bool improved = f1.penalty < best.f.penalty;
    if (improved) best = {u1, q1, f1};
    const bool stretched = x.head<2>().norm() > 1 || x.tail<2>().norm() > 4;
    if (!improved || !stretched) break;
  }
  return best;
}

// Half-width of the 95 % Wilson score interval of a hit rate k / n within
// kRemoteAxisHitRateError.
bool hit_rate_settled(int k, int n) {
  constexpr double z = 1.959963984540054;  // 97.5 % quantile of the normal distribution
  const double p = static_cast<double>(k) / n;
  const double half = z / (1 + z * z / n) * std::sqrt(p * (1 - p) / n + z * z / (4.0 * n * n));
  return half <= kRemoteAxisHitRateError;
}

}  // namespace

AxisFeasibility remote_axis_feasibility(const RotationInput& in, const Eigen::Vector3d& point,
                                        const Eigen::Vector3d& direction) {
  const AxisProblem p = make_problem(in);
  return feasibility(p, direction.normalized(), (point - p.centroid) / p.scale);
}

double remote_axis_penalty(const RotationInput& in, const Eigen::Vector3d& point,
                           const Eigen::Vector3d& direction) {
  return remote_axis_feasibility(in, point, direction).penalty;
}

int remote_axis_starts(Preset preset) {
  switch (preset) {
    case Preset::fast:
      return 16;
    case Preset::standard:
      return 64;
    case Preset::precise:
      return 256;
  }
  return 64;  // not reached: every enumerator is handled above
}

RemoteAxisResult search_remote_axis(const RotationInput& in, const RemoteAxisOptions& options) {
  if (options.starts < 1)
    throw InputError("block " + in.block + ": remote_axis.starts",
                     std::to_string(options.starts) + " is not a positive number of starts");
  const AxisProblem p = make_problem(in);
  RemoteAxisResult result;
  result.starts = options.starts;
  result.constraints = static_cast<int>(p.corner.size());
  std::mt19937 gen(options.seed);
  bool have = false;
  LocalAxis best;
  for (int s = 0; s < options.starts; ++s) {
    const double z = 2 * unit_uniform(gen) - 1;
    const double phi = 2 * std::numbers::pi * unit_uniform(gen);
    const double rho = std::sqrt(1 - z * z);
    const Eigen::Vector3d u(rho * std::cos(phi), rho * std::sin(phi), z);
    const double radius = kRemoteAxisStartRadius * std::sqrt(unit_uniform(gen));
    const double psi = 2 * std::numbers::pi * unit_uniform(gen);
    const AxisChart across(u, Eigen::Vector3d::Zero());
    const Eigen::Vector3d q = radius * (std::cos(psi) * across.e1 + std::sin(psi) * across.e2);

    const LocalAxis local = minimise_from(p, u, q);
    const bool hit = local.f.max_violation <= kRemoteAxisHitRad;
    if (hit) ++result.hits;
    const bool best_hit = have && best.f.max_violation <= kRemoteAxisHitRad;
    const bool better = !have || (hit && (!best_hit || local.f.clearance > best.f.clearance)) ||
                        (!hit && !best_hit && local.f.penalty < best.f.penalty);
    if (better) {
      best = local;
      have = true;
    }
    result.starts = s + 1;
    if (options.early_stop && result.hits > 0 && result.starts >= kRemoteAxisMinStarts &&
        result.starts < options.starts && hit_rate_settled(result.hits, result.starts)) {
      result.stopped_early = true;
      break;
    }
  }
  result.found = result.hits > 0;
  result.direction = best.u;
  result.point = p.centroid + p.scale * best.q;
  result.distance = p.scale * best.q.norm();
  result.penalty = best.f.penalty;
  result.max_violation = best.f.max_violation;
  result.clearance = best.f.clearance;
  return result;
}

}  // namespace rockface::kinematics

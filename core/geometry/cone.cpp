#include "core/geometry/cone.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <Eigen/Geometry>

#include "core/geometry/tolerances.h"

namespace rockface::geometry {

namespace {

// min_i n_i . d for unit d, stopping early once it cannot beat `best`.
double min_dot(const std::vector<Eigen::Vector3d>& normals, const Eigen::Vector3d& d, double best) {
  double m = std::numeric_limits<double>::infinity();
  for (const auto& n : normals) {
    m = std::min(m, n.dot(d));
    if (m <= best) return m;
  }
  return m;
}

double safe_asin(double s) {
  return std::asin(std::clamp(s, -1.0, 1.0));
}

}  // namespace

Cone::Cone(const std::vector<Eigen::Vector3d>& inward_normals) {
  normals_.reserve(inward_normals.size());
  for (const auto& n : inward_normals) add(n);
}

Cone Cone::from_unit_normals(std::vector<Eigen::Vector3d> unit_inward_normals) {
  for (const auto& n : unit_inward_normals)
    // Rounding leaves |n|^2 within a few 1e-16 of 1; 1e-12 only catches
    // normals that were never normalised.
    if (!(std::abs(n.squaredNorm() - 1) < 1e-12))
      throw std::invalid_argument("cone half-space normal is not a unit vector");
  Cone c;
  c.normals_ = std::move(unit_inward_normals);
  return c;
}

void Cone::add(const Eigen::Vector3d& inward_normal) {
  const double len = inward_normal.norm();
  if (!(len > 0) || !std::isfinite(len))
    throw std::invalid_argument("cone half-space with a zero or non-finite normal");
  normals_.push_back(inward_normal / len);
}

Cone Cone::intersect(const Cone& other) const {
  Cone c = *this;
  c.normals_.insert(c.normals_.end(), other.normals_.begin(), other.normals_.end());
  return c;
}

ConeMargin Cone::margin() const {
  ConeMargin best;
  if (normals_.empty()) {
    best.angle = std::numbers::pi / 2;
    return best;
  }
  double best_dot = -std::numeric_limits<double>::infinity();
  auto consider = [&](const Eigen::Vector3d& raw) {
    const double len = raw.norm();
    if (!(len > kParallelCross)) return;
    const Eigen::Vector3d d = raw / len;
    const double m = min_dot(normals_, d, best_dot);
    if (m > best_dot) {
      best_dot = m;
      best.direction = d;
    }
  };
  const size_t m = normals_.size();
  // One tight half-space: d = n_i.
  for (size_t i = 0; i < m; ++i) consider(normals_[i]);
  // Two equally tight: d on their bisector, the maximum of n_i . d there.
  // For (nearly) opposite normals the bisector is a whole great circle on
  // which n_i . d is flat; the best point there is where another half-space
  // is best, the projection of its normal onto that circle.
  for (size_t i = 0; i < m; ++i)
    for (size_t j = i + 1; j < m; ++j) {
      const Eigen::Vector3d sum = normals_[i] + normals_[j];
      consider(sum);
      consider(-sum);
      if (sum.norm() < kOppositeNormals) {
        const Eigen::Vector3d u = (normals_[i] - normals_[j]).normalized();
        consider(u.unitOrthogonal());
        for (size_t k = 0; k < m; ++k)
          if (k != i && k != j) consider(normals_[k] - normals_[k].dot(u) * u);
      }
    }
  // Three equally tight: d is normal to (n_i - n_j) and (n_j - n_k); the
  // cyclic sum of cross products is that normal without the cancellation of
  // subtracting nearly equal normals first.
  // The two senses share the length and the tight value t = n_i . d (and
  // -t): a sense whose t cannot beat the best so far has a min below it too
  // and is skipped, with the result of considering it.
  for (size_t i = 0; i < m; ++i)
    for (size_t j = i + 1; j < m; ++j)
      for (size_t k = j + 1; k < m; ++k) {
        const Eigen::Vector3d c = normals_[i].cross(normals_[j]) + normals_[j].cross(normals_[k]) +
                                  normals_[k].cross(normals_[i]);
        const double len = c.norm();
        if (!(len > kParallelCross)) continue;
        const Eigen::Vector3d d = c / len;
        const double t = normals_[i].dot(d);
        if (t > best_dot) consider(c);
        if (-t > best_dot) consider(-c);
      }
  // Every candidate degenerate (e.g. two opposite half-spaces only): the cone
  // is a plane, any direction in it has margin zero.
  if (!std::isfinite(best_dot)) {
    best_dot = 0;
    Eigen::Vector3d any = normals_[0].unitOrthogonal();
    best.direction = any;
    best_dot = min_dot(normals_, any, -2.0);
  }
  best.sine = best_dot;
  best.angle = safe_asin(best_dot);
  return best;
}

double Cone::margin_of(const Eigen::Vector3d& d) const {
  const double len = d.norm();
  if (!(len > 0)) return -std::numbers::pi / 2;
  if (normals_.empty()) return std::numbers::pi / 2;
  return safe_asin(min_dot(normals_, d / len, -2.0));
}

std::vector<Eigen::Vector3d> Cone::edges() const {
  return normals_.size() < 2 ? std::vector<Eigen::Vector3d>{} : edges(margin().angle);
}

std::vector<Eigen::Vector3d> Cone::edges(double known_margin) const {
  std::vector<Eigen::Vector3d> rays;
  if (normals_.size() < 2 || known_margin < -kAngleEpsRad) return rays;
  const size_t m = normals_.size();
  const double outside = std::nextafter(-kAngleEpsRad, -std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < m; ++i)
    for (size_t j = i + 1; j < m; ++j) {
      const Eigen::Vector3d c = normals_[i].cross(normals_[j]);
      const double len = c.norm();
      if (!(len > kParallelCross)) continue;
      for (double sense : {1.0, -1.0}) {
        const Eigen::Vector3d d = sense * c / len;
        // Early exit at the first half-space below -kAngleEpsRad (the
        // returned value is then below it; otherwise it is the exact min).
        if (min_dot(normals_, d, outside) < -kAngleEpsRad) continue;
        const bool seen = std::any_of(rays.begin(), rays.end(), [&](const Eigen::Vector3d& r) {
          return r.cross(d).norm() < kSameRayRad && r.dot(d) > 0;
        });
        if (!seen) rays.push_back(d);
      }
    }
  return rays;
}

namespace {

// A candidate is cut when another half-space is below its tight value by
// more than the rounding of its direction: a direction made from a vector
// of length len (sums and cross products of unit normals, terms of size
// <= 3) is off by ~3e-16 / len, so kCutRounding / len bounds that with a
// wide factor, and kCutSine covers the dot products themselves (~1e-16). A
// candidate kept needlessly costs time, never accuracy.
constexpr double kCutSine = 1e-12;
constexpr double kCutRounding = 1e-14;
// How far above the margin before a half-space joins a new candidate is
// still evaluated: the margin is the best candidate's value, within the
// rounding of its direction (~1e-15) of the max-min; 1e-9 is far wider.
constexpr double kCeilingSlack = 1e-9;

}  // namespace

bool IncrementalMargin::consider(const Eigen::Vector3d& raw,
                                 std::initializer_list<const Eigen::Vector3d*> makers) {
  const double len = raw.norm();
  if (!(len > kParallelCross)) return false;
  const Eigen::Vector3d d = raw / len;
  if (makers.size() == 0) {
    live_.push_back({d, min_dot(normals_, d, -2.0), -std::numeric_limits<double>::infinity()});
    return true;
  }
  double tight = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d* n : makers) tight = std::min(tight, n->dot(d));
  const double cut = tight - kCutSine - kCutRounding / len;
  // Its value cannot exceed the margin before the new half-space joined
  // (ceiling_): above that it is cut without looking at the normals.
  if (cut > ceiling_) return true;
  double value = tight;
  // Most new candidates are cut by one of the first normals: stop there.
  for (const auto& n : normals_) {
    value = std::min(value, n.dot(d));
    if (value < cut) return true;
  }
  live_.push_back({d, value, cut});
  return true;
}

bool IncrementalMargin::consider_triple(const Eigen::Vector3d& raw, int i, int j, int k) {
  // consider(raw, makers i, j, k) and then consider(-raw, the same), sharing
  // the length, the direction and the makers' dot products: negating a
  // vector negates them exactly.
  const double len = raw.norm();
  if (!(len > kParallelCross)) return false;
  const Eigen::Vector3d d = raw / len;
  const double a = normals_[i].dot(d), b = normals_[j].dot(d), c = normals_[k].dot(d);
  const double rounding = kCutRounding / len;
  for (const double sense : {1.0, -1.0}) {
    const double tight = sense > 0 ? std::min(std::min(a, b), c) : -std::max(std::max(a, b), c);
    const double cut = tight - kCutSine - rounding;
    if (cut > ceiling_) continue;  // see consider()
    double value = tight;
    bool is_cut = false;
    for (const auto& n : normals_) {
      value = std::min(value, sense * n.dot(d));
      if (value < cut) {
        is_cut = true;
        break;
      }
    }
    if (!is_cut) live_.push_back({sense > 0 ? d : Eigen::Vector3d(-d), value, cut, i, j, k});
  }
  return true;
}

void IncrementalMargin::clear() {
  normals_.clear();
  live_.clear();
  opposite_axes_.clear();
  all_pairs_ = false;
  ceiling_ = std::numeric_limits<double>::infinity();
}

void IncrementalMargin::add(const Eigen::Vector3d& inward_normal) {
  const double len = inward_normal.norm();
  if (!(len > 0) || !std::isfinite(len))
    throw std::invalid_argument("cone half-space with a zero or non-finite normal");
  const Eigen::Vector3d w = inward_normal / len;
  if (normals_.empty()) {  // rotation spaces grow to ~15 normals, ~40 candidates
    normals_.reserve(16);
    live_.reserve(64);
    edge_.reserve(16 * 16);
    pairs_.reserve(32);
  }
  const size_t m = normals_.size();  // index of w
  // The live candidates see the new half-space; those it cuts go. The
  // triples it lowers or lies on (the facets it sees, those in whose plane
  // it lies, and some more) give the pairs that make new triples with it.
  bool all_pairs = all_pairs_;
  bool any_triple = false;
  std::vector<char>& edge = edge_;
  edge.assign(all_pairs ? 0 : m * m, 0);
  pairs_.clear();
  auto mark = [&](int i, int j) {
    if (!edge[i * m + j]) {
      edge[i * m + j] = 1;
      pairs_.push_back({i, j});
    }
  };
  // The margin before w joins: the best live value. With w it can only be
  // lower, so no new candidate's value is above it (to the rounding of the
  // candidates' directions, ~1e-15; kCeilingSlack covers it widely).
  double before = live_.empty() ? std::numeric_limits<double>::infinity()
                                : -std::numeric_limits<double>::infinity();
  std::erase_if(live_, [&](Candidate& c) {
    before = std::max(before, c.value);
    const double x = w.dot(c.d);
    if (c.k >= 0) {
      any_triple = true;
      // Seen, or in its plane to within its rounding (coplanar normals: the
      // facet grows by w, as in an incremental hull).
      if (x < c.value + (c.value - c.cut) && !all_pairs) {
        mark(c.i, c.j);
        mark(c.i, c.k);
        mark(c.j, c.k);
      }
    }
    c.value = std::min(c.value, x);
    return c.value < c.cut;
  });
  ceiling_ = before + kCeilingSlack;
  // No facet yet (fewer than three normals, or all on one line): every pair.
  if (!any_triple) all_pairs = true;
  normals_.push_back(w);
  const Eigen::Vector3d& nw = normals_.back();
  // The candidates Cone::margin() makes with w among the normals: w alone,
  // w with each earlier normal (bisector, or the circle of an opposite
  // pair), w with each earlier pair - in the same arithmetic. The circle
  // candidates of opposite pairs are rare and never dropped.
  // w alone: its tight value is 1 (to ~1e-16, |w| = 1); skipped when even
  // that cut is above the ceiling, as consider() would.
  if (1 - 1e-15 - kCutSine - kCutRounding / (1 - 1e-15) <= ceiling_) consider(nw, {&nw});
  for (const auto& u : opposite_axes_) consider(nw - nw.dot(u) * u, {});
  for (size_t i = 0; i < m; ++i) {
    // Only the bisector +sum: where just two half-spaces are tight, the
    // optimum is the maximum of the smaller of their two dot products,
    // which is there; at -sum that smaller one is least along the circle
    // of equal dot products, never a maximum (Cone::margin() considers it
    // too, and it never wins there either, unless a third half-space is
    // as tight - a triple, made below, or an opposite pair's circle).
    const Eigen::Vector3d sum = normals_[i] + nw;
    // Shut (the ceiling below zero): a bisector of a pair far from opposite
    // (|sum| >= kOppositeNormals, squared with a margin for rounding) is
    // skipped by the test below whatever its length (its cut is above
    // 0.5e-3 - 2e-11 > 0), and there is no circle: no square root needed.
    if (ceiling_ < 0 && sum.squaredNorm() > 1.001 * kOppositeNormals * kOppositeNormals) continue;
    const double len = sum.norm();
    // Both makers' dot products with sum / len are len / 2 (unit normals),
    // to ~1e-16: when even that lower bound of its tight value is cut above
    // the ceiling, consider() would skip it; this skips the division.
    if (0.5 * len - 1e-15 - kCutSine - kCutRounding / len <= ceiling_)
      consider(sum, {&normals_[i], &nw});
    if (len < kOppositeNormals) {
      const Eigen::Vector3d u = (normals_[i] - nw).normalized();
      consider(u.unitOrthogonal(), {});
      for (size_t k = 0; k < m; ++k)
        if (k != i) consider(normals_[k] - normals_[k].dot(u) * u, {});
      opposite_axes_.push_back(u);
    }
  }
  auto triple = [&](size_t i, size_t j) {
    const Eigen::Vector3d c =
        normals_[i].cross(normals_[j]) + normals_[j].cross(nw) + nw.cross(normals_[i]);
    if (!consider_triple(c, static_cast<int>(i), static_cast<int>(j), static_cast<int>(m)))
      all_pairs_ = true;
  };
  if (all_pairs) {
    for (size_t i = 0; i < m; ++i)
      for (size_t j = i + 1; j < m; ++j) triple(i, j);
  } else {
    // The marked pairs in the order of the loop over all pairs.
    std::sort(pairs_.begin(), pairs_.end());
    for (const auto& [i, j] : pairs_) triple(i, j);
  }
  ceiling_ = std::numeric_limits<double>::infinity();
}

ConeMargin IncrementalMargin::margin() const {
  if (normals_.empty()) {
    ConeMargin best;
    best.angle = std::numbers::pi / 2;
    return best;
  }
  ConeMargin best = margin_sine();
  best.angle = safe_asin(best.sine);
  return best;
}

ConeMargin IncrementalMargin::margin_sine() const {
  ConeMargin best;
  if (normals_.empty()) return best;
  double best_dot = -std::numeric_limits<double>::infinity();
  for (const auto& c : live_)
    if (c.value > best_dot) {
      best_dot = c.value;
      best.direction = c.d;
    }
  // Every candidate degenerate: the cone is a plane (see Cone::margin()).
  if (!std::isfinite(best_dot)) {
    const Eigen::Vector3d any = normals_[0].unitOrthogonal();
    best.direction = any;
    best_dot = min_dot(normals_, any, -2.0);
  }
  best.sine = best_dot;
  return best;
}

namespace {

// The half-space of `all` that the unit direction d is least inside.
std::pair<size_t, double> least_inside(const std::vector<Eigen::Vector3d>& all,
                                       const Eigen::Vector3d& d) {
  size_t worst = 0;
  double worst_dot = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < all.size(); ++i) {
    const double x = all[i].dot(d);
    if (x < worst_dot) {
      worst_dot = x;
      worst = i;
    }
  }
  return {worst, worst_dot};
}

// Rounding of the dot products (~1e-16) is all that may separate a
// half-space the subset's optimum keeps at the level from one it violates.
constexpr double kLevelRounding = 1e-15;

}  // namespace

// The exact margin of a cone with many half-spaces, by active sets: the
// margin of a subset is never below the margin of the whole (more
// half-spaces can only lower the max-min), so when the subset's optimal
// direction keeps every other half-space at least as far, it is the
// optimum of the whole. Otherwise the half-space it violates most joins the
// subset (an IncrementalMargin, whose candidates are kept from step to
// step), which ends because every half-space joins it at most once. The
// answer is certified by that test against all half-spaces.
//
// (An earlier version first walked a basis of about four half-spaces with
// fresh exact searches, as for a convex problem; for shut cones - nearly
// all rotation spaces of blocks with many faces - it ended by handing its
// basis to the growing subset after ~4 steps, and starting the growing
// subset at once costs 12 % fewer instructions on the mix of
// tools/bench/quick_checks_bench, 14 % on its 12-face blocks.)
ConeMargin active_set_margin(const Cone& cone, size_t direct_up_to) {
  const auto& all = cone.normals();
  if (all.size() <= direct_up_to) return cone.margin();
  // One search object and one list per thread, reused: a block's quick
  // checks run ~10 of these searches, and their memory is most of the
  // allocations otherwise.
  thread_local IncrementalMargin active;
  thread_local std::vector<char> used;
  active.clear();
  used.assign(all.size(), 0);
  used[0] = 1;
  active.add(all[0]);
  for (;;) {
    const ConeMargin m = active.margin_sine();
    const auto [worst, worst_dot] = least_inside(all, m.direction);
    if (worst_dot >= m.sine - kLevelRounding || used[worst]) {
      ConeMargin result = m;
      result.angle = std::min(safe_asin(m.sine), safe_asin(worst_dot));
      result.sine = std::min(m.sine, worst_dot);
      return result;
    }
    used[worst] = 1;
    active.add(all[worst]);
  }
}

// Intersections of joint and excavation pyramids have up to ~20 half-spaces;
// from 7 on the active sets are cheaper (measured on the blocks of
// tools/bench/quick_checks_bench: 12 faces, 60k -> ~15k instructions).
constexpr size_t kDirectUpTo = 6;

UnionEmptiness intersection_with_union_empty(const Cone& a, const std::vector<Cone>& b) {
  UnionEmptiness result;
  result.margin = std::numbers::pi / 2;  // nothing to intersect with: shut by any measure
  for (size_t k = 0; k < b.size(); ++k) {
    const double open = active_set_margin(a.intersect(b[k]), kDirectUpTo).angle;
    if (-open < result.margin) {
      result.margin = -open;
      result.open_index = static_cast<int>(k);
    }
  }
  result.empty = result.margin > 0;
  return result;
}

}  // namespace rockface::geometry

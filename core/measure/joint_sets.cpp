#include "core/measure/joint_sets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "core/common/error.h"
#include "core/common/units.h"

namespace rockface::measure {

namespace {

// Poles within this angle of a pole count toward its density when choosing
// the seeds of the clustering (a typical set's spread is 10-20 degrees).
constexpr double kSeedNeighbourhoodDeg = 15.0;
constexpr int kMaxIterations = 100;

Eigen::Vector3d principal_axis(const std::vector<Eigen::Vector3d>& poles,
                               const std::vector<std::size_t>& members) {
  Eigen::Matrix3d T = Eigen::Matrix3d::Zero();
  for (std::size_t i : members) T += poles[i] * poles[i].transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(T);
  return eig.eigenvectors().col(2).normalized();
}

Eigen::Vector3d upward(Eigen::Vector3d n) {
  if (n.z() < 0 || (n.z() == 0 && (n.y() < 0 || (n.y() == 0 && n.x() < 0)))) n = -n;
  return n;
}

// Fisher's 95 % cone of confidence of the mean of n poles of resultant R.
double alpha95_of(double n, double resultant) {
  if (n < 2 || !(resultant > 0)) return kPi;
  const double c = 1 - (n - resultant) / resultant * (std::pow(1 / 0.05, 1 / (n - 1)) - 1);
  return c <= -1 ? kPi : std::acos(std::min(1.0, c));
}

FisherStatistics fisher_of(const std::vector<Eigen::Vector3d>& poles,
                           const std::vector<std::size_t>& members) {
  FisherStatistics f;
  f.count = members.size();
  if (members.empty()) return f;
  const Eigen::Vector3d axis = principal_axis(poles, members);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i : members) sum += poles[i].dot(axis) < 0 ? -poles[i] : poles[i];
  f.resultant = sum.norm();
  f.mean = upward(f.resultant > 0 ? Eigen::Vector3d(sum / f.resultant) : axis);
  const double n = static_cast<double>(f.count);
  if (f.count < 2) {
    f.kappa = 0;
    f.alpha95 = kPi;
    return f;
  }
  const double spread = n - f.resultant;
  f.kappa = spread > 0 ? (n - 1) / spread : std::numeric_limits<double>::infinity();
  f.alpha95 = alpha95_of(n, f.resultant);
  return f;
}

// log of the Fisher density kappa / (4 pi sinh kappa) exp(kappa cos theta),
// stable for large kappa.
double fisher_log_density(double kappa, double cos_theta) {
  if (!(kappa > 1e-9)) return -std::log(4 * kPi);
  const double log_sinh = kappa + std::log1p(-std::exp(-2 * kappa)) - std::log(2.0);
  return std::log(kappa / (4 * kPi)) - log_sinh + kappa * cos_theta;
}

struct KMeans {
  std::vector<int> assignment;
  std::vector<Eigen::Vector3d> means;
};

KMeans spherical_kmeans(const std::vector<Eigen::Vector3d>& poles, int k) {
  const std::size_t n = poles.size();
  const double near = std::cos(deg_to_rad(kSeedNeighbourhoodDeg));
  std::vector<double> density(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) density[i] += std::abs(poles[i].dot(poles[j])) >= near;
  // Seeds: the densest pole, then the pole that is both dense and far from
  // every seed so far (deterministic, robust to stray poles).
  KMeans km;
  km.means.push_back(poles[std::max_element(density.begin(), density.end()) - density.begin()]);
  while (static_cast<int>(km.means.size()) < k) {
    double best = -1;
    std::size_t pick = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double closest = 0;
      for (const auto& m : km.means) closest = std::max(closest, std::abs(poles[i].dot(m)));
      const double score = density[i] * (1 - closest);
      if (score > best) {
        best = score;
        pick = i;
      }
    }
    km.means.push_back(poles[pick]);
  }
  km.assignment.assign(n, -1);
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    bool changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      int best = 0;
      for (int s = 1; s < k; ++s)
        if (std::abs(poles[i].dot(km.means[s])) > std::abs(poles[i].dot(km.means[best]))) best = s;
      changed = changed || km.assignment[i] != best;
      km.assignment[i] = best;
    }
    if (!changed) break;
    for (int s = 0; s < k; ++s) {
      std::vector<std::size_t> members;
      for (std::size_t i = 0; i < n; ++i)
        if (km.assignment[i] == s) members.push_back(i);
      if (!members.empty()) km.means[s] = principal_axis(poles, members);
    }
  }
  return km;
}

// Bayesian information criterion of a hard-assigned mixture of Fisher
// distributions: lower is better. Three parameters per set (mean, kappa)
// plus the k - 1 weights.
double mixture_bic(const std::vector<Eigen::Vector3d>& poles, const KMeans& km, int k) {
  double ll = 0;
  const double n = static_cast<double>(poles.size());
  for (int s = 0; s < k; ++s) {
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < poles.size(); ++i)
      if (km.assignment[i] == s) members.push_back(i);
    if (members.empty()) continue;
    const FisherStatistics f = fisher_of(poles, members);
    // Cap kappa: coincident poles would give an infinite likelihood.
    const double kappa = std::min(f.kappa, 1e4);
    const double weight = static_cast<double>(members.size()) / n;
    for (std::size_t i : members)
      ll += std::log(weight) + fisher_log_density(kappa, std::abs(poles[i].dot(f.mean)));
  }
  return -2 * ll + (4.0 * k - 1) * std::log(n);
}

bool sets_acceptable(const std::vector<Eigen::Vector3d>& poles, const KMeans& km, int k,
                     double min_separation) {
  for (int s = 0; s < k; ++s) {
    if (std::count(km.assignment.begin(), km.assignment.end(), s) < 2) return false;
    for (int t = s + 1; t < k; ++t)
      if (std::acos(std::min(1.0, std::abs(km.means[s].dot(km.means[t])))) < min_separation)
        return false;
  }
  (void)poles;
  return true;
}

std::optional<double> mean_gap(std::vector<double> positions, double merge) {
  std::sort(positions.begin(), positions.end());
  std::vector<double> distinct;
  for (double p : positions)
    if (distinct.empty() || p - distinct.back() > merge) distinct.push_back(p);
  if (distinct.size() < 2) return std::nullopt;
  return (distinct.back() - distinct.front()) / static_cast<double>(distinct.size() - 1);
}

int distinct_count(std::vector<double> positions, double merge) {
  std::sort(positions.begin(), positions.end());
  int n = 0;
  double last = -std::numeric_limits<double>::infinity();
  for (double p : positions)
    if (p - last > merge) {
      ++n;
      last = p;
    }
  return n;
}

}  // namespace

double alpha95_from(double kappa, std::size_t count) {
  if (count < 2 || !(kappa > 0)) return kPi;
  if (std::isinf(kappa)) return 0;
  const double n = static_cast<double>(count);
  return alpha95_of(n, n - (n - 1) / kappa);
}

double fisher_cone(double kappa, double fraction) {
  if (!(kappa > 0)) return kPi;
  if (std::isinf(kappa)) return 0;
  // 1 - cos t = -ln(1 - fraction (1 - exp(-2 K))) / K, with expm1 / log1p
  // so that a large K loses no digits.
  const double one_minus_cos = -std::log1p(fraction * std::expm1(-2 * kappa)) / kappa;
  return one_minus_cos >= 2 ? kPi : std::acos(1 - one_minus_cos);
}

FisherStatistics fisher_statistics(const std::vector<Eigen::Vector3d>& poles) {
  if (poles.empty()) throw InputError("poles", "no poles to average");
  std::vector<Eigen::Vector3d> unit;
  for (std::size_t i = 0; i < poles.size(); ++i) {
    if (!poles[i].allFinite() || poles[i].norm() == 0)
      throw InputError("poles[" + std::to_string(i) + "]", "is not a direction");
    unit.push_back(poles[i].normalized());
  }
  std::vector<std::size_t> all(unit.size());
  std::iota(all.begin(), all.end(), 0);
  return fisher_of(unit, all);
}

PoleClusters cluster_poles(const std::vector<Eigen::Vector3d>& poles_in,
                           const ClusterOptions& options) {
  PoleClusters out;
  if (poles_in.empty()) return out;
  std::vector<Eigen::Vector3d> poles;
  for (std::size_t i = 0; i < poles_in.size(); ++i) {
    if (!poles_in[i].allFinite() || poles_in[i].norm() == 0)
      throw InputError("poles[" + std::to_string(i) + "]", "is not a direction");
    poles.push_back(poles_in[i].normalized());
  }
  const int n = static_cast<int>(poles.size());
  if (options.count < 0) throw InputError("sets", "the number of sets cannot be negative");
  if (options.count > n)
    throw InputError("sets", "asks for " + std::to_string(options.count) + " sets from " +
                                 std::to_string(n) + " poles");
  const double separation = deg_to_rad(options.min_separation_deg);
  KMeans chosen;
  int k_chosen = 1;
  if (options.count > 0) {
    k_chosen = options.count;
    chosen = spherical_kmeans(poles, k_chosen);
  } else {
    chosen = spherical_kmeans(poles, 1);
    double best = mixture_bic(poles, chosen, 1);
    for (int k = 2; k <= std::min(options.max_count, n / 2); ++k) {
      KMeans km = spherical_kmeans(poles, k);
      if (!sets_acceptable(poles, km, k, separation)) continue;
      const double bic = mixture_bic(poles, km, k);
      if (bic < best) {
        best = bic;
        chosen = std::move(km);
        k_chosen = k;
      }
    }
  }
  // Sets by size, largest first; poles far from their set's mean are left out.
  const double max_angle = deg_to_rad(options.max_member_angle_deg);
  std::vector<std::vector<std::size_t>> members(k_chosen);
  for (int i = 0; i < n; ++i) {
    const int s = chosen.assignment[i];
    if (std::acos(std::min(1.0, std::abs(poles[i].dot(chosen.means[s])))) <= max_angle)
      members[s].push_back(static_cast<std::size_t>(i));
  }
  std::vector<int> by_size(k_chosen);
  std::iota(by_size.begin(), by_size.end(), 0);
  std::stable_sort(by_size.begin(), by_size.end(),
                   [&](int a, int b) { return members[a].size() > members[b].size(); });
  out.set_of.assign(n, -1);
  for (int rank = 0; rank < k_chosen; ++rank) {
    const auto& m = members[by_size[rank]];
    if (m.empty()) continue;
    const int label = static_cast<int>(out.sets.size());
    for (std::size_t i : m) out.set_of[i] = label;
    out.sets.push_back(fisher_of(poles, m));
  }
  return out;
}

std::vector<JointSetSummary> summarise_joint_sets(const std::vector<SetMember>& members,
                                                  const PoleClusters& clusters,
                                                  const std::optional<ScanLine>& scanline) {
  if (clusters.set_of.size() != members.size())
    throw InputError("sets", "the clustering does not belong to these " +
                                 std::to_string(members.size()) + " discontinuities");
  std::vector<JointSetSummary> out;
  for (std::size_t s = 0; s < clusters.sets.size(); ++s) {
    JointSetSummary j;
    j.label = "S" + std::to_string(s + 1);
    j.fisher = clusters.sets[s];
    const Eigen::Vector3d mean = j.fisher.mean;
    std::vector<double> offsets, crossings, lengths, uncensored;
    Eigen::Vector3d dir = Eigen::Vector3d::Zero();
    double line_length = 0;
    if (scanline) {
      dir = scanline->to - scanline->from;
      line_length = dir.norm();
      if (line_length > 0) dir /= line_length;
    }
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (clusters.set_of[i] != static_cast<int>(s)) continue;
      const SetMember& m = members[i];
      if (m.point) {
        offsets.push_back(mean.dot(*m.point));
        const Eigen::Vector3d n = m.normal.normalized();
        const double across = n.dot(dir);
        if (line_length > 0 && std::abs(across) > 1e-9) {
          const double t = n.dot(*m.point - scanline->from) / across;
          if (t >= 0 && t <= line_length) crossings.push_back(t);
        }
      }
      if (m.trace_length) {
        lengths.push_back(*m.trace_length);
        if (!m.censored) uncensored.push_back(*m.trace_length);
      }
    }
    j.spacing = mean_gap(offsets, kSameDiscontinuityM);
    j.spacing_gaps = std::max(0, distinct_count(offsets, kSameDiscontinuityM) - 1);
    if (line_length > 0) {
      const double c = std::abs(dir.dot(mean));
      if (c > 1e-9)
        if (auto g = mean_gap(crossings, kSameDiscontinuityM / c)) j.scanline_spacing = *g * c;
    }
    auto mean_of = [](const std::vector<double>& v) {
      return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
    };
    j.traces = static_cast<int>(lengths.size());
    j.censored_traces = static_cast<int>(lengths.size() - uncensored.size());
    if (!lengths.empty()) j.mean_trace_length = mean_of(lengths);
    if (!uncensored.empty()) j.mean_uncensored_trace_length = mean_of(uncensored);
    if (!uncensored.empty() && 2 * uncensored.size() >= lengths.size())
      j.persistence = j.mean_uncensored_trace_length;
    std::ostringstream text;
    if (lengths.empty())
      text << "no trace lengths";
    else if (j.censored_traces == 0)
      text << "all " << j.traces << " traces end inside the mapped area";
    else
      text << j.censored_traces << " of " << j.traces
           << " traces leave the mapped area: their lengths are lower bounds, so the mean of all "
              "traces underestimates the true mean"
           << (j.persistence ? "" : "; persistence not estimable from this window");
    j.censoring = text.str();
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace rockface::measure

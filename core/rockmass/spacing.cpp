#include "core/rockmass/spacing.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <map>
#include <numeric>

#include "core/common/number_format.h"
#include "core/rockmass/tolerances.h"

namespace rockface::rockmass {

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const double at = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(at));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (at - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

Histogram histogram_of(const std::vector<double>& values, int bins) {
  Histogram h;
  if (values.empty() || bins < 1) return h;
  const auto [lo_it, hi_it] = std::minmax_element(values.begin(), values.end());
  const double lo = *lo_it, hi = *hi_it;
  const double width = hi > lo ? (hi - lo) / bins : 1.0;
  for (int i = 0; i <= bins; ++i) h.edges.push_back(lo + width * i);
  h.counts.assign(bins, 0);
  for (double x : values) ++h.counts[std::min(bins - 1, static_cast<int>((x - lo) / width))];
  return h;
}

std::vector<SetSpacing> set_spacings(const std::vector<FaceTrace>& traces,
                                     const std::vector<SetInput>& sets, const SetTraces& assigned,
                                     const FaceWindow& window) {
  std::vector<SetSpacing> out;
  const double cap = 1.0 / std::cos(kBlindZoneDeg * M_PI / 180.0);
  for (std::size_t k = 0; k < sets.size(); ++k) {
    SetSpacing s;
    s.label = sets[k].label;
    const Eigen::Vector3d n = sets[k].normal.normalized();
    // One position per discontinuity: the pieces of one joint (same joint
    // label) averaged; unlabelled traces each their own.
    std::map<std::string, std::pair<double, int>> by_joint;
    std::vector<double> at;
    for (int i : assigned.members[k]) {
      const auto& pts = traces[i].points;
      if (pts.empty()) continue;
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (const auto& p : pts) c += p;
      const double x = n.dot(c / static_cast<double>(pts.size()));
      if (traces[i].joint_label.empty()) {
        at.push_back(x);
      } else {
        auto& [sum, count] = by_joint[traces[i].joint_label];
        sum += x;
        ++count;
      }
    }
    for (const auto& [label, sc] : by_joint) at.push_back(sc.first / sc.second);
    s.traces = static_cast<int>(assigned.members[k].size());
    std::sort(at.begin(), at.end());
    std::vector<double> merged;
    for (double x : at)
      if (merged.empty() || x - merged.back() > kSameDiscontinuityM) merged.push_back(x);
    s.discontinuities = static_cast<int>(merged.size());
    for (std::size_t i = 1; i < merged.size(); ++i) s.gaps_m.push_back(merged[i] - merged[i - 1]);

    const double sin_theta = window.normal.cross(n).norm();
    s.face_angle_deg = std::asin(std::min(1.0, sin_theta)) * 180.0 / M_PI;
    s.in_blind_zone = sin_theta < 1.0 / cap;
    s.terzaghi_weight = s.in_blind_zone ? cap : 1.0 / sin_theta;
    s.weighted_count = s.terzaghi_weight * s.discontinuities;

    if (!s.gaps_m.empty()) {
      const auto& g = s.gaps_m;
      const double mean = std::accumulate(g.begin(), g.end(), 0.0) / static_cast<double>(g.size());
      double ss = 0;
      for (double x : g) ss += (x - mean) * (x - mean);
      s.mean_m = mean;
      s.median_m = quantile(g, 0.5);
      s.min_m = *std::min_element(g.begin(), g.end());
      s.max_m = *std::max_element(g.begin(), g.end());
      s.p10_m = quantile(g, 0.1);
      s.p90_m = quantile(g, 0.9);
      if (g.size() >= 2) {
        s.std_m = std::sqrt(ss / static_cast<double>(g.size() - 1));
        s.cv = *s.std_m / mean;
        // Priest & Hudson 1976: random positions give a negative exponential
        // (CV 1); regular sets fall well below, clustered ones above.
        const char* shape = *s.cv < 0.5   ? "regular"
                            : *s.cv < 1.3 ? "close to negative exponential (random positions)"
                                          : "clustered";
        s.distribution = std::string(shape) + " (CV " + format_fixed(*s.cv, 2) + " over " +
                         std::to_string(g.size()) + " gaps)";
      } else {
        s.distribution = "one gap: no distribution";
      }
      s.histogram = histogram_of(g, std::clamp(static_cast<int>(std::sqrt(g.size())), 1, 10));
      if (!s.in_blind_zone) s.apparent_on_face_m = mean / sin_theta;
    } else {
      s.distribution = s.discontinuities == 1 ? "one located discontinuity: no spacing"
                                              : "no traces: no spacing";
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace rockface::rockmass

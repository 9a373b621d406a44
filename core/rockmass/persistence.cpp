#include "core/rockmass/persistence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rockface::rockmass {

namespace {

double polyline_length(const std::vector<Eigen::Vector3d>& p) {
  double l = 0;
  for (std::size_t i = 1; i < p.size(); ++i) l += (p[i] - p[i - 1]).norm();
  return l;
}

}  // namespace

const char* isrm_persistence_words(double l) {
  if (l < 1) return "very low persistence (< 1 m)";
  if (l < 3) return "low persistence (1-3 m)";
  if (l < 10) return "medium persistence (3-10 m)";
  if (l < 20) return "high persistence (10-20 m)";
  return "very high persistence (> 20 m)";
}

std::vector<SetPersistence> set_persistence(const std::vector<FaceTrace>& traces,
                                            const std::vector<SetInput>& sets,
                                            const SetTraces& assigned) {
  std::vector<SetPersistence> out;
  for (std::size_t k = 0; k < sets.size(); ++k) {
    SetPersistence p;
    p.label = sets[k].label;
    double all = 0, free = 0;
    int n_free = 0;
    for (int i : assigned.members[k]) {
      const FaceTrace& t = traces[i];
      const double l = t.length_m.value_or(polyline_length(t.points));
      ++p.traces;
      all += l;
      p.longest_m = std::max(p.longest_m.value_or(0.0), l);
      if (t.censored) {
        ++p.censored;
      } else {
        free += l;
        ++n_free;
      }
    }
    char text[200];
    if (p.traces > 0) {
      p.mean_all_m = all / p.traces;
      if (n_free > 0) p.mean_uncensored_m = free / n_free;
      if (2 * n_free >= p.traces && p.mean_uncensored_m) {
        p.persistence_m = p.mean_uncensored_m;
        std::snprintf(text, sizeof text,
                      "%d of %d traces leave the mapped area; persistence from the %d inside",
                      p.censored, p.traces, n_free);
      } else {
        p.lower_bound_m = p.mean_all_m;
        std::snprintf(text, sizeof text,
                      "%d of %d traces leave the mapped area: the window is too small to estimate "
                      "persistence; at least %.2f m (mean of all)",
                      p.censored, p.traces, *p.mean_all_m);
      }
      p.censoring = text;
      const double shown = p.persistence_m ? *p.persistence_m : *p.lower_bound_m;
      p.isrm_words =
          std::string(isrm_persistence_words(shown)) + (p.persistence_m ? "" : " or more");
    } else {
      p.censoring = "no traces";
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace rockface::rockmass

#pragma once
// Normal spacing of each set and its distribution (Priest 1993, ch. 4-5).
//
// A trace of a set lies on its discontinuity, so the position of that
// discontinuity along the set's mean normal n is n . c for any point c of
// the trace (its centroid is taken). Sorted, positions closer than
// kSameDiscontinuityM merged (one joint traced twice), the gaps are the
// normal spacings: their mean, median, spread and histogram.
//
// The face samples a set in proportion to sin(theta), theta the angle
// between the set's normal and the face's (a set parallel to the face shows
// no traces): Terzaghi's weight for the face window is 1 / sin(theta),
// capped at the blind zone (kBlindZoneDeg), and weighted_count is how many
// of the set the face would have shown were it perpendicular to the set.
// The scanline estimate (scanline_rqd.h) adds the line's Terzaghi
// correction beside it.
#include <optional>
#include <string>
#include <vector>

#include "core/rockmass/set_traces.h"

namespace rockface::rockmass {

struct Histogram {
  std::vector<double> edges;  // bins [edges[i], edges[i + 1])
  std::vector<int> counts;
};

struct SetSpacing {
  std::string label;
  int traces = 0;           // traces given to the set
  int discontinuities = 0;  // located, after merging
  std::vector<double> gaps_m;
  std::optional<double> mean_m, median_m, std_m, cv, min_m, max_m, p10_m, p90_m;
  // "close to negative exponential (CV 0.9)", "regular (CV 0.2)", ...
  std::string distribution;
  Histogram histogram;
  double face_angle_deg = 0;  // between the set's normal and the face's
  double terzaghi_weight = 1;
  bool in_blind_zone = false;
  double weighted_count = 0;
  // The set's apparent spacing along the face, across its traces: the
  // geologist's tape across the face (mean normal spacing / sin theta).
  std::optional<double> apparent_on_face_m;
};

std::vector<SetSpacing> set_spacings(const std::vector<FaceTrace>& traces,
                                     const std::vector<SetInput>& sets, const SetTraces& assigned,
                                     const FaceWindow& window);

// Summary statistics of a sample (helper shared with block sizes).
Histogram histogram_of(const std::vector<double>& values, int bins);
double quantile(std::vector<double> values, double q);

}  // namespace rockface::rockmass

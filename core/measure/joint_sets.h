#pragma once
// Joint sets from the measured planes: poles clustered into sets (a given
// count or automatic), Fisher statistics per set (mean pole, K, alpha95),
// spacing normal to the set or along a scan line, trace length with the
// censoring stated, and persistence where it can be estimated.
//
// Poles are axes: n and -n are the same plane. Statistics align each pole
// to the set's principal axis before summing (Fisher 1953; Priest 1993,
// "Discontinuity analysis for rock engineering", ch. 5).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/orientation.h"
#include "core/measure/tolerances.h"

namespace rockface::measure {

struct FisherStatistics {
  std::size_t count = 0;
  Eigen::Vector3d mean = Eigen::Vector3d::UnitZ();  // unit mean pole, upward (a plane's normal)
  double resultant = 0;  // R, length of the sum of the aligned unit poles
  // Best estimate of Fisher's K, (N - 1) / (N - R); +infinity when all poles
  // coincide, 0 for fewer than two.
  double kappa = 0;
  // Semi-angle (radians) of the 95 % cone of confidence about the mean:
  // cos a95 = 1 - (N - R) / R ((1 / 0.05)^(1 / (N - 1)) - 1); pi when undefined.
  double alpha95 = 0;
  geometry::PlaneOrientation plane() const { return geometry::plane_orientation(mean); }
};

// The 95 % cone of confidence of a set known only by its K and count (a
// set stored with them, its poles not kept): R = N - (N - 1) / K, then
// alpha95 as above (Fisher 1953). Radians; pi when undefined (N < 2, K not
// above 0), 0 when K is infinite.
double alpha95_from(double kappa, std::size_t count);

// The variability cone: the semi-angle (radians) about the mean holding
// `fraction` of a Fisher distribution's poles, P(angle <= t) =
// (1 - exp(-K (1 - cos t))) / (1 - exp(-2 K)); pi when K is not above 0,
// 0 when infinite. Where a set's joints lie, as alpha95 is where its mean lies.
double fisher_cone(double kappa, double fraction = 0.95);

// Throws InputError("poles", ...) when empty or a pole is not finite or zero.
FisherStatistics fisher_statistics(const std::vector<Eigen::Vector3d>& poles);

struct ClusterOptions {
  int count = 0;  // sets wanted; 0 = automatic (1 .. max_count)
  int max_count = 6;
  double max_member_angle_deg = kMaxSetMemberDeg;
  double min_separation_deg = kMinSetSeparationDeg;
};

struct PoleClusters {
  std::vector<int> set_of;             // per pole: its set, or -1 (not in any set)
  std::vector<FisherStatistics> sets;  // ordered by size, largest first
};

// Spherical k-means on axes with farthest-point seeding (deterministic).
// Automatic: the largest count whose sets are all at least
// min_separation_deg apart and hold at least two poles each.
PoleClusters cluster_poles(const std::vector<Eigen::Vector3d>& poles,
                           const ClusterOptions& options);

// One measured discontinuity as the statistics see it.
struct SetMember {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  std::optional<Eigen::Vector3d> point;  // a point on it (datum-relative), to locate it
  std::optional<double> trace_length;    // m
  bool censored = false;                 // its trace leaves the mapped area
};

struct ScanLine {
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
};

struct JointSetSummary {
  std::string label;  // "S1", "S2", ... in the order of PoleClusters::sets
  FisherStatistics fisher;
  // Mean spacing normal to the set (m): gaps between its located
  // discontinuities along the mean normal (kSameDiscontinuityM merges one
  // joint seen twice); needs two or more.
  std::optional<double> spacing;
  int spacing_gaps = 0;
  // Along the scan line: the true spacing from the apparent one (gaps
  // between where the planes cross the line, times |cos| of the angle
  // between line and mean normal).
  std::optional<double> scanline_spacing;
  // Trace length (m): mean of all traces, mean of those whose both ends are
  // in the mapped area; how many were censored. The mean of all is a lower
  // bound when any is censored.
  std::optional<double> mean_trace_length, mean_uncensored_trace_length;
  int traces = 0, censored_traces = 0;
  // Persistence (m): the mean uncensored trace length when at least half the
  // traces are uncensored; otherwise not estimable from this window.
  std::optional<double> persistence;
  std::string censoring;  // the censoring stated in words
};

std::vector<JointSetSummary> summarise_joint_sets(const std::vector<SetMember>& members,
                                                  const PoleClusters& clusters,
                                                  const std::optional<ScanLine>& scanline = {});

}  // namespace rockface::measure

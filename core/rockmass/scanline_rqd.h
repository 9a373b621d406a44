#pragma once
// RQD along virtual scanlines on the face, in three directions
// (horizontal, vertical and inclined at 45 deg up to the right), each
// kScanlinesPerDirection parallel lines spread evenly across the mapped
// outline. The traces cut each line into pieces; Deere's RQD is the share
// of the lines' length in pieces of kRqdPieceM or more (the window's edges
// end the first and last piece, as a core run's ends do).
//
// Beside it, Priest & Hudson's (1976) estimate from the discontinuity
// frequency lambda (per m), for a negative exponential spacing:
//   RQD = 100 e^(-0.1 lambda) (0.1 lambda + 1),
// once with the frequency counted on the lines and once with the
// frequency the sets' normal spacings give along the line,
// lambda = sum_i |cos delta_i| / S_i (delta_i between the line and set i's
// normal). Per set, the line's Terzaghi correction turns its apparent
// spacing into a normal one: S = apparent |cos delta|, not attempted inside
// the blind zone.
#include <optional>
#include <string>
#include <vector>

#include "core/rockmass/set_traces.h"
#include "core/rockmass/spacing.h"

namespace rockface::rockmass {

struct SetOnLine {
  std::string label;
  int crossings = 0;
  double cos_delta = 0;  // |cos| of the angle between the line and the set's normal
  bool in_blind_zone = false;
  std::optional<double> apparent_m, corrected_m;
};

struct ScanlineDirection {
  std::string name;      // "horizontal", "vertical", "inclined 45 deg"
  double angle_deg = 0;  // in the face, from horizontal towards up
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
  int lines = 0;
  double length_m = 0;  // summed over the lines
  int crossings = 0;
  double frequency_per_m = 0;
  std::optional<double> rqd_percent;                   // on the lines
  std::optional<double> priest_hudson_from_frequency;  // from frequency_per_m
  std::optional<double> frequency_from_sets_per_m;     // sum |cos delta| / S
  std::optional<double> priest_hudson_from_spacing;    // from that frequency
  std::vector<SetOnLine> sets;
};

struct ScanlineRqd {
  std::vector<ScanlineDirection> directions;
  // The mean of the three directions' RQD, and the lowest (RQD is
  // directional: the sheet takes the mean; the lowest says how far it goes).
  std::optional<double> rqd_percent, lowest_percent;
  std::optional<double> priest_hudson_from_spacing;  // mean over the directions
};

double priest_hudson_rqd(double frequency_per_m);

// `spacings` gives the sets' mean normal spacings (set_spacings, same
// order as `sets`); sets without one add no frequency.
ScanlineRqd scanline_rqd(const std::vector<FaceTrace>& traces, const SetTraces& assigned,
                         const std::vector<SetInput>& sets, const std::vector<SetSpacing>& spacings,
                         const FaceWindow& window);

}  // namespace rockface::rockmass

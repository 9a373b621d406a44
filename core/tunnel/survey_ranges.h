#pragma once
// The ranges a tunnel's survey values lie in. Values beyond them are typos
// or hostile input, not surveys: 1e308 in an alignment turned into null
// origins, zero wedges and a face "at offset 1000... (300 digits)" (issue
// 41). Every reader of an alignment (core/tunnel/alignment.h builds every
// one) and of a typed placement refuses them naming the field and the
// range.
#include <cmath>
#include <string>

#include <Eigen/Core>

#include "core/common/number_format.h"

namespace rockface::tunnel {

// Eastings and northings of any national grid or UTM zone (UTM northings
// reach 1e7 m) and chainages of any drive, with room: +-1e8 m.
inline constexpr double kMaxSurveyHorizontalM = 1e8;
// Elevations: from the deepest mine to above any mountain, with room.
inline constexpr double kMaxSurveyElevationM = 1e5;
// A typed placement stands the range pole in the excavation: no tunnel or
// cavern is wider or higher than 100 m, so it is at most 50 m from the
// axis across and up or down.
inline constexpr double kMaxTypedOffsetM = 50;

// Whether a point (E, N, elevation) lies within the ranges above: any
// point of a scene does, in survey coordinates or a local frame.
inline bool within_survey_ranges(const Eigen::Vector3d& v) {
  return std::abs(v.x()) <= kMaxSurveyHorizontalM && std::abs(v.y()) <= kMaxSurveyHorizontalM &&
         std::abs(v.z()) <= kMaxSurveyElevationM;
}
// "must be survey coordinates (easting and northing within +-1e+08 m,
// elevation within +-100000 m)", as the alignment's datum is refused.
inline std::string survey_ranges_refusal() {
  return "must be survey coordinates (easting and northing within +-" +
         format_significant(kMaxSurveyHorizontalM, 6) + " m, elevation within +-" +
         format_significant(kMaxSurveyElevationM, 6) + " m)";
}

}  // namespace rockface::tunnel

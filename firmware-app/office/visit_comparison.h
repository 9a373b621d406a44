#pragma once
// Two visits side by side (issue 46): the same face a round later. Sets
// are matched by the angle between their poles (axial: a pole and its
// opposite are one plane), nearest first, within kSameSetDeg; each match
// says its mean orientation then and now and the change in degrees, a set
// of the earlier visit left unmatched has vanished, one of the later is new.
// Blocks are matched by centroid, nearest first, within kSameBlockM and
// with volumes within a factor kSameBlockVolume; a match says whether the
// verdict changed. Every figure as text with its unit; each visit says who
// mapped it (its geologist, or "not recorded").
#include <string>

#include <nlohmann/json.hpp>

#include "storage/field_report/field_report.h"

namespace rockface::app::office_web {

// Farther apart than a set's scatter (alpha95 is a few degrees, Fisher
// cones of joint sets 10-20°) and nearer than two sets of one face.
inline constexpr double kSameSetDeg = 25.0;
// A block found again a round later lies where it was, give or take the
// traces' picking (centimetres) and the round's advance along the face;
// its volume within the blocks' reconstruction error.
inline constexpr double kSameBlockM = 0.5;
inline constexpr double kSameBlockVolume = 2.0;

nlohmann::json compare_visits(const storage::FieldReport& earlier,
                              const storage::FieldReport& later);

}  // namespace rockface::app::office_web

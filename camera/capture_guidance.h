#pragma once
// Capture guidance for a stereo pair, from EXIF and settings: both shots
// with the same focal length, focus and aperture, no flash; and the base
// length to walk between the stations once the distance to the face is
// known.
//
// A calibration holds for one focal length and one focus setting, so a
// pair shot with different ones is refused (require_same_optics); other
// differences are warnings the geologist may accept.
#include <string>
#include <vector>

#include "camera/exif.h"

namespace rockface::camera {

struct CaptureTolerances {
  // Zoom lenses report focal length to 1 mm or better; 0.5 % is far below
  // one zoom-ring step and above rounding of the EXIF rational.
  double focal_length_rel = 0.005;
  // Focus distance in EXIF comes in coarse steps (often 1/16 of the lens'
  // distance scale); 2 % or 1 cm, whichever is larger, separates "held" from "refocused".
  double focus_rel = 0.02;
  double focus_abs_m = 0.01;
};

struct GuidanceNote {
  enum class Severity { warning, refusal };
  Severity severity = Severity::warning;
  std::string text;
};

// Problems of one shot on its own (flash fired; focal length unknown).
std::vector<GuidanceNote> check_shot(const ExifInfo& shot, const std::string& label);

// Everything worth telling about a pair, refusals first.
std::vector<GuidanceNote> check_pair(const ExifInfo& left, const ExifInfo& right,
                                     const CaptureTolerances& tolerances = {});

// Throws InputError("stereo pair", ...) when the two shots were taken with
// different focal length or focus: one calibration cannot serve both.
void require_same_optics(const ExifInfo& left, const ExifInfo& right,
                         const CaptureTolerances& tolerances = {});

// Base length between the stations: 1/8 to 1/5 of the distance to the face
// (narrower loses depth precision, wider loses overlap and matching).
struct BaseLengthHint {
  double min_m = 0, max_m = 0;
  std::string text;
};
BaseLengthHint base_length_hint(double distance_m);

}  // namespace rockface::camera

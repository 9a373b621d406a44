#include "camera/capture_guidance.h"

#include <cmath>

#include "core/common/error.h"
#include "core/common/number_format.h"

namespace rockface::camera {

std::vector<GuidanceNote> check_shot(const ExifInfo& shot, const std::string& label) {
  std::vector<GuidanceNote> notes;
  if (shot.flash_fired && *shot.flash_fired)
    notes.push_back({GuidanceNote::Severity::warning,
                     "the flash fired on the " + label +
                         " shot: flash shadows move with the camera and spoil matching; "
                         "switch the flash off"});
  if (!shot.focal_length_mm)
    notes.push_back(
        {GuidanceNote::Severity::warning, "the " + label +
                                              " shot has no focal length in its EXIF, so rockface "
                                              "cannot check that it matches the calibration"});
  return notes;
}

std::vector<GuidanceNote> check_pair(const ExifInfo& left, const ExifInfo& right,
                                     const CaptureTolerances& tol) {
  std::vector<GuidanceNote> refusals, warnings;
  if (left.focal_length_mm && right.focal_length_mm) {
    const double a = *left.focal_length_mm, b = *right.focal_length_mm;
    if (std::abs(a - b) > tol.focal_length_rel * std::max(a, b))
      refusals.push_back({GuidanceNote::Severity::refusal,
                          "the left shot was taken at " + format_significant(a, 3, " mm") +
                              " focal length and the "
                              "right at " +
                              format_significant(b, 3, " mm") +
                              ": one calibration cannot serve both; set the zoom once "
                              "(tape the ring) and retake the pair"});
  }
  if (left.focus_distance_m && right.focus_distance_m) {
    const double a = *left.focus_distance_m, b = *right.focus_distance_m;
    if (std::abs(a - b) > std::max(tol.focus_abs_m, tol.focus_rel * std::max(a, b)))
      refusals.push_back({GuidanceNote::Severity::refusal,
                          "the camera refocused between the shots (" +
                              format_significant(a, 3, " m") + " then " +
                              format_significant(b, 3, " m") +
                              "): focusing moves the lens and changes the calibration; lock "
                              "focus (or switch the lens to MF) and retake the pair"});
  }
  if (left.f_number && right.f_number && std::abs(*left.f_number - *right.f_number) > 0.05)
    warnings.push_back({GuidanceNote::Severity::warning,
                        "the aperture changed between the shots (f/" +
                            format_significant(*left.f_number, 3, " ") + "then f/" +
                            format_significant(*right.f_number, 3, " ") +
                            "); use aperture priority with a fixed f-number"});
  if (!left.model.empty() && !right.model.empty() && left.model != right.model)
    warnings.push_back({GuidanceNote::Severity::warning, "the shots come from two camera bodies (" +
                                                             left.model + ", " + right.model +
                                                             "); each needs its own calibration"});
  for (const auto& n : check_shot(left, "left")) warnings.push_back(n);
  for (const auto& n : check_shot(right, "right")) warnings.push_back(n);
  refusals.insert(refusals.end(), warnings.begin(), warnings.end());
  return refusals;
}

void require_same_optics(const ExifInfo& left, const ExifInfo& right,
                         const CaptureTolerances& tol) {
  for (const auto& note : check_pair(left, right, tol))
    if (note.severity == GuidanceNote::Severity::refusal)
      throw InputError("stereo pair", note.text);
}

BaseLengthHint base_length_hint(double distance_m) {
  if (!(distance_m > 0) || !std::isfinite(distance_m))
    throw InputError("distance to the face", "must be a positive number of metres");
  BaseLengthHint h;
  h.min_m = distance_m / 8;
  h.max_m = distance_m / 5;
  h.text = "at " + format_fixed(distance_m, 1, " m") + " from the face, place the two stations " +
           format_fixed(h.min_m, 2) + " to " + format_fixed(h.max_m, 2, " m") + " apart";
  return h;
}

}  // namespace rockface::camera

#include "core/tunnel/visit_placement.h"
#include "core/tunnel/survey_ranges.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/tunnel/face_front.h"
#include "core/tunnel/surface_reach.h"

namespace rockface::tunnel {

namespace {

// The face is the surface within this band (m of chainage) of the farthest
// 1 % of the vertices: a face leans and is rough by a few decimetres.
constexpr double kFaceBandM = 0.3;

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// A chainage in a message: to the centimetre, as the surveyor writes it;
// one beyond any alignment (1e308, a typo or a fuzzed file) to 6
// significant digits, not 300 (issue 41).
std::string chainage_text(double chainage) {
  constexpr double kLongestChainageM = 1e9;
  return std::abs(chainage) < kLongestChainageM ? format_fixed(chainage, 2)
                                                : format_significant(chainage, 6);
}

}  // namespace

Eigen::Vector3d typed_pole_position(const Alignment& alignment, double chainage, double offset,
                                    double height) {
  if (!alignment.contains(chainage)) {
    throw InputError("tunnel.placement.chainage",
                     chainage_text(chainage) + " is off the alignment (" +
                         format_fixed(alignment.first_chainage(), 2) + " to " +
                         format_fixed(alignment.last_chainage(), 2) + ")");
  }
  // The pole stands in the excavation: an offset of 130 m was taken
  // without a word and placed the visit in the rock (issue 41).
  for (auto [value, field] :
       {std::pair{offset, "tunnel.placement.offset"}, std::pair{height, "tunnel.placement.height"}})
    if (!(std::abs(value) <= kMaxTypedOffsetM)) {
      // %g: 1e308 is not 300 digits.
      throw InputError(field, format_significant(value, 6, " m") +
                                  " from the axis is more than any tunnel's half-width (at most " +
                                  format_fixed(kMaxTypedOffsetM, 0, " m") +
                                  "): a typo, or the pole outside the excavation?");
    }
  return alignment.frame_at(chainage).to_local(offset, height);
}

VisitPlacement place_visit(const Alignment& alignment, const DesignProfile& profile,
                           const SurfaceInput& surface, const FrameRegistration& registration,
                           const std::string& visit) {
  // Without north the 3D image's turn about the vertical is the camera's:
  // its walls would be compared with the design profile at a random angle.
  if (registration.method == VisitPlacement::Method::chainage_compass && !registration.north_known)
    throw InputError(visit,
                     "its 3D image has no north (no compass line was given with the range pole): "
                     "a placement by chainage needs the compass line's azimuth; or place it by "
                     "monitoring targets with survey coordinates");
  const double sense = alignment.drive() == Drive::ascending ? 1.0 : -1.0;
  const std::vector<AlignmentPlace> places = rock_places(alignment, surface);
  const auto reach = surface_reach(alignment, places);
  if (!reach) throw InputError(visit, "its 3D image has no rock to place");
  double face_ahead = sense * reach->front;
  const double rear = reach->rear;
  if (const auto front = face_front(alignment, profile, surface, rear))
    face_ahead = sense * front->median_chainage;
  std::vector<double> offsets, heights;
  for (const auto& p : places)
    if (sense * p.chainage >= face_ahead - kFaceBandM) {
      offsets.push_back(p.offset);
      heights.push_back(p.height);
    }
  VisitPlacement out;
  out.chainage = sense * face_ahead;
  out.offset_m = median(offsets);
  out.height_m = median(heights);
  if (!alignment.contains(out.chainage)) {
    throw InputError(visit, "its face lies at chainage " + chainage_text(out.chainage) +
                                ", off the alignment (" +
                                format_fixed(alignment.first_chainage(), 2) + " to " +
                                format_fixed(alignment.last_chainage(), 2) + ")");
  }
  out.method = registration.method;
  if (registration.method == VisitPlacement::Method::ground_control) {
    out.residuals = registration.residuals;
    out.rms_m = registration.rms_m;
    out.note = std::to_string(registration.residuals.size()) +
               " monitoring targets with survey coordinates";
  } else {
    out.compass_azimuth_deg = registration.compass_azimuth_deg;
    out.note = registration.typed.empty()
                   ? "range pole at its surveyed position, north from the compass line"
                   : "range pole at " + registration.typed + ", north from the compass line";
  }
  return out;
}

}  // namespace rockface::tunnel

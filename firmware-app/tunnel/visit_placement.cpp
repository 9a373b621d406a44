#include "firmware-app/tunnel/visit_placement.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/tunnel/survey_ranges.h"
#include "firmware-app/tunnel/face_front.h"

namespace rockface::app {

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

}  // namespace

Eigen::Vector3d typed_pole_position(const tunnel::Alignment& alignment, double chainage,
                                    double offset, double height) {
  if (!alignment.contains(chainage)) {
    throw InputError("tunnel.placement.chainage",
                     format_fixed(chainage, 2) + " is off the alignment (" +
                         format_fixed(alignment.first_chainage(), 2) + " to " +
                         format_fixed(alignment.last_chainage(), 2) + ")");
  }
  // The pole stands in the excavation: an offset of 130 m was taken
  // without a word and placed the visit in the rock (issue 41).
  for (auto [value, field] :
       {std::pair{offset, "tunnel.placement.offset"}, std::pair{height, "tunnel.placement.height"}})
    if (!(std::abs(value) <= tunnel::kMaxTypedOffsetM)) {
      std::ostringstream v;  // %g: 1e308 is not 300 digits
      v.precision(6);
      v << value << " m";
      throw InputError(field, v.str() +
                                  " from the axis is more than any tunnel's half-width (at most " +
                                  format_fixed(tunnel::kMaxTypedOffsetM, 0, " m") +
                                  "): a typo, or the pole outside the excavation?");
    }
  return alignment.frame_at(chainage).to_local(offset, height);
}

storage::VisitPlacement place_visit(const tunnel::Alignment& alignment,
                                    const tunnel::DesignProfile& profile,
                                    const VisitSurface& surface, storage::RecordId visit_id,
                                    const std::string& typed) {
  const std::string where = "visit " + std::to_string(visit_id);
  const double sense = alignment.drive() == tunnel::Drive::ascending ? 1.0 : -1.0;
  const std::vector<tunnel::AlignmentPlace> places = rock_places(alignment, surface);
  const auto reach = surface_reach(alignment, places);
  if (!reach) throw InputError(where, "its 3D image has no rock to place");
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
  storage::VisitPlacement out;
  out.visit_id = visit_id;
  out.chainage = sense * face_ahead;
  out.offset_m = median(offsets);
  out.height_m = median(heights);
  if (!alignment.contains(out.chainage)) {
    throw InputError(where, "its face lies at chainage " + format_fixed(out.chainage, 2) +
                                ", off the alignment (" +
                                format_fixed(alignment.first_chainage(), 2) + " to " +
                                format_fixed(alignment.last_chainage(), 2) + ")");
  }
  const storage::Model& m = surface.first;
  if (m.registration.kind == "ground_control") {
    out.method = storage::VisitPlacement::Method::ground_control;
    out.residuals = m.residuals;
    out.rms_m = m.registration.rms_m;
    out.note = std::to_string(m.residuals.size()) + " monitoring targets with survey coordinates";
  } else {
    out.method = storage::VisitPlacement::Method::chainage_compass;
    const nlohmann::json p = nlohmann::json::parse(m.registration.parameters_json, nullptr, false);
    const nlohmann::json::json_pointer at("/registration/north/azimuth_deg");
    if (!p.is_discarded() && p.contains(at) && p[at].is_number())
      out.compass_azimuth_deg = p[at].get<double>();
    out.note = typed.empty() ? "range pole at its surveyed position, north from the compass line"
                             : "range pole at " + typed + ", north from the compass line";
  }
  return out;
}

std::optional<storage::VisitPlacement> known_placement(storage::ProjectStore& store,
                                                       const storage::TunnelRecord& tunnel,
                                                       storage::RecordId visit_id) {
  if (auto stored = store.load_visit_placement(visit_id)) return stored;
  const auto models = store.list_visit_models(visit_id);
  if (models.empty() || models.front().registration_kind != "ground_control") return std::nullopt;
  return place_visit(tunnel.alignment(store.project().datum), tunnel.profile,
                     visit_surface(store, visit_id), visit_id);
}

}  // namespace rockface::app

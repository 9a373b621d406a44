#include "firmware-app/tunnel/visit_placement.h"

#include "storage/project/model_registration.h"

namespace rockface::app {

tunnel::FrameRegistration frame_registration(const VisitSurface& surface,
                                             const std::string& typed) {
  const storage::Model& m = surface.first;
  const storage::ModelRegistration reg = storage::read_model_registration(m.registration);
  tunnel::FrameRegistration out;
  if (reg.kind == "ground_control" || reg.kind == storage::kScannerRegistration) {
    // A scan in survey coordinates was registered to the site's control by
    // its surveyor: placed as ground control is, with no residuals of ours.
    out.method = tunnel::VisitPlacement::Method::ground_control;
    for (const auto& r : m.residuals) out.residuals.push_back({r.label, r.residual});
    out.rms_m = m.registration.rms_m;
  } else {
    out.method = tunnel::VisitPlacement::Method::chainage_compass;
    out.compass_azimuth_deg = reg.compass_azimuth_deg;
    out.north_known = reg.oriented();
    out.typed = typed;
  }
  return out;
}

storage::VisitPlacement place_visit(const tunnel::Alignment& alignment,
                                    const tunnel::DesignProfile& profile,
                                    const VisitSurface& surface, storage::RecordId visit_id,
                                    const std::string& typed) {
  storage::VisitPlacement out;
  static_cast<tunnel::VisitPlacement&>(out) =
      tunnel::place_visit(alignment, profile, surface_input(surface),
                          frame_registration(surface, typed), "visit " + std::to_string(visit_id));
  out.visit_id = visit_id;
  return out;
}

std::optional<storage::VisitPlacement> known_placement(storage::ProjectStore& store,
                                                       const storage::TunnelRecord& tunnel,
                                                       storage::RecordId visit_id) {
  if (auto stored = store.load_visit_placement(visit_id)) return stored;
  const auto models = store.list_visit_models(visit_id);
  if (models.empty()) return std::nullopt;
  const std::string& kind = models.front().registration_kind;
  if (kind != "ground_control" && kind != storage::kScannerRegistration) return std::nullopt;
  storage::VisitPlacement placed =
      place_visit(tunnel.alignment(store.project().datum), tunnel.profile,
                  visit_surface(store, visit_id), visit_id);
  if (kind == storage::kScannerRegistration) {
    placed.note =
        std::string("a scan in survey coordinates (") + storage::kScannerRegistrationWords + ")";
    placed.rms_m.reset();  // the surveyor's residuals are not in the file
  }
  return placed;
}

}  // namespace rockface::app

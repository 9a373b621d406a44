#include "firmware-app/tunnel/replay_tunnel.h"

#include "core/common/number_format.h"
#include "firmware-app/tunnel/visit_placement.h"
#include "firmware-app/tunnel/visit_surface.h"

namespace rockface::app {

std::optional<Eigen::Vector3d> typed_range_pole(const storage::Scene& scene) {
  if (!scene.tunnel || !scene.tunnel->placement) return std::nullopt;
  const auto& p = *scene.tunnel->placement;
  const Eigen::Vector3d origin = scene.has_datum ? scene.datum : Eigen::Vector3d::Zero();
  return tunnel::typed_pole_position(scene.tunnel->record.alignment(origin), p.chainage, p.offset,
                                     p.height);
}

std::string place_replayed_visit(storage::ProjectStore& store, const storage::Scene& scene,
                                 storage::RecordId visit_id) {
  if (!scene.tunnel) return {};
  std::optional<storage::TunnelRecord> tunnel = store.load_tunnel();
  std::string note;
  if (!tunnel) {
    store.save_tunnel(scene.tunnel->record);
    tunnel = scene.tunnel->record;
    note = "tunnel " + tunnel->name + " stored in the project; ";
  }
  const tunnel::Alignment alignment = tunnel->alignment(store.project().datum);
  const VisitSurface surface = visit_surface(store, visit_id);
  std::string typed;
  if (scene.tunnel->placement) {
    typed = "chainage " + format_fixed(scene.tunnel->placement->chainage, 2) + ", offset " +
            format_fixed(scene.tunnel->placement->offset, 2, " m") + " (typed)";
  }
  const storage::VisitPlacement placement =
      place_visit(alignment, tunnel->profile, surface, visit_id, typed);
  store.save_visit_placement(placement);
  return note + "visit placed in the tunnel: face at chainage " +
         format_fixed(placement.chainage, 2) + ", offset " +
         format_fixed(placement.offset_m, 2, " m") + " (" + placement.note + ")";
}

}  // namespace rockface::app

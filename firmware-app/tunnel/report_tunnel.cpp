#include "firmware-app/tunnel/report_tunnel.h"

#include "core/analysis/block_reading.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/tunnel/tunnel_relative.h"
#include "firmware-app/tunnel/visit_placement.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "firmware-app/tunnel/visit_profile_json.h"
#include "storage/field_report/tunnel_pictures.h"

namespace rockface::app {

void add_tunnel_to_report(storage::ProjectStore& store, storage::FieldReport& report, Preset preset,
                          const DriveFaces* faces) {
  const auto record = store.load_tunnel();
  if (!record) return;
  const tunnel::Alignment alignment = record->alignment(store.project().datum);
  storage::ReportedTunnel t;
  t.name = record->name;
  t.drive = tunnel::drive_name(record->drive);
  t.profile_name = record->profile.name();
  t.first_chainage = alignment.first_chainage();
  t.last_chainage = alignment.last_chainage();
  t.perimeter_m = record->profile.perimeter();
  t.area_m2 = record->profile.area();
  t.underbreak_tolerance_m = record->underbreak_tolerance_m;
  t.placement = known_placement(store, *record, report.visit_id);
  // A visit placed by its typed chainage alone (planes typed in, no
  // photographs yet) is reported without its round: there is no surface to
  // measure it on, and the rest of the report still stands.
  if (t.placement && store.list_visit_models(report.visit_id).empty()) {
    t.profile_lines.push_back("no 3D image of this visit: the round is not measured");
  } else if (t.placement) {
    const VisitProfile profile = visit_profile(store, report.visit_id, preset, faces);
    // The summary's first line is the visit's place, which the report's
    // tunnel section prints from the placement above it (issue 39: the
    // place was printed twice, in two sizes).
    const std::vector<std::string> summary = visit_profile_summary(profile);
    t.profile_lines.assign(summary.begin() + (summary.empty() ? 0 : 1), summary.end());
    if (profile.deviation.status != tunnel::DeviationStatus::no_walls_in_view)
      t.developed_view = storage::developed_view_picture(profile.deviation, record->profile);
  }
  // The drive's direction where the visit is (its face, else the middle).
  const double at = t.placement ? t.placement->chainage
                                : 0.5 * (alignment.first_chainage() + alignment.last_chainage());
  const Eigen::Vector3d drive = alignment.tangent_at(at);
  auto plane_row = [&](const std::string& label, double dip, double dipdir,
                       const std::optional<Eigen::Vector3d>& point) {
    const Eigen::Vector3d normal = geometry::plane_normal_deg(dip, dipdir);
    storage::ReportedTunnelPlane row;
    row.label = label;
    row.dip_deg = dip;
    row.dipdir_deg = dipdir;
    tunnel::StrikeVsDrive s = tunnel::strike_vs_drive(normal, drive);
    if (point) {
      const tunnel::PlaneInTunnel in = tunnel::plane_in_tunnel(alignment, *point, normal);
      row.chainage = in.place.chainage;
      row.offset_m = in.place.offset;
      s = in.strike;
    }
    row.strike_class = s.words;
    row.rmr_adjustment = s.rmr_adjustment;
    row.margin_deg = s.margin_deg;
    row.marginal = s.marginal;
    t.planes.push_back(row);
  };
  for (const auto& set : report.sets) plane_row(set.label, set.dip_deg, set.dipdir_deg, {});
  for (const auto& j : store.list_joints(report.visit_id))
    plane_row(j.label, j.dip_deg, j.dipdir_deg, j.point);
  for (const auto& b : report.blocks) {
    if (b.vertices.empty()) continue;
    // The alignment works in the project frame (datum-relative).
    const auto vertices = analysis::relative_to(b.vertices, report.datum);
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto& v : vertices) centroid += v;
    centroid /= static_cast<double>(vertices.size());
    const tunnel::AlignmentPlace place = alignment.place(centroid);
    t.blocks.push_back(
        {b.id, alignment.to_survey(centroid), place.chainage, place.offset, place.height});
  }
  report.tunnel = std::move(t);
}

}  // namespace rockface::app

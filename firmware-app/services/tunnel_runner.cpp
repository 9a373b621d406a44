// The tablet's tunnel views (ui::TunnelRunner): each opens its own
// connection to the project (one per thread) and runs what the verbs
// `tunnel`, `profile`, `drive` and `place` run.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/number_format.h"
#include "firmware-app/services/ui_services.h"
#include "firmware-app/tunnel/project_drive.h"
#include "firmware-app/tunnel/tunnel_from_files.h"
#include "firmware-app/tunnel/typed_placement.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "storage/field_report/tunnel_pictures.h"
#include "storage/project/project_store.h"

namespace rockface::app {

namespace {

storage::ProjectStore open_read_only(const std::filesystem::path& project) {
  storage::OpenOptions read;
  read.read_only = true;
  return storage::ProjectStore::open(project, read);
}

}  // namespace

std::string StoreTunnelRunner::give_tunnel(const std::filesystem::path& project,
                                           const ui::TunnelFileChoice& files, Progress& progress) {
  progress.step("reading the alignment and the design profile", 0.1);
  TunnelFiles options;
  options.alignment = files.alignment.string();
  options.profile = files.profile.string();
  options.name = files.name;
  return give_project_its_tunnel(project, options).summary;
}

ui::ExcavationView StoreTunnelRunner::profile(const std::filesystem::path& project,
                                              storage::RecordId visit_id, Progress& progress) {
  progress.step("excavation against the design", 0.1);
  storage::ProjectStore store = open_read_only(project);
  const VisitProfile p = visit_profile(store, visit_id);
  progress.step("developed view", 0.9);
  const tunnel::ProfileDeviation& d = p.deviation;
  ui::ExcavationView v;
  v.lines.push_back("tunnel " + p.tunnel.name + ", face at chainage " +
                    format_fixed(p.placement.chainage, 2) + " m; the round from chainage " +
                    format_fixed(p.round_from, 2) + " m (" + p.round_from_source + ") to " +
                    format_fixed(p.round_to, 2) + " m.");
  v.message = d.message;
  v.compared = !d.view.chainage.empty() && !d.view.s.empty() &&
               d.status != tunnel::DeviationStatus::no_walls_in_view &&
               d.status != tunnel::DeviationStatus::outside_alignment;
  if (!v.compared) return v;
  const tunnel::DesignProfile& profile = p.tunnel.profile;
  v.perimeter_m = profile.perimeter();
  for (auto [angle, name] :
       {std::pair{-std::numbers::pi / 2, "invert"}, std::pair{0.0, "right wall"},
        std::pair{std::numbers::pi / 2, "crown"}, std::pair{std::numbers::pi, "left wall"}})
    v.places.push_back({name, profile.ray_hit(angle).s});
  v.chainage_bottom = d.view.chainage.front();
  v.chainage_top = d.view.chainage.back();
  v.scale_m = storage::developed_view_scale_m(d);
  v.tolerance_m = d.underbreak_tolerance_m;
  // The cells at the field report's resolution (900 px across the outline),
  // as tall as the round at the same metres per pixel (bounded).
  const int w = 900;
  const double length = std::abs(v.chainage_top - v.chainage_bottom);
  const int h = std::clamp(static_cast<int>(std::lround(std::max(length, 0.5) * w / v.perimeter_m)),
                           160, 900);
  v.cells_margin_px = 8;  // the outline and the marker may cross the frame
  v.cells = cv::Mat(h + 2 * v.cells_margin_px + 1, w + 2 * v.cells_margin_px + 1, CV_8UC3,
                    cv::Scalar(255, 255, 255));
  storage::draw_developed_view_cells(v.cells, {v.cells_margin_px, v.cells_margin_px}, w, h, d,
                                     profile, v.scale_m);
  v.overbreak_m3 = d.overbreak_volume_m3;
  v.underbreak_m3 = d.underbreak_volume_m3;
  v.overbreak_sigma_m3 = d.overbreak_volume_sigma_m3;
  v.underbreak_sigma_m3 = d.underbreak_volume_sigma_m3;
  v.seen_fraction = d.seen_fraction;
  if (d.has_underbreak) {
    v.deepest_underbreak_m = d.max_underbreak_m;
    v.deepest_underbreak_chainage = d.max_underbreak.chainage;
    v.deepest_underbreak_s_m = d.max_underbreak.s;
  }
  if (d.max_overbreak_m > 0) {
    v.largest_overbreak_m = d.max_overbreak_m;
    v.largest_overbreak_chainage = d.max_overbreak.chainage;
    v.largest_overbreak_s_m = d.max_overbreak.s;
  }
  v.patches_beyond_tolerance = static_cast<int>(d.beyond_tolerance.size());
  return v;
}

ui::DriveJoints StoreTunnelRunner::drive(const std::filesystem::path& project, Progress& progress) {
  progress.step("joints and sets along the drive", 0.1);
  storage::ProjectStore store = open_read_only(project);
  const tunnel::DriveSets d = project_drive(store);
  ui::DriveJoints out;
  out.visits = static_cast<int>(d.visits.size());
  for (const auto& v : d.visits)
    for (const auto& j : visit_joint_orientations(store, v.visit_id))
      out.joints.push_back({v.visit_id, v.chainage, j.label, j.dip_deg, j.dipdir_deg});
  for (const auto& t : d.tracks) {
    ui::DriveSetTrack track;
    track.id = t.id;
    for (const auto& p : t.points)
      track.points.push_back({p.chainage, p.dip_deg, p.dipdir_deg, p.turned});
    for (auto [on, word] :
         {std::pair{t.appears, "new"}, std::pair{t.turns, "turns"}, std::pair{t.vanishes, "gone"}})
      if (on) track.flags += (track.flags.empty() ? "" : ", ") + std::string(word);
    out.sets.push_back(std::move(track));
  }
  out.lines = drive_summary(d, drive_geologists(store));
  out.lines.front() += ", " + std::to_string(out.joints.size()) + " measured joints";
  return out;
}

std::vector<std::string> StoreTunnelRunner::place(const std::filesystem::path& project,
                                                  storage::RecordId visit_id, double chainage,
                                                  double offset, double height,
                                                  Progress& progress) {
  progress.step("moving the 3D images to the typed chainage", 0.2);
  storage::ProjectStore store = storage::ProjectStore::open(project);
  const storage::VisitPlacement p =
      place_by_typed_chainage(store, visit_id, {chainage, offset, height});
  return {"visit " + std::to_string(static_cast<long long>(visit_id)) +
              " placed: face at chainage " + format_fixed(p.chainage, 2) + ", offset " +
              format_fixed(p.offset_m, 2, " m"),
          p.note};
}

}  // namespace rockface::app

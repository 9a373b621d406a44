// ProjectStore: the project's tunnel (alignment, design profile, drive,
// underbreak tolerance) and the place of each visit in it (schema 5).
#include <cmath>

#include "core/common/error.h"
#include "storage/project/project_store.h"
#include "storage/project/project_store_rows.h"
#include "storage/tunnel/tunnel_records.h"

namespace rockface::storage {

using namespace rows;  // row helpers and the SQLite wrappers

const char* placement_method_name(VisitPlacement::Method m) {
  return m == VisitPlacement::Method::ground_control ? "ground_control" : "chainage_compass";
}

namespace {

VisitPlacement::Method method_of(const std::string& text, const std::string& where) {
  if (text == "ground_control") return VisitPlacement::Method::ground_control;
  if (text == "chainage_compass") return VisitPlacement::Method::chainage_compass;
  throw Error(where + ": unknown placement method '" + text + "'");
}

}  // namespace

void ProjectStore::save_tunnel(const TunnelRecord& t) {
  const std::string doing = "saving the tunnel";
  require_writable(doing);
  if (t.name.empty()) throw InputError("tunnel.name", "must not be empty");
  require_finite(t.underbreak_tolerance_m, "tunnel.underbreak_tolerance_m");
  if (t.underbreak_tolerance_m < 0)
    throw InputError("tunnel.underbreak_tolerance_m", "must not be negative");
  if (!t.polyline && t.radii.size() + 1 != t.stations.size())
    throw InputError("tunnel.radii",
                     "one radius per element (" +
                         std::to_string(t.stations.empty() ? 0 : t.stations.size() - 1) +
                         "), got " + std::to_string(t.radii.size()));
  // The table must make an alignment and the profile a valid outline: what
  // is stored can always be used.
  const ProjectInfo info = project();
  try {
    (void)t.alignment(info.datum);
  } catch (const InputError& e) {
    throw InputError("tunnel." + e.where(), e.reason());
  }
  t.profile.require_valid("tunnel.profile");

  WriteTransaction tx(db_, doing);
  db_.exec("DELETE FROM tunnel_station; DELETE FROM tunnel_profile_segment; DELETE FROM tunnel",
           doing);
  Statement head(db_,
                 "INSERT INTO tunnel (id, name, alignment_kind, drive, underbreak_tolerance_m, "
                 "profile_name, ray_centre_u, ray_centre_v, alignment_source, profile_source, "
                 "created_at) VALUES (1, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                 doing);
  std::optional<double> cu, cv;
  if (t.profile.ray_centre_given()) {
    cu = t.profile.ray_centre().x();
    cv = t.profile.ray_centre().y();
  }
  head.bind(1, t.name)
      .bind(2, t.polyline ? "polyline" : "elements")
      .bind(3, tunnel::drive_name(t.drive))
      .bind(4, t.underbreak_tolerance_m)
      .bind(5, t.profile.name())
      .bind(6, cu)
      .bind(7, cv)
      .bind(8, t.alignment_source)
      .bind(9, t.profile_source)
      .bind(10, or_now(t.created_at));
  head.run();
  Statement st(db_,
               "INSERT INTO tunnel_station (tunnel_id, idx, chainage, easting, northing, "
               "elevation, radius_m) VALUES (1, ?, ?, ?, ?, ?, ?)",
               doing);
  for (std::size_t i = 0; i < t.stations.size(); ++i) {
    const auto& s = t.stations[i];
    std::optional<double> radius;
    if (!t.polyline && i < t.radii.size()) radius = t.radii[i];
    st.reset();
    st.bind(1, static_cast<std::int64_t>(i))
        .bind(2, s.chainage)
        .bind(3, s.survey.x())
        .bind(4, s.survey.y())
        .bind(5, s.survey.z())
        .bind(6, radius);
    st.run();
  }
  Statement seg(db_,
                "INSERT INTO tunnel_profile_segment (tunnel_id, idx, kind, from_u, from_v, to_u, "
                "to_v, centre_u, centre_v, ccw) VALUES (1, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                doing);
  const auto& segments = t.profile.segments();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto& s = segments[i];
    const bool arc = s.kind == tunnel::ProfileSegment::Kind::arc;
    seg.reset();
    seg.bind(1, static_cast<std::int64_t>(i))
        .bind(2, arc ? "arc" : "line")
        .bind(3, s.from.x())
        .bind(4, s.from.y())
        .bind(5, s.to.x())
        .bind(6, s.to.y())
        .bind(7, arc ? std::optional<double>(s.centre.x()) : std::nullopt)
        .bind(8, arc ? std::optional<double>(s.centre.y()) : std::nullopt)
        .bind(9, arc ? std::optional<std::int64_t>(s.ccw ? 1 : 0) : std::nullopt);
    seg.run();
  }
  insert_log(std::nullopt, "tunnel saved",
             t.name + ": " + std::to_string(t.stations.size()) + " stations (" +
                 (t.polyline ? "polyline" : "elements") + "), " + std::to_string(segments.size()) +
                 " profile segments, drive " + tunnel::drive_name(t.drive));
  tx.commit();
}

std::optional<TunnelRecord> ProjectStore::load_tunnel() {
  const std::string doing = "loading the tunnel";
  ReadTransaction tx(db_);
  Statement head(db_,
                 "SELECT name, alignment_kind, drive, underbreak_tolerance_m, profile_name, "
                 "ray_centre_u, ray_centre_v, alignment_source, profile_source, created_at FROM "
                 "tunnel WHERE id = 1",
                 doing);
  if (!head.step()) return std::nullopt;
  TunnelRecord t;
  RowReader row(head);
  t.name = row.next_text();
  t.polyline = row.next_text() == "polyline";
  t.drive = tunnel::drive_of(row.next_text(), file_.string() + ": tunnel.drive");
  t.underbreak_tolerance_m = row.next_double();
  const std::string profile_name = row.next_text();
  const auto cu = row.next_optional_double();
  const auto cv = row.next_optional_double();
  t.alignment_source = row.next_text();
  t.profile_source = row.next_text();
  t.created_at = row.next_text();

  Statement st(db_,
               "SELECT chainage, easting, northing, elevation, radius_m FROM tunnel_station WHERE "
               "tunnel_id = 1 ORDER BY idx",
               doing);
  std::vector<std::optional<double>> radii;
  while (st.step()) {
    RowReader r(st);
    tunnel::AlignmentStation s;
    s.chainage = r.next_double();
    s.survey = next_vector3(r);
    t.stations.push_back(s);
    radii.push_back(r.next_optional_double());
  }
  if (!t.polyline)
    for (std::size_t i = 0; i + 1 < radii.size(); ++i) t.radii.push_back(radii[i].value_or(0.0));

  Statement seg(db_,
                "SELECT kind, from_u, from_v, to_u, to_v, centre_u, centre_v, ccw FROM "
                "tunnel_profile_segment WHERE tunnel_id = 1 ORDER BY idx",
                doing);
  std::vector<tunnel::ProfileSegment> segments;
  while (seg.step()) {
    RowReader r(seg);
    const std::string kind = r.next_text();
    const double fu = r.next_double(), fv = r.next_double(), tu = r.next_double(),
                 tv = r.next_double();
    if (kind == "arc") {
      const auto cu2 = r.next_optional_double(), cv2 = r.next_optional_double();
      const auto ccw = r.next_optional_int64();
      if (!cu2 || !cv2) throw Error(file_.string() + ": the tunnel's stored profile is damaged");
      segments.push_back(
          tunnel::ProfileSegment::arc({fu, fv}, {tu, tv}, {*cu2, *cv2}, ccw.value_or(1) != 0));
    } else {
      segments.push_back(tunnel::ProfileSegment::line({fu, fv}, {tu, tv}));
    }
  }
  std::optional<Eigen::Vector2d> centre;
  if (cu && cv) centre = Eigen::Vector2d(*cu, *cv);
  t.profile = tunnel::DesignProfile(std::move(segments), centre, profile_name);
  return t;
}

void ProjectStore::save_visit_placement(const VisitPlacement& p) {
  const std::string doing = "saving the visit's place in the tunnel";
  require_writable(doing);
  const std::string where = "visit " + std::to_string(p.visit_id) + " placement";
  require_finite(p.chainage, where + ".chainage");
  require_finite(p.offset_m, where + ".offset_m");
  if (p.height_m) require_finite(*p.height_m, where + ".height_m");
  if (p.rms_m) require_finite(*p.rms_m, where + ".rms_m");
  if (p.compass_azimuth_deg) {
    require_finite(*p.compass_azimuth_deg, where + ".compass_azimuth_deg");
    if (*p.compass_azimuth_deg < 0 || *p.compass_azimuth_deg >= 360)
      throw InputError(where + ".compass_azimuth_deg", "must be in [0, 360) degrees");
  }
  for (const auto& r : p.residuals)
    require_finite(r.residual, where + ".residuals (" + r.label + ")");
  if (p.method == VisitPlacement::Method::ground_control && p.residuals.empty())
    throw InputError(where + ".residuals",
                     "a placement by ground control keeps the residuals of its targets");
  if (p.method == VisitPlacement::Method::chainage_compass && !p.residuals.empty())
    throw InputError(where + ".residuals", "a typed chainage has no target residuals");

  WriteTransaction tx(db_, doing);
  Statement del(db_, "DELETE FROM visit_placement_residual WHERE visit_id = ?", doing);
  del.bind(1, p.visit_id);
  del.run();
  Statement del2(db_, "DELETE FROM visit_placement WHERE visit_id = ?", doing);
  del2.bind(1, p.visit_id);
  del2.run();
  Statement st(db_,
               "INSERT INTO visit_placement (visit_id, method, chainage, offset_m, height_m, "
               "rms_m, compass_azimuth_deg, note, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
               doing);
  st.bind(1, p.visit_id)
      .bind(2, placement_method_name(p.method))
      .bind(3, p.chainage)
      .bind(4, p.offset_m)
      .bind(5, p.height_m)
      .bind(6, p.rms_m)
      .bind(7, p.compass_azimuth_deg)
      .bind(8, p.note)
      .bind(9, or_now(p.created_at));
  try {
    st.run();
  } catch (const Error& e) {
    throw InputError(where, std::string("cannot be saved (is there a visit ") +
                                std::to_string(p.visit_id) + "?): " + e.what());
  }
  Statement res(db_,
                "INSERT INTO visit_placement_residual (visit_id, idx, label, dx, dy, dz) VALUES "
                "(?, ?, ?, ?, ?, ?)",
                doing);
  for (std::size_t i = 0; i < p.residuals.size(); ++i) {
    const auto& r = p.residuals[i];
    res.reset();
    res.bind(1, p.visit_id)
        .bind(2, static_cast<std::int64_t>(i))
        .bind(3, r.label)
        .bind(4, r.residual.x())
        .bind(5, r.residual.y())
        .bind(6, r.residual.z());
    res.run();
  }
  insert_log(p.visit_id, "visit placed in the tunnel",
             std::string(placement_method_name(p.method)) + ", chainage " +
                 std::to_string(p.chainage) + ", offset " + std::to_string(p.offset_m) + " m");
  tx.commit();
}

namespace {

std::vector<VisitPlacement> read_placements(sqlite::Connection& db, const std::string& file,
                                            std::optional<RecordId> visit_id) {
  const std::string doing = "loading visit placements";
  Statement st(db,
               std::string("SELECT visit_id, method, chainage, offset_m, height_m, rms_m, "
                           "compass_azimuth_deg, note, created_at FROM visit_placement WHERE ") +
                   (visit_id ? "visit_id = ?1" : "?1 IS NULL") + " ORDER BY chainage, visit_id",
               doing);
  st.bind(1, visit_id);
  std::vector<VisitPlacement> out;
  while (st.step()) {
    RowReader r(st);
    VisitPlacement p;
    p.visit_id = r.next_int64();
    p.method = method_of(r.next_text(), file + ": visit_placement");
    p.chainage = r.next_double();
    p.offset_m = r.next_double();
    p.height_m = r.next_optional_double();
    p.rms_m = r.next_optional_double();
    p.compass_azimuth_deg = r.next_optional_double();
    p.note = r.next_text();
    p.created_at = r.next_text();
    out.push_back(p);
  }
  Statement res(db,
                "SELECT label, dx, dy, dz FROM visit_placement_residual WHERE visit_id = ? ORDER "
                "BY idx",
                doing);
  for (auto& p : out) {
    res.reset();
    res.bind(1, p.visit_id);
    while (res.step()) {
      RowReader r(res);
      tunnel::TargetResidual rr;
      rr.label = r.next_text();
      rr.residual = next_vector3(r);
      p.residuals.push_back(rr);
    }
  }
  return out;
}

}  // namespace

std::optional<VisitPlacement> ProjectStore::load_visit_placement(RecordId visit_id) {
  ReadTransaction tx(db_);
  auto all = read_placements(db_, file_.string(), visit_id);
  if (all.empty()) return std::nullopt;
  return all.front();
}

std::vector<VisitPlacement> ProjectStore::list_visit_placements() {
  ReadTransaction tx(db_);
  return read_placements(db_, file_.string(), std::nullopt);
}

}  // namespace rockface::storage

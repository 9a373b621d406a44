#include "firmware-app/office/office_pages.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/geometry/orientation.h"
#include "core/rockmass/figures_in_words.h"
#include "firmware-app/office/office_workflows.h"
#include "storage/office/server_records.h"
#include "storage/office/server_schema.h"
#include "storage/project/model_registration.h"
#include "storage/project/visit_geologist.h"

namespace rockface::app::office_web {

namespace office = storage::office;
using nlohmann::json;

namespace {

std::int64_t tunnel_id(office::Connection& c, const std::string& tunnel) {
  const office::Result r = c.query("SELECT id FROM rockface.tunnel WHERE name = $1",
                                   {office::Param::of(tunnel)}, "finding the tunnel");
  // Row-level security hides a tunnel the role may not read: the same
  // answer as one that does not exist.
  if (r.rows() == 0) throw InputError("tunnel " + tunnel, "no such tunnel for this log-in");
  return r.int64(0, 0);
}

// "dd/ddd" as geologists write an orientation, whole degrees.
std::string dip_and_direction_text(double dip, double dipdir) {
  return format_fixed(dip, 0, "°") + " / " + format_fixed(dipdir, 0, "°");
}

std::string optional_fixed(const std::optional<double>& v, int decimals, std::string_view unit) {
  return v ? format_fixed(*v, decimals, unit) : std::string("–");
}

// A volume with three significant digits: blocks from litres to hundreds
// of cubic metres.
std::string volume_text(double m3) {
  return format_significant(m3, 3, " m³");
}

json point(const Eigen::Vector3d& p) {
  // Millimetres are finer than any trace is picked to.
  auto mm = [](double v) { return std::round(v * 1000.0) / 1000.0; };
  return json::array({mm(p.x()), mm(p.y()), mm(p.z())});
}

}  // namespace

json tunnels_page(office::Connection& c) {
  const office::Result r = c.query(
      "SELECT t.name, count(v.uuid), max(v.started_at), "
      "(SELECT min(l.c)::text || ' ' || max(l.c)::text FROM (SELECT DISTINCT ON (uuid) "
      "(body->'row'->>'chainage')::float8 AS c, deleted FROM rockface.record WHERE tunnel_id = "
      "t.id AND kind = 'visit_placement' ORDER BY uuid, revision DESC) l WHERE NOT l.deleted) "
      "FROM rockface.tunnel t LEFT JOIN rockface.visit v ON v.tunnel_id = t.id "
      "GROUP BY t.id, t.name ORDER BY t.name",
      {}, "reading the tunnels");
  json out = json::array();
  for (int i = 0; i < r.rows(); ++i) {
    json t;
    t["name"] = r.text(i, 0);
    t["visits"] = r.int64(i, 1);
    t["last_visit"] = r.is_null(i, 2) ? "no visit yet" : r.text(i, 2);
    if (r.is_null(i, 3)) {
      t["drive_length"] = "no visit placed";
    } else {
      double lo = 0, hi = 0;
      std::sscanf(r.text(i, 3).c_str(), "%lf %lf", &lo, &hi);
      // Chainage is surveyed to the centimetre; the length is read in metres.
      t["drive_length"] = format_fixed(hi - lo, 1, " m") + " (ch " + format_fixed(lo, 1, " m") +
                          " to " + format_fixed(hi, 1, " m") + ")";
    }
    out.push_back(std::move(t));
  }
  return out;
}

std::string tunnel_stamp(office::Connection& c, const std::string& tunnel) {
  const std::int64_t id = tunnel_id(c, tunnel);
  const office::Result r = c.query(
      "SELECT count(*)::text || '/' || coalesce(max(synced_at)::text, '') FROM rockface.record "
      "WHERE tunnel_id = $1",
      {office::Param::of(id)}, "reading the tunnel's state");
  return r.text(0, 0);
}

json drive_page(office::Connection& c, const std::string& tunnel, const DriveFilter& filter) {
  return drive_page(read_drive_page(c, tunnel, filter));
}

DriveRead read_drive_page(office::Connection& c, const std::string& tunnel,
                          const DriveFilter& filter) {
  const std::int64_t id = tunnel_id(c, tunnel);
  DriveRead read;
  json& out = read.page;
  out["tunnel"] = tunnel;
  out["stamp"] = tunnel_stamp(c, tunnel);
  // One query for the visit list: the latest live revision of the records
  // it needs, then per visit its placement, note and the blocks of its
  // latest analysis (a record's reference to another is {"$ref": uuid},
  // storage/office/record_documents.h).
  const office::Result r = c.query(
      "WITH live AS (SELECT * FROM (SELECT DISTINCT ON (kind, uuid) kind, uuid, visit_uuid, "
      "project_uuid, local_id, deleted, body FROM rockface.record WHERE tunnel_id = $1 AND kind IN "
      "('visit', 'visit_placement', 'visit_heading', 'visit_geologist', 'analysis', 'block') "
      "ORDER BY kind, uuid, "
      "revision DESC) l "
      "WHERE NOT deleted), "
      "last_analysis AS (SELECT DISTINCT ON (visit_uuid) visit_uuid, uuid::text AS aid FROM live "
      "WHERE kind = 'analysis' ORDER BY visit_uuid, local_id DESC), "
      "blocks AS (SELECT b.visit_uuid, count(*) AS n, "
      "count(*) FILTER (WHERE b.body->'row'->>'removable' IN ('1', 'true') AND "
      "coalesce(b.body->'row'->>'mode', 'none') NOT IN ('none', '')) AS moving, "
      "max((b.body->'row'->>'volume_m3')::float8) FILTER (WHERE b.body->'row'->>'removable' IN "
      "('1', 'true')) AS largest FROM live b JOIN last_analysis a ON a.visit_uuid = b.visit_uuid "
      "AND b.body->'row'->'analysis_id'->>'$ref' = a.aid WHERE b.kind = 'block' GROUP BY "
      "b.visit_uuid), "
      // Joined, not looked up per visit: a subquery per row over `live`
      // grows as the square of the visits (3,000 visits took minutes).
      "placements AS (SELECT visit_uuid, body->'row'->>'chainage' AS chainage FROM live WHERE "
      "kind = 'visit_placement'), "
      "notes AS (SELECT uuid, body->'row'->>'note' AS note FROM live WHERE kind = 'visit'), "
      // A visit's heading is a record of its own, keyed by the visit's uuid.
      "headings AS (SELECT uuid, body->'row'->>'heading' AS heading FROM live WHERE kind = "
      "'visit_heading'), "
      // And so is the geologist who mapped it (storage/project/visit_geologist.h).
      "geologists AS (SELECT uuid, body->'row'->>'geologist' AS geologist FROM live WHERE kind = "
      "'visit_geologist') "
      // Every visit of the tunnel, the filter's verdict a column of its
      // own: the list of headings is read from all of them (from a drive
      // filtered by one heading the others must stay choosable), the
      // latest heading records once for both.
      "SELECT v.uuid::text, v.started_at, v.owner, p.name, pl.chainage, n.note, bl.n, "
      "bl.moving, bl.largest, h.heading, "
      "($2 = '' OR v.started_at >= $2) AND ($3 = '' OR left(v.started_at, 10) <= $3) "
      "AND ($4 = '' OR v.owner = $4) AND ($5 = '' OR coalesce(h.heading, $6) = $5), "
      "g.geologist "
      "FROM rockface.visit v JOIN rockface.project p ON p.uuid = v.project_uuid "
      "LEFT JOIN placements pl ON pl.visit_uuid = v.uuid LEFT JOIN notes n ON n.uuid = v.uuid "
      "LEFT JOIN blocks bl ON bl.visit_uuid = v.uuid LEFT JOIN headings h ON h.uuid = v.uuid "
      "LEFT JOIN geologists g ON g.uuid = v.uuid "
      "WHERE v.tunnel_id = $1 "
      "ORDER BY v.started_at, v.project_uuid, v.local_id",
      {office::Param::of(id), office::Param::of(filter.from), office::Param::of(filter.to),
       office::Param::of(filter.tablet), office::Param::of(filter.heading),
       office::Param::of(std::string(kNoHeading))},
      "reading the drive's visits");
  json visits = json::array();
  std::map<std::string, int> tablets;
  // The headings named among all the tunnel's visits, whatever the filter.
  std::set<std::string> all_headings;
  for (int i = 0; i < r.rows(); ++i) {
    all_headings.insert(r.is_null(i, 9) ? std::string(kNoHeading) : r.text(i, 9));
    if (r.text(i, 10) != "t") continue;  // not the filter's
    json v;
    v["id"] = r.text(i, 0);
    v["date"] = r.text(i, 1);
    v["tablet"] = r.text(i, 2);
    v["project"] = r.text(i, 3);
    ++tablets[r.text(i, 2)];
    if (!r.is_null(i, 4)) {
      const double ch = std::strtod(r.text(i, 4).c_str(), nullptr);
      v["chainage"] = ch;
      v["chainage_text"] = format_fixed(ch, 2, " m");
    } else {
      v["chainage_text"] = "not placed";
    }
    v["note"] = r.is_null(i, 5) ? "" : r.text(i, 5);
    v["heading"] = r.is_null(i, 9) ? kNoHeading : r.text(i, 9);
    // Text for the page (its own text node: escaped by the browser), never
    // "" for a visit without one.
    v["geologist"] = r.is_null(i, 11) ? std::string(storage::kGeologistNotRecorded) : r.text(i, 11);
    const std::int64_t n = r.is_null(i, 6) ? 0 : r.int64(i, 6);
    v["blocks"] = n;
    v["moving"] = r.is_null(i, 7) ? 0 : r.int64(i, 7);
    v["largest_block"] =
        r.is_null(i, 8) ? "–" : volume_text(std::strtod(r.text(i, 8).c_str(), nullptr));
    visits.push_back(std::move(v));
  }
  out["visits"] = std::move(visits);
  json tablet_list = json::array();
  for (const auto& [name, n] : tablets) tablet_list.push_back(name);
  out["tablets"] = std::move(tablet_list);
  // "—" last: the visits without one.
  json heading_list = json::array();
  for (const auto& name : all_headings)
    if (name != kNoHeading) heading_list.push_back(name);
  if (all_headings.count(kNoHeading)) heading_list.push_back(kNoHeading);
  out["headings"] = std::move(heading_list);

  // The drive's records of sets: tracked in drive_page (no server).
  try {
    office::require_compatible_server(c);
    read.drive = office::read_server_drive(c, tunnel);
  } catch (const InputError& e) {
    c.exec("ROLLBACK", "ending the drive's reading");
    read.sets_note = std::string("no sets along the drive: ") + e.what();
  }
  return read;
}

json drive_page(DriveRead read) {
  json out = std::move(read.page);
  // The sets along the drive: the same tracks as `rockface drive
  // postgresql://...` (firmware-app/office/office_workflows.h).
  json tracks = json::array();
  out["sets_note"] = read.sets_note;
  if (read.drive) {
    try {
      const tunnel::DriveSets d = server_drive(*read.drive);
      for (const auto& t : d.tracks) {
        json track;
        track["name"] = "set " + std::to_string(t.id);
        std::string flags;
        if (t.appears) flags += "new ";
        if (t.turns) flags += "turns ";
        if (t.vanishes) flags += "vanishes";
        track["flags"] = flags;
        json points = json::array();
        for (const auto& p : t.points) {
          json q;
          q["chainage"] = p.chainage;
          q["dip"] = p.dip_deg;
          q["dipdir"] = p.dipdir_deg;
          q["turned"] = p.turned;
          // alpha95 gives the fitting precision of the mean orientation.
          q["text"] = "ch " + format_fixed(p.chainage, 1, " m") + ": " +
                      dip_and_direction_text(p.dip_deg, p.dipdir_deg) +
                      (p.alpha95_deg < 180 ? " ±" + format_fixed(p.alpha95_deg, 0, "°") : "") +
                      " (" + std::to_string(p.count) + " planes)";
          points.push_back(std::move(q));
        }
        track["points"] = std::move(points);
        json events = json::array();
        for (const auto& e : t.events) events.push_back(e.message);
        track["events"] = std::move(events);
        tracks.push_back(std::move(track));
      }
    } catch (const InputError& e) {
      tracks = json::array();
      out["sets_note"] = std::string("no sets along the drive: ") + e.what();
    }
  }
  out["sets"] = std::move(tracks);
  return out;
}

json visit_page(const storage::FieldReport& report, const std::string& visit_uuid,
                const Eigen::Vector3d& origin) {
  json out;
  out["id"] = visit_uuid;
  out["started_at"] = report.visit_started_at;
  out["source"] = report.visit_source;
  out["geologist"] = report.visit_geologist.value_or(storage::kGeologistNotRecorded);
  out["project"] = report.project_name;
  out["camera"] = report.camera_body + (report.lens.empty() ? "" : ", " + report.lens);
  out["preset"] = report.preset;
  const Eigen::Vector3d shift = report.datum + origin;

  json figures = json::array();
  auto figure = [&](const std::string& name, const std::string& value) {
    figures.push_back(json{{"name", name}, {"value", value}});
  };
  const auto& a = report.accuracy;
  figure("scale from", a.scale_source.empty() ? "–" : a.scale_source);
  if (a.range_pole_m) figure("range pole", format_fixed(*a.range_pole_m, 3, " m"));
  // What the visit's record does not state is said, never shown as zero
  // (issue 41: a visit measured on another visit's 3D image).
  auto known = [](const std::optional<double>& v, double factor, int digits, const char* unit) {
    return v ? format_fixed(*v * factor, digits, unit) : std::string("not known");
  };
  figure("distance to the face", known(a.distance_m, 1, 1, " m"));
  figure("depth precision (1 sigma)", known(a.sigma_z_m, 1000, 1, " mm"));
  figure("point spacing", known(a.point_spacing_m, 1000, 1, " mm"));
  figure("reprojection RMS", known(a.reprojection_rms_px, 1, 2, " px"));
  if (a.control_rms_m)
    figure("control points RMS", format_fixed(*a.control_rms_m * 1000, 1, " mm"));
  out["figures"] = std::move(figures);
  json warnings = json::array();
  for (const auto& w : a.warnings) warnings.push_back(w);
  out["warnings"] = std::move(warnings);

  json sets = json::array();
  for (const auto& s : report.sets)
    sets.push_back({{"label", s.label},
                    {"orientation", dip_and_direction_text(s.dip_deg, s.dipdir_deg)},
                    {"dip", s.dip_deg},
                    {"dipdir", s.dipdir_deg},
                    {"count", s.count},
                    {"fisher_k", std::isfinite(s.fisher_k) ? format_fixed(s.fisher_k, 0) : "∞"},
                    {"alpha95", optional_fixed(s.alpha95_deg, 1, "°")}});
  out["sets"] = std::move(sets);
  json joints = json::array();
  for (const auto& j : report.joints)
    joints.push_back({{"label", j.label},
                      {"set", j.set_label.empty() ? "–" : j.set_label},
                      {"orientation", dip_and_direction_text(j.dip_deg, j.dipdir_deg)},
                      {"friction", optional_fixed(j.friction_deg, 0, "°")},
                      {"cohesion", j.cohesion_pa ? format_fixed(*j.cohesion_pa / 1000, 0, " kPa")
                                                 : std::string("–")}});
  out["joints"] = std::move(joints);
  // The stereonet's poles (lower hemisphere, equal area, drawn in the page).
  json poles = json::array();
  for (std::size_t i = 0; i < report.poles.size(); ++i) {
    const geometry::PlaneOrientation o = geometry::plane_orientation(report.poles[i]);
    constexpr double deg = 180.0 / 3.14159265358979323846;
    poles.push_back({{"dip", o.dip * deg},
                     {"dipdir", o.dipdir * deg},
                     {"set", i < report.pole_sets.size() ? report.pole_sets[i] : -1}});
  }
  out["poles"] = std::move(poles);

  // Each trace with its set (an index into `sets`, the stereonet's and the
  // legend's colour; -1 none). Traces are stored in the project frame, the
  // blocks below with the datum added.
  json traces = json::array();
  for (std::size_t i = 0; i < report.traces.size(); ++i) {
    const auto& [label, pts] = report.traces[i];
    json line = json::array();
    for (const auto& p : pts) line.push_back(point(p - origin));
    const int set = i < report.trace_sets.size() ? report.trace_sets[i] : -1;
    traces.push_back({{"label", label}, {"set", set}, {"points", std::move(line)}});
  }
  out["traces"] = std::move(traces);

  json blocks = json::array();
  for (const auto& b : report.blocks) {
    json block;
    block["label"] = b.id;
    block["verdict"] = storage::report_verdict(b);
    block["verdict_kind"] = !b.finite ? "infinite" : b.removable ? "removable" : "keyed";
    block["marginal"] = b.marginal;
    block["margin"] = format_fixed(b.margin_deg, 1, "°");
    block["mode"] = storage::report_mode(b);
    block["fos"] =
        b.fos ? format_fixed(*b.fos, 2) + (b.fos_marginal ? " (marginal)" : "") : std::string("–");
    block["volume"] = b.volume ? volume_text(*b.volume) : std::string("–");
    block["mass"] = b.mass ? format_significant(*b.mass / 1000, 3, " t") : std::string("–");
    block["rotation"] = storage::report_rotation(b);
    block["motion"] = b.dynamics ? b.dynamics->outcome : std::string("–");
    json outline = json::array();
    for (const auto& v : b.vertices) outline.push_back(point(v - shift));
    block["vertices"] = std::move(outline);
    json faces = json::array();
    for (const auto& f : b.faces) faces.push_back(f);
    block["faces"] = std::move(faces);
    blocks.push_back(std::move(block));
  }
  out["blocks"] = std::move(blocks);

  json tunnel = json::object();
  if (report.tunnel) {
    const auto& t = *report.tunnel;
    tunnel["name"] = t.name;
    tunnel["profile"] = t.profile_name;
    tunnel["chainage"] = t.placement ? format_fixed(t.placement->chainage, 2, " m") : "not placed";
    tunnel["lines"] = t.profile_lines;
    // The developed view is served as a picture (/api/visit/picture).
    tunnel["has_developed_view"] = !t.developed_view.empty();
  }
  out["tunnel"] = std::move(tunnel);
  json wedges = json::object();
  if (report.wedges) {
    wedges["lines"] = report.wedges->lines;
    wedges["rows"] = report.wedges->rows;
    wedges["notes"] = report.wedges->notes;
    wedges["has_picture"] = !report.wedges->picture.empty();
  }
  out["wedges"] = std::move(wedges);
  json rockmass = json::object();
  if (report.rockmass) {
    rockmass["rmr"] = rockmass::rmr_line(report.rockmass->rmr);
    rockmass["q"] = rockmass::q_line(report.rockmass->q);
    rockmass["lines"] = rockmass::figures_lines(*report.rockmass);
  } else {
    rockmass["note"] = report.rockmass_note;
  }
  out["rockmass"] = std::move(rockmass);
  json support = json::object();
  if (report.support) {
    support["proposals"] = report.support->proposals;
    support["decision"] = report.support->decision;
  }
  out["support"] = std::move(support);
  return out;
}

namespace {

const storage::ModelSummary* first_model(const std::vector<storage::ModelSummary>& models) {
  return models.empty() ? nullptr : &models.front();
}

Eigen::Vector3d centre_of(const storage::Mesh& mesh) {
  if (mesh.vertices.empty()) return Eigen::Vector3d::Zero();
  Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
  for (const auto& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return 0.5 * (lo + hi);
}

template <typename T>
void put(std::vector<std::uint8_t>& out, const T& value) {
  const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
  out.insert(out.end(), p, p + sizeof(T));
}

}  // namespace

json range_pole_overlay(const storage::Model& model, const Eigen::Vector3d& origin) {
  const storage::ModelRegistration r = storage::read_model_registration(model.registration);
  if (!r.has_pole || r.targets_project.size() < 2) return nullptr;
  json pole;
  pole["targets"] =
      json::array({point(r.targets_project[0] - origin), point(r.targets_project[1] - origin)});
  // The pole's length is set on the tablet to the millimetre.
  pole["length"] =
      r.pole_length_m && *r.pole_length_m > 0 ? format_fixed(*r.pole_length_m, 3, " m") : "–";
  return pole;
}

Eigen::Vector3d face_origin(storage::ProjectStore& store, storage::RecordId visit_id) {
  const auto models = store.list_visit_models(visit_id);
  const auto* m = first_model(models);
  if (!m) return Eigen::Vector3d::Zero();
  return centre_of(store.load_model(m->id).mesh);
}

FaceMesh face_mesh(storage::ProjectStore& store, storage::RecordId visit_id,
                   std::size_t max_triangles) {
  const auto models = store.list_visit_models(visit_id);
  const auto* m = first_model(models);
  if (!m) throw InputError("visit " + std::to_string(visit_id), "has no 3D image");
  const storage::Mesh mesh = store.load_model(m->id).mesh;
  const Eigen::Vector3d origin = centre_of(mesh);
  FaceMesh out;
  out.full_triangles = mesh.faces.size();

  // Vertex clustering: cells of size h; h grows by 1.25 until the
  // surviving triangles fit. The first vertex of a cell represents it, so
  // its texture coordinate stays a real one.
  std::vector<std::int32_t> remap(mesh.vertices.size());
  std::vector<std::int32_t> kept;  // new index -> old index
  std::vector<std::array<std::int32_t, 3>> faces;
  auto cluster = [&](double h) {
    kept.clear();
    faces.clear();
    if (h <= 0) {
      for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        remap[i] = static_cast<std::int32_t>(i);
        kept.push_back(static_cast<std::int32_t>(i));
      }
      faces = mesh.faces;
      return;
    }
    std::unordered_map<std::uint64_t, std::int32_t> cells;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const Eigen::Vector3d q = (mesh.vertices[i] - origin) / h;
      // 21 bits per axis: 2 million cells a side is far beyond any face.
      const auto key = [](double v) {
        return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v)) + (1 << 20)) &
               0x1fffff;
      };
      const std::uint64_t k = key(q.x()) | (key(q.y()) << 21) | (key(q.z()) << 42);
      const auto [it, added] = cells.emplace(k, static_cast<std::int32_t>(kept.size()));
      if (added) kept.push_back(static_cast<std::int32_t>(i));
      remap[i] = it->second;
    }
    for (const auto& f : mesh.faces) {
      const std::array<std::int32_t, 3> g = {remap[f[0]], remap[f[1]], remap[f[2]]};
      if (g[0] != g[1] && g[1] != g[2] && g[0] != g[2]) faces.push_back(g);
    }
  };
  cluster(0);
  if (max_triangles > 0 && mesh.faces.size() > max_triangles) {
    // Start from the spacing a uniform grid of max_triangles / 2 vertices
    // over the face's extent would have.
    Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
    for (const auto& v : mesh.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    const Eigen::Vector3d size = hi - lo;
    const double area = std::max({size.x() * size.y(), size.y() * size.z(), size.x() * size.z()});
    double h = std::sqrt(area / (static_cast<double>(max_triangles) / 2.0));
    for (int round = 0; round < 40; ++round) {
      cluster(h);
      if (faces.size() <= max_triangles) break;
      h *= 1.25;
    }
  }
  const bool uv = mesh.texcoords.size() == mesh.vertices.size();
  out.vertices = kept.size();
  out.triangles = faces.size();
  std::vector<std::uint8_t>& b = out.bytes;
  b.reserve(32 + kept.size() * 20 + faces.size() * 12);
  b.insert(b.end(), {'R', 'F', 'M', '1'});
  put(b, static_cast<std::uint32_t>(kept.size()));
  put(b, static_cast<std::uint32_t>(faces.size()));
  put(b, static_cast<std::uint32_t>(uv ? 1 : 0));
  for (int k = 0; k < 3; ++k) put(b, origin[k]);
  for (std::int32_t i : kept) {
    const Eigen::Vector3d p = mesh.vertices[static_cast<std::size_t>(i)] - origin;
    for (int k = 0; k < 3; ++k) put(b, static_cast<float>(p[k]));
  }
  if (uv)
    for (std::int32_t i : kept)
      for (int k = 0; k < 2; ++k) put(b, mesh.texcoords[static_cast<std::size_t>(i)][k]);
  for (const auto& f : faces)
    for (int k = 0; k < 3; ++k) put(b, static_cast<std::uint32_t>(f[k]));
  return out;
}

}  // namespace rockface::app::office_web

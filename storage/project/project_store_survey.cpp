// ProjectStore: what the geologist measured and what was analysed
// (measurements, joints, analysis runs).
#include "storage/project/project_store.h"

#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/project/project_blobs.h"
#include "storage/project/project_block_row.h"
#include "storage/project/project_store_rows.h"

namespace rockface::storage {

using namespace rows;  // row helpers and the SQLite wrappers

namespace {

// Picked pixels as JSON text ([[u, v], ...]): a few hundred at most per
// measurement, readable with any SQLite tool.
std::string pixels_text(const std::vector<Eigen::Vector2d>& pixels) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& p : pixels) a.push_back({p.x(), p.y()});
  return a.dump();
}

std::vector<Eigen::Vector2d> pixels_of(const std::string& text, const std::string& where) {
  const auto a = nlohmann::json::parse(text, nullptr, false);
  std::vector<Eigen::Vector2d> out;
  bool ok = a.is_array();
  for (std::size_t i = 0; ok && i < a.size(); ++i) {
    ok = a[i].is_array() && a[i].size() == 2 && a[i][0].is_number() && a[i][1].is_number();
    if (ok) out.emplace_back(a[i][0].get<double>(), a[i][1].get<double>());
  }
  if (!ok) throw Error(where + ": stored pixels are damaged");
  return out;
}

}  // namespace

// ---------------------------------------------------------------- measurements

std::vector<RecordId> ProjectStore::save_measurements(
    RecordId visit_id, const std::vector<Measurement>& measurements) {
  const std::string doing = "saving measurements";
  require_writable(doing);
  for (std::size_t i = 0; i < measurements.size(); ++i) {
    const auto& m = measurements[i];
    const std::string where = "measurements[" + std::to_string(i) + "] (" + m.label + ")";
    if (m.points.empty()) throw InputError(where, "has no points");
    for (const auto& p : m.points) require_finite(p, where + ".points");
    if (m.dip_deg.has_value() != m.dipdir_deg.has_value())
      throw InputError(where, "dip and dip direction must be given together");
    if (m.dip_deg) require_orientation(*m.dip_deg, *m.dipdir_deg, where);
    if (m.kind == Measurement::Kind::point_orientation && !m.dip_deg)
      throw InputError(where, "a point orientation needs its dip and dip direction");
    if (!m.rock_side.empty() && m.rock_side != "upper" && m.rock_side != "lower")
      throw InputError(where + ".rock_side", "must be 'upper' or 'lower'");
    if (!m.rock_side.empty() && m.kind != Measurement::Kind::area)
      throw InputError(where + ".rock_side", "only an area (a free face) has a rock side");
    require_finite(m.fit_rms_m, where + ".fit_rms_m");
    for (const auto& px : m.pixels)
      if (!px.allFinite()) throw InputError(where + ".pixels", "a pixel is not a number");
    if (!m.pixels.empty() && m.photo.empty())
      throw InputError(where + ".photo", "pixels need the photo they were picked in");
    if (m.sigma_deg) require_finite(*m.sigma_deg, where + ".sigma_deg");
    if (m.trace_length_m) require_finite(*m.trace_length_m, where + ".trace_length_m");
    if (m.origin != "hand" && m.origin != "proposed" && m.origin != "corrected")
      throw InputError(where + ".origin",
                       "must be 'hand', 'proposed' or 'corrected', not '" + m.origin + "'");
    if (m.origin != "hand" && m.kind != Measurement::Kind::trace)
      throw InputError(where + ".origin", "only a trace is proposed or corrected");
    if (m.compass_dip_deg.has_value() != m.compass_dipdir_deg.has_value())
      throw InputError(where + ".compass", "dip and dip direction must be given together");
    if (m.compass_dip_deg) {
      if (m.kind != Measurement::Kind::trace)
        throw InputError(where + ".compass", "only a trace carries a compass reading");
      require_orientation(*m.compass_dip_deg, *m.compass_dipdir_deg, where + ".compass");
    }
    if (m.compass_off_deg) require_finite(*m.compass_off_deg, where + ".compass_off_deg");
  }
  WriteTransaction tx(db_, doing);
  Statement st(db_,
               "INSERT INTO measurement (visit_id, model_id, kind, label, joint_label, points, "
               "dip, dipdir, fit_rms_m, rock_side, created_at, photo, photo_capture_id, pixels, "
               "sigma_deg, trace_length_m, censored, note, origin, compass_dip, compass_dipdir, "
               "compass_off_deg) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
               "?, ?, ?)",
               doing);
  std::vector<RecordId> ids;
  std::string labels;
  for (const auto& m : measurements) {
    const auto points = blobs::encode_points(m.points);
    st.reset();
    st.bind(1, visit_id)
        .bind(2, m.model_id)
        .bind(3, kind_text(m.kind))
        .bind(4, m.label)
        .bind(5, m.joint_label)
        .bind_blob(6, points)
        .bind(7, m.dip_deg)
        .bind(8, m.dipdir_deg)
        .bind(9, m.fit_rms_m)
        .bind(10, m.rock_side)
        .bind(11, or_now(m.created_at))
        .bind(12, m.photo)
        .bind(13, m.photo_capture_id)
        .bind(14, pixels_text(m.pixels))
        .bind(15, m.sigma_deg)
        .bind(16, m.trace_length_m)
        .bind(17, m.censored)
        .bind(18, m.note)
        .bind(19, m.origin)
        .bind(20, m.compass_dip_deg)
        .bind(21, m.compass_dipdir_deg)
        .bind(22, m.compass_off_deg);
    st.run();
    ids.push_back(db_.last_insert_id());
    labels += (labels.empty() ? "" : " ") + m.label;
  }
  insert_log(visit_id, "measurements saved",
             std::to_string(measurements.size()) + " measurements: " + labels);
  tx.commit();
  return ids;
}

std::vector<Measurement> ProjectStore::list_measurements(std::optional<RecordId> visit_id) {
  // One visit's rows by the index on visit_id: "(?1 IS NULL OR visit_id =
  // ?1)" reads the whole table for every visit (issue 46: a drive's rounds
  // read every visit's rows once per visit, quadratic in the visits).
  Statement st(
      db_,
      std::string("SELECT id, visit_id, model_id, kind, label, joint_label, points, dip, dipdir, "
                  "fit_rms_m, rock_side, created_at, photo, photo_capture_id, pixels, sigma_deg, "
                  "trace_length_m, censored, note, origin, compass_dip, compass_dipdir, "
                  "compass_off_deg FROM measurement WHERE ") +
          (visit_id ? "visit_id = ?1" : "?1 IS NULL") + " ORDER BY id",
      "listing measurements");
  st.bind(1, visit_id);
  std::vector<Measurement> out;
  while (st.step()) {
    RowReader row(st);
    Measurement m;
    m.id = row.next_int64();
    const std::string where = file_.string() + ": measurement " + std::to_string(m.id);
    m.visit_id = row.next_int64();
    m.model_id = row.next_optional_int64();
    m.kind = kind_of(row.next_text(), where);
    m.label = row.next_text();
    m.joint_label = row.next_text();
    m.points = blobs::decode_points(row.next_blob(), where);
    m.dip_deg = row.next_optional_double();
    m.dipdir_deg = row.next_optional_double();
    m.fit_rms_m = row.next_double();
    m.rock_side = row.next_text();
    m.created_at = row.next_text();
    m.photo = row.next_text();
    m.photo_capture_id = row.next_optional_int64();
    m.pixels = pixels_of(row.next_text(), where);
    m.sigma_deg = row.next_optional_double();
    m.trace_length_m = row.next_optional_double();
    m.censored = row.next_bool();
    m.note = row.next_text();
    m.origin = row.next_text();
    m.compass_dip_deg = row.next_optional_double();
    m.compass_dipdir_deg = row.next_optional_double();
    m.compass_off_deg = row.next_optional_double();
    out.push_back(std::move(m));
  }
  return out;
}

// ---------------------------------------------------------------- joints

std::vector<RecordId> ProjectStore::save_joints(RecordId visit_id,
                                                const std::vector<JointSet>& sets,
                                                const std::vector<Joint>& joints) {
  const std::string doing = "saving joints";
  require_writable(doing);
  std::set<std::string> set_labels, joint_labels;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const std::string where = "joint_sets[" + std::to_string(i) + "] (" + sets[i].label + ")";
    if (sets[i].label.empty()) throw InputError(where, "has no label");
    if (!set_labels.insert(sets[i].label).second) throw InputError(where, "label is repeated");
    require_orientation(sets[i].dip_deg, sets[i].dipdir_deg, where);
    require_finite(sets[i].fisher_k, where + ".fisher_k");
    for (const auto& [value, field] : {std::pair{sets[i].alpha95_deg, ".alpha95"},
                                       {sets[i].spacing_m, ".spacing"},
                                       {sets[i].mean_trace_length_m, ".mean_trace_length"},
                                       {sets[i].persistence_m, ".persistence"}})
      if (value) require_finite(*value, where + field);
  }
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const auto& j = joints[i];
    const std::string where = "joints[" + std::to_string(i) + "] (" + j.label + ")";
    if (j.label.empty()) throw InputError(where, "has no label");
    if (!joint_labels.insert(j.label).second) throw InputError(where, "label is repeated");
    require_orientation(j.dip_deg, j.dipdir_deg, where);
    if (j.point) require_finite(*j.point, where + ".point");
    if (j.friction_deg) require_finite(*j.friction_deg, where + ".friction");
    if (j.cohesion_pa) require_finite(*j.cohesion_pa, where + ".cohesion");
    if (j.persistence_m) require_finite(*j.persistence_m, where + ".persistence");
  }

  WriteTransaction tx(db_, doing);
  std::map<std::string, RecordId> set_ids;
  Statement set_st(db_,
                   "INSERT INTO joint_set (visit_id, label, dip, dipdir, fisher_k, count, "
                   "alpha95_deg, spacing_m, mean_trace_length_m, censored_traces, persistence_m, "
                   "note) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                   doing);
  for (const auto& s : sets) {
    set_st.reset();
    set_st.bind(1, visit_id)
        .bind(2, s.label)
        .bind(3, s.dip_deg)
        .bind(4, s.dipdir_deg)
        .bind(5, s.fisher_k)
        .bind(6, s.count)
        .bind(7, s.alpha95_deg)
        .bind(8, s.spacing_m)
        .bind(9, s.mean_trace_length_m)
        .bind(10, s.censored_traces)
        .bind(11, s.persistence_m)
        .bind(12, s.note);
    set_st.run();
    set_ids[s.label] = db_.last_insert_id();
  }
  Statement find_set(db_, "SELECT id FROM joint_set WHERE visit_id = ? AND label = ?", doing);
  Statement find_joint(db_, "SELECT 1 FROM joint WHERE visit_id = ? AND label = ?", doing);
  Statement st(db_,
               "INSERT INTO joint (visit_id, set_id, measurement_id, label, dip, dipdir, px, py, "
               "pz, friction_deg, cohesion_pa, source, type, persistence_m) VALUES (?, ?, ?, ?, "
               "?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
               doing);
  std::vector<RecordId> ids;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const auto& j = joints[i];
    const std::string where = "joints[" + std::to_string(i) + "] (" + j.label + ")";
    find_joint.reset();
    find_joint.bind(1, visit_id).bind(2, j.label);
    if (find_joint.step())
      throw InputError(where, "visit " + std::to_string(visit_id) + " already has a joint " +
                                  j.label + "; nothing was saved");
    std::optional<RecordId> set_id;
    if (!j.set_label.empty()) {
      if (auto it = set_ids.find(j.set_label); it != set_ids.end()) {
        set_id = it->second;
      } else {
        find_set.reset();
        find_set.bind(1, visit_id).bind(2, j.set_label);
        if (!find_set.step())
          throw InputError(where + ".set", "no joint set '" + j.set_label + "' in visit " +
                                               std::to_string(visit_id) + "; nothing was saved");
        set_id = find_set.column_int(0);
      }
    }
    st.reset();
    st.bind(1, visit_id).bind(2, set_id).bind(3, j.measurement_id).bind(4, j.label);
    st.bind(5, j.dip_deg).bind(6, j.dipdir_deg);
    if (j.point) {
      st.bind(7, j.point->x()).bind(8, j.point->y()).bind(9, j.point->z());
    } else {
      st.bind_null(7).bind_null(8).bind_null(9);
    }
    st.bind(10, j.friction_deg).bind(11, j.cohesion_pa).bind(12, j.source);
    st.bind(13, j.type).bind(14, j.persistence_m);
    st.run();
    ids.push_back(db_.last_insert_id());
  }
  insert_log(visit_id, "joints saved",
             std::to_string(joints.size()) + " joints, " + std::to_string(sets.size()) + " sets");
  tx.commit();
  return ids;
}

std::vector<JointSet> ProjectStore::list_joint_sets(RecordId visit_id) {
  Statement st(db_,
               "SELECT id, label, dip, dipdir, fisher_k, count, alpha95_deg, spacing_m, "
               "mean_trace_length_m, censored_traces, persistence_m, note FROM joint_set WHERE "
               "visit_id = ? ORDER BY id",
               "listing joint sets");
  st.bind(1, visit_id);
  std::vector<JointSet> out;
  while (st.step()) {
    RowReader row(st);
    JointSet s;
    s.id = row.next_int64();
    s.label = row.next_text();
    s.dip_deg = row.next_double();
    s.dipdir_deg = row.next_double();
    s.fisher_k = row.next_double();
    s.count = row.next_int();
    s.alpha95_deg = row.next_optional_double();
    s.spacing_m = row.next_optional_double();
    s.mean_trace_length_m = row.next_optional_double();
    s.censored_traces = row.next_int();
    s.persistence_m = row.next_optional_double();
    s.note = row.next_text();
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<Joint> ProjectStore::list_joints(std::optional<RecordId> visit_id) {
  Statement st(db_,
               "SELECT j.id, j.visit_id, j.label, s.label, j.dip, j.dipdir, j.px, j.py, j.pz, "
               "j.friction_deg, j.cohesion_pa, j.measurement_id, j.source, j.type, "
               "j.persistence_m FROM joint j LEFT "
               "JOIN joint_set s ON s.id = j.set_id WHERE " +
                   std::string(visit_id ? "j.visit_id = ?1" : "?1 IS NULL") + " ORDER BY j.id",
               "listing joints");
  st.bind(1, visit_id);
  std::vector<Joint> out;
  while (st.step()) {
    RowReader row(st);
    Joint j;
    j.id = row.next_int64();
    j.visit_id = row.next_int64();
    j.label = row.next_text();
    j.set_label = row.next_text();
    j.dip_deg = row.next_double();
    j.dipdir_deg = row.next_double();
    j.point = next_optional_vector3(row);
    j.friction_deg = row.next_optional_double();
    j.cohesion_pa = row.next_optional_double();
    j.measurement_id = row.next_optional_int64();
    j.source = row.next_text();
    j.type = row.next_text();
    j.persistence_m = row.next_optional_double();
    out.push_back(std::move(j));
  }
  return out;
}

// ---------------------------------------------------------------- analyses

RecordId ProjectStore::save_analysis(const AnalysisRun& run) {
  const std::string doing = "saving a block analysis";
  require_writable(doing);
  std::vector<BlockRow> rows;
  for (const auto& b : run.blocks) rows.push_back(block_row(b));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& b = rows[i];
    const std::string where = "blocks[" + std::to_string(i) + "] (" + b.label + ")";
    require_finite(b.volume_m3, where + ".volume");
    if (b.fos && std::isnan(*b.fos)) throw InputError(where + ".fos", "is not a number");
  }
  WriteTransaction tx(db_, doing);
  Statement st(db_,
               "INSERT INTO analysis (visit_id, model_id, created_at, preset, effects, "
               "effects_json) VALUES (?, ?, ?, ?, ?, ?)",
               doing);
  st.bind(1, run.visit_id)
      .bind(2, run.model_id)
      .bind(3, or_now(run.created_at))
      .bind(4, run.preset)
      .bind(5, nlohmann::json(run.effects).dump())
      .bind(6, run.effects_json);
  st.run();
  const RecordId id = db_.last_insert_id();
  Statement block(db_,
                  "INSERT INTO block (analysis_id, label, source, code, volume_m3, finite, "
                  "removable, marginal, mode, fos, report_json) VALUES (?, ?, ?, ?, ?, ?, ?, ?, "
                  "?, ?, ?)",
                  doing);
  int removable = 0;
  for (const auto& b : rows) {
    block.reset();
    block.bind(1, id)
        .bind(2, b.label)
        .bind(3, b.source)
        .bind(4, b.code)
        .bind(5, b.volume_m3)
        .bind(6, b.finite)
        .bind(7, b.removable)
        .bind(8, b.marginal)
        .bind(9, b.mode)
        .bind(10, b.fos)
        .bind(11, b.report_json);
    block.run();
    removable += b.removable ? 1 : 0;
  }
  insert_log(run.visit_id, "blocks analysed",
             "analysis " + std::to_string(id) + " (" + run.preset +
                 "): " + std::to_string(run.blocks.size()) + " blocks, " +
                 std::to_string(removable) + " removable");
  tx.commit();
  return id;
}

namespace {
AnalysisRun read_analysis_row(const Statement& st, const std::string& file) {
  RowReader row(st);
  AnalysisRun a;
  a.id = row.next_int64();
  a.visit_id = row.next_int64();
  a.model_id = row.next_optional_int64();
  a.created_at = row.next_text();
  a.preset = row.next_text();
  const std::string effects = row.next_text();
  auto parsed = nlohmann::json::parse(effects, nullptr, false);
  if (parsed.is_discarded() || !parsed.is_array())
    throw Error(file + ": analysis " + std::to_string(a.id) + ": stored effects are damaged");
  for (const auto& e : parsed) a.effects.push_back(e.is_string() ? e.get<std::string>() : e.dump());
  a.effects_json = row.next_text();
  return a;
}
constexpr const char* kAnalysisColumns =
    "id, visit_id, model_id, created_at, preset, effects, effects_json";
}  // namespace

AnalysisRun ProjectStore::load_analysis(RecordId id) {
  const std::string doing = "loading analysis " + std::to_string(id);
  ReadTransaction snapshot(db_);
  Statement st(db_, std::string("SELECT ") + kAnalysisColumns + " FROM analysis WHERE id = ?",
               doing);
  st.bind(1, id);
  if (!st.step())
    throw InputError(file_.string(), "no analysis " + std::to_string(id) + " in this project");
  AnalysisRun a = read_analysis_row(st, file_.string());
  Statement blocks(db_,
                   "SELECT label, source, code, volume_m3, finite, removable, marginal, mode, "
                   "fos, report_json FROM block WHERE analysis_id = ? ORDER BY id",
                   doing);
  blocks.bind(1, id);
  while (blocks.step()) {
    RowReader row(blocks);
    BlockRow b;
    b.label = row.next_text();
    b.source = row.next_text();
    b.code = row.next_text();
    b.volume_m3 = row.next_double();
    b.finite = row.next_bool();
    b.removable = row.next_bool();
    b.marginal = row.next_bool();
    b.mode = row.next_text();
    b.fos = row.next_optional_double();
    b.report_json = row.next_text();
    a.blocks.push_back(block_of_row(b));
  }
  return a;
}

std::vector<AnalysisRun> ProjectStore::list_analyses(std::optional<RecordId> visit_id) {
  Statement st(db_,
               std::string("SELECT ") + kAnalysisColumns + " FROM analysis WHERE " +
                   (visit_id ? "visit_id = ?1" : "?1 IS NULL") + " ORDER BY id",
               "listing analyses");
  st.bind(1, visit_id);
  std::vector<AnalysisRun> out;
  while (st.step()) out.push_back(read_analysis_row(st, file_.string()));
  return out;
}

}  // namespace rockface::storage

// Reader of one block of the analysis report (SCENE.md, rockface-report/1,
// a "blocks" entry), the inverse of report_json.cpp's writer: what the
// project store keeps per block, read back as the one verdict type.
//
// It reads what this program wrote and what older versions of it stored: a
// field that is absent, null or of another type is left at the verdict's
// default (an absent optional), and a part that is not what the writer makes
// (a rotation, a dynamics) is left out whole. It never throws: a damaged row
// still opens, with what it holds.
#include <limits>

#include <nlohmann/json.hpp>

#include "storage/report/report.h"
#include "storage/report/report_dynamics_json.h"

namespace rockface::storage {

namespace {

using nlohmann::json;

const json* field(const json& obj, const char* key) {
  if (!obj.is_object()) return nullptr;
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

// A number the writer wrote: null is an unknown (the writer's NaN or
// infinity), kept as NaN.
std::optional<double> stored_number(const json& obj, const char* key) {
  const json* v = field(obj, key);
  if (!v) return std::nullopt;
  if (v->is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!v->is_number()) return std::nullopt;
  return v->get<double>();
}

// An optional number the writer writes as null when it has none
// (number_or_null): null reads as none.
std::optional<double> number_or_none(const json& obj, const char* key) {
  const json* v = field(obj, key);
  if (!v || !v->is_number()) return std::nullopt;
  return v->get<double>();
}

void read_number(const json& obj, const char* key, double& out) {
  if (const auto v = stored_number(obj, key)) out = *v;
}

void read_bool(const json& obj, const char* key, bool& out) {
  if (const json* v = field(obj, key); v && v->is_boolean()) out = v->get<bool>();
}

void read_int(const json& obj, const char* key, int& out) {
  if (const json* v = field(obj, key); v && v->is_number_integer()) out = v->get<int>();
}

void read_string(const json& obj, const char* key, std::string& out) {
  if (const json* v = field(obj, key); v && v->is_string()) out = v->get<std::string>();
}

std::vector<std::string> texts(const json& obj, const char* key) {
  std::vector<std::string> out;
  if (const json* v = field(obj, key); v && v->is_array())
    for (const auto& s : *v)
      if (s.is_string()) out.push_back(s.get<std::string>());
  return out;
}

std::vector<double> numbers(const json& obj, const char* key) {
  std::vector<double> out;
  if (const json* v = field(obj, key); v && v->is_array())
    for (const auto& x : *v)
      out.push_back(x.is_number() ? x.get<double>() : std::numeric_limits<double>::quiet_NaN());
  return out;
}

std::optional<Eigen::Vector3d> vector3(const json& v) {
  if (!v.is_array() || v.size() != 3) return std::nullopt;
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) {
    if (v[i].is_null())
      out(i) = std::numeric_limits<double>::quiet_NaN();
    else if (v[i].is_number())
      out(i) = v[i].get<double>();
    else
      return std::nullopt;
  }
  return out;
}

std::optional<Eigen::Vector3d> vector3(const json& obj, const char* key) {
  const json* v = field(obj, key);
  return v ? vector3(*v) : std::nullopt;
}

std::vector<Eigen::Vector3d> vectors(const json& obj, const char* key) {
  std::vector<Eigen::Vector3d> out;
  if (const json* v = field(obj, key); v && v->is_array())
    for (const auto& p : *v)
      if (const auto x = vector3(p)) out.push_back(*x);  // a malformed point is left out
  return out;
}

// The faces' loops, only when every loop indexes the vertices read (a
// vertex left out above shifts the indices): a block's mesh with a face
// missing or wrong is worse than none, so any doubt leaves all faces out.
std::vector<std::vector<int>> face_loops(const json& obj, std::size_t vertex_count) {
  const json* f = field(obj, "faces");
  const json* v = field(obj, "vertices");
  if (!f || !f->is_array() || !v || !v->is_array() || v->size() != vertex_count) return {};
  std::vector<std::vector<int>> loops;
  for (const auto& loop : *f) {
    if (!loop.is_array() || loop.size() < 3) return {};
    std::vector<int> indices;
    for (const auto& i : loop) {
      if (!i.is_number_integer()) return {};
      const auto index = i.get<long long>();
      if (index < 0 || index >= static_cast<long long>(vertex_count)) return {};
      indices.push_back(static_cast<int>(index));
    }
    loops.push_back(std::move(indices));
  }
  return loops;
}

std::optional<analysis::ReportMode> mode_of(const json& m) {
  if (!m.is_object()) return std::nullopt;
  analysis::ReportMode mode;
  read_string(m, "type", mode.type);
  mode.planes = texts(m, "planes");
  mode.direction = vector3(m, "direction");
  read_bool(m, "marginal", mode.marginal);
  return mode;
}

std::optional<Eigen::Matrix3d> inertia_of(const json& obj) {
  const json* rows = field(obj, "inertia");
  if (!rows || !rows->is_array() || rows->size() != 3) return std::nullopt;
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r) {
    const auto row = vector3((*rows)[r]);
    if (!row) return std::nullopt;
    m.row(r) = row->transpose();
  }
  return m;
}

std::optional<analysis::ReportRotation> rotation_of(const json& rot) {
  if (!rot.is_object()) return std::nullopt;
  analysis::ReportRotation r;
  if (const json* cs = field(rot, "corners"); cs && cs->is_array())
    for (const auto& c : *cs) {
      analysis::ReportCorner corner;
      read_int(c, "vertex", corner.vertex);
      read_bool(c, "rotatable", corner.rotatable);
      read_number(c, "margin_deg", corner.margin_deg);
      read_bool(c, "marginal", corner.marginal);
      corner.rotation_edges = vectors(c, "rotation_edges");
      corner.sliding_on = texts(c, "sliding_on");
      r.corners.push_back(corner);
    }
  if (const json* es = field(rot, "edges"); es && es->is_array())
    for (const auto& e : *es) {
      analysis::ReportEdge edge;
      if (const json* v = field(e, "vertices"); v && v->is_array() && v->size() == 2 &&
                                                (*v)[0].is_number_integer() &&
                                                (*v)[1].is_number_integer())
        edge.vertices = {(*v)[0].get<int>(), (*v)[1].get<int>()};
      read_bool(e, "rotatable", edge.rotatable);
      read_number(e, "margin_deg", edge.margin_deg);
      read_bool(e, "marginal", edge.marginal);
      r.edges.push_back(edge);
    }
  return r;
}

std::optional<analysis::ReportRemoteAxis> remote_axis_of(const json& ra) {
  if (!ra.is_object()) return std::nullopt;
  analysis::ReportRemoteAxis a;
  read_bool(ra, "found", a.found);
  if (const auto p = vector3(ra, "point")) a.point = *p;
  if (const auto d = vector3(ra, "direction")) a.direction = *d;
  read_int(ra, "starts", a.starts);
  read_int(ra, "hits", a.hits);
  read_number(ra, "penalty", a.penalty);
  return a;
}

std::optional<analysis::ReportStability> stability_of(const json& st) {
  if (!st.is_object()) return std::nullopt;
  analysis::ReportStability s;
  s.fos = number_or_none(st, "fos");
  s.static_mode = numbers(st, "static_mode");
  s.dynamic_mode = numbers(st, "dynamic_mode");
  if (const json* path = field(st, "path"); path && path->is_array())
    for (const auto& p : *path) {
      analysis::ReportStabilityStep step;
      read_number(p, "lambda", step.lambda);
      step.displacement = numbers(p, "displacement");
      s.path.push_back(step);
    }
  return s;
}

analysis::ReportRigidMode rigid_mode_of(const json& m) {
  analysis::ReportRigidMode r;
  if (const auto t = vector3(m, "translation")) r.translation = *t;
  if (const auto w = vector3(m, "rotation")) r.rotation = *w;
  read_string(m, "kind", r.kind);
  return r;
}

std::optional<analysis::ReportMechanics> mechanics_of(const json& mj) {
  if (!mj.is_object()) return std::nullopt;
  analysis::ReportMechanics m;
  m.fos_limit_point = number_or_none(mj, "fos_limit_point");
  read_string(mj, "outcome", m.outcome);
  if (const json* f = field(mj, "failure_mode")) m.failure_mode = rigid_mode_of(*f);
  if (const json* d = field(mj, "dynamic_mode")) m.dynamic_mode = rigid_mode_of(*d);
  read_string(mj, "stability", m.stability);
  m.flutter_lambda = stored_number(mj, "flutter_lambda");
  if (const json* path = field(mj, "path"); path && path->is_array())
    for (const auto& p : *path)
      if (p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number())
        m.path.push_back({p[0].get<double>(), p[1].get<double>()});
  read_int(mj, "contacts", m.contacts);
  read_int(mj, "steps", m.steps);
  read_string(mj, "joint_law", m.joint_law);
  if (const json* plot = field(mj, "plot"); plot && plot->is_string())
    m.plot = plot->get<std::string>();
  return m;
}

}  // namespace

analysis::ReportBlock block_from_json(const std::string& text) {
  analysis::ReportBlock b;
  const json j = json::parse(text, nullptr, false);
  if (!j.is_object()) return b;
  read_string(j, "id", b.id);
  read_string(j, "source", b.source);
  b.traces = texts(j, "traces");
  read_string(j, "code", b.code);
  read_bool(j, "convex", b.convex);
  b.vertices = vectors(j, "vertices");
  b.faces = face_loops(j, b.vertices.size());
  b.volume = stored_number(j, "volume");
  b.mass = stored_number(j, "mass");
  b.centroid = vector3(j, "centroid");
  b.inertia = inertia_of(j);
  b.principal_moments = vector3(j, "principal_moments");
  if (const json* areas = field(j, "face_areas"); areas && areas->is_object())
    for (const auto& [face, area] : areas->items())
      if (area.is_number()) b.face_areas[face] = area.get<double>();
  read_bool(j, "finite", b.finite);
  read_bool(j, "removable", b.removable);
  read_number(j, "margin_deg", b.margin_deg);
  read_bool(j, "marginal", b.marginal);
  if (const json* m = field(j, "mode")) b.mode = mode_of(*m);
  b.fos = number_or_none(j, "fos");
  read_bool(j, "fos_marginal", b.fos_marginal);
  if (const json* r = field(j, "resultant")) {
    const auto force = vector3(*r, "force"), moment = vector3(*r, "moment");
    if (force && moment) {
      b.resultant_force = force;
      b.resultant_moment = moment;
    }
  }
  if (const json* r = field(j, "rotation")) b.rotation = rotation_of(*r);
  if (const json* r = field(j, "remote_axis")) b.remote_axis = remote_axis_of(*r);
  if (const json* s = field(j, "stability")) b.stability = stability_of(*s);
  if (const json* m = field(j, "mechanics")) b.mechanics = mechanics_of(*m);
  if (const json* d = field(j, "dynamics")) b.dynamics = dynamics_from_json(*d);
  b.notes = texts(j, "notes");
  return b;
}

}  // namespace rockface::storage

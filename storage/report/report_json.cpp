// Writer of the analysis report (SCENE.md, rockface-report/1).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "storage/report/report.h"
#include "storage/report/report_dynamics_json.h"
#include "storage/report/report_numbers.h"
#include "storage/report/rockmass_report_json.h"

namespace rockface::storage {

namespace {

using nlohmann::json;
using ordered = nlohmann::ordered_json;

double tidy(double v) {
  return tidy_relative(v);
}

ordered vec(const Eigen::Vector3d& v) {
  return ordered::array({tidy(v.x()), tidy(v.y()), tidy(v.z())});
}

// An absolute point (m): to 1e-5 m at survey coordinates (report_numbers.h).
ordered survey_point(const Eigen::Vector3d& v) {
  return ordered::array({tidy_coordinate(v.x()), tidy_coordinate(v.y()), tidy_coordinate(v.z())});
}

ordered number_or_null(std::optional<double> v) {
  if (!v || !std::isfinite(*v)) return nullptr;  // JSON has no infinity: "no finite value"
  return tidy(*v);
}

ordered rigid_mode_json(const analysis::ReportRigidMode& m) {
  ordered j;
  j["translation"] = vec(m.translation);
  j["rotation"] = vec(m.rotation);
  j["kind"] = m.kind;
  return j;
}

ordered mechanics_json(const analysis::ReportMechanics& m) {
  ordered j;
  j["fos_limit_point"] = number_or_null(m.fos_limit_point);
  j["outcome"] = m.outcome;
  j["failure_mode"] = rigid_mode_json(m.failure_mode);
  j["dynamic_mode"] = rigid_mode_json(m.dynamic_mode);
  j["stability"] = m.stability;
  if (m.flutter_lambda) j["flutter_lambda"] = tidy(*m.flutter_lambda);
  ordered path = ordered::array();
  for (const auto& p : m.path) path.push_back(ordered::array({tidy(p[0]), tidy(p[1])}));
  j["path"] = path;
  j["contacts"] = m.contacts;
  j["steps"] = m.steps;
  j["joint_law"] = m.joint_law;
  if (m.plot) j["plot"] = *m.plot;
  return j;
}

ordered mode_json(const analysis::ReportMode& m) {
  ordered j;
  j["type"] = m.type;
  j["planes"] = m.planes;
  if (m.direction) j["direction"] = vec(*m.direction);
  if (m.marginal) j["marginal"] = true;
  return j;
}

ordered pyramid_json(const analysis::ReportPyramid& p) {
  ordered j;
  j["face"] = p.face;
  j["code"] = p.code;
  j["empty"] = p.empty;
  j["finite"] = p.finite;
  j["removable"] = p.removable;
  j["margin_deg"] = tidy(p.margin_deg);
  j["marginal"] = p.marginal;
  j["jp_margin_deg"] = tidy(p.jp_margin_deg);
  j["jp_ep_margin_deg"] = tidy(p.jp_ep_margin_deg);
  if (p.mode) j["mode"] = mode_json(*p.mode);
  if (p.mode) j["fos"] = number_or_null(p.fos);
  return j;
}

ordered block_json(const analysis::ReportBlock& b) {
  ordered j;
  j["id"] = b.id;
  j["source"] = b.source;
  if (!b.traces.empty()) j["traces"] = b.traces;
  j["code"] = b.code;
  j["convex"] = b.convex;
  ordered verts = ordered::array();
  for (const auto& v : b.vertices) verts.push_back(survey_point(v));
  j["vertices"] = verts;
  if (!b.faces.empty()) j["faces"] = b.faces;
  if (b.volume) j["volume"] = tidy(*b.volume);
  if (b.mass) j["mass"] = tidy(*b.mass);
  if (b.centroid) j["centroid"] = survey_point(*b.centroid);
  if (b.inertia) {
    ordered rows = ordered::array();
    for (int r = 0; r < 3; ++r) rows.push_back(vec(b.inertia->row(r).transpose()));
    j["inertia"] = rows;
  }
  if (b.principal_moments) j["principal_moments"] = vec(*b.principal_moments);
  if (!b.face_areas.empty()) {
    ordered areas = ordered::object();
    for (const auto& [id, a] : b.face_areas) areas[id] = tidy(a);
    j["face_areas"] = areas;
  }
  j["finite"] = b.finite;
  j["removable"] = b.removable;
  j["margin_deg"] = tidy(b.margin_deg);
  j["marginal"] = b.marginal;
  if (b.mode) j["mode"] = mode_json(*b.mode);
  if (b.mode) j["fos"] = number_or_null(b.fos);
  if (b.fos_marginal) j["fos_marginal"] = true;
  if (b.resultant_force && b.resultant_moment) {
    ordered r;
    r["force"] = vec(*b.resultant_force);
    r["moment"] = vec(*b.resultant_moment);
    j["resultant"] = r;
  }
  if (b.rotation) {
    ordered rot;
    ordered corners = ordered::array();
    for (const auto& c : b.rotation->corners) {
      ordered cj;
      cj["vertex"] = c.vertex;
      cj["rotatable"] = c.rotatable;
      cj["margin_deg"] = tidy(c.margin_deg);
      cj["marginal"] = c.marginal;
      ordered edges = ordered::array();
      for (const auto& e : c.rotation_edges) edges.push_back(vec(e));
      cj["rotation_edges"] = edges;
      if (!c.sliding_on.empty()) cj["sliding_on"] = c.sliding_on;
      corners.push_back(cj);
    }
    ordered edges = ordered::array();
    for (const auto& e : b.rotation->edges) {
      ordered ej;
      ej["vertices"] = {e.vertices[0], e.vertices[1]};
      ej["rotatable"] = e.rotatable;
      ej["margin_deg"] = tidy(e.margin_deg);
      ej["marginal"] = e.marginal;
      edges.push_back(ej);
    }
    rot["corners"] = corners;
    rot["edges"] = edges;
    j["rotation"] = rot;
  }
  if (b.remote_axis) {
    ordered ra;
    ra["found"] = b.remote_axis->found;
    ra["point"] = survey_point(b.remote_axis->point);
    ra["direction"] = vec(b.remote_axis->direction);
    ra["starts"] = b.remote_axis->starts;
    ra["hits"] = b.remote_axis->hits;
    ra["penalty"] = tidy(b.remote_axis->penalty);
    j["remote_axis"] = ra;
  }
  if (b.stability) {
    ordered st;
    st["fos"] = number_or_null(b.stability->fos);
    st["static_mode"] = b.stability->static_mode;
    st["dynamic_mode"] = b.stability->dynamic_mode;
    ordered path = ordered::array();
    for (const auto& s : b.stability->path)
      path.push_back({{"lambda", tidy(s.lambda)}, {"displacement", s.displacement}});
    st["path"] = path;
    j["stability"] = st;
  }
  if (b.mechanics) j["mechanics"] = mechanics_json(*b.mechanics);
  if (b.dynamics) j["dynamics"] = dynamics_to_json(*b.dynamics);
  if (!b.notes.empty()) j["notes"] = b.notes;
  return j;
}

}  // namespace

std::string block_to_json(const analysis::ReportBlock& block) {
  return block_json(block).dump();
}

std::string report_to_json(const analysis::Report& r) {
  ordered j;
  j["format"] = "rockface-report/1";
  j["effects_simulated"] = r.effects_simulated;
  j["analyses"] = r.analyses;
  ordered pyramids = ordered::array();
  for (const auto& p : r.pyramids) pyramids.push_back(pyramid_json(p));
  j["pyramids"] = pyramids;
  ordered blocks = ordered::array();
  for (const auto& b : r.blocks) blocks.push_back(block_json(b));
  j["blocks"] = blocks;
  if (!r.notes.empty()) j["notes"] = r.notes;
  if (r.rockmass) j["rockmass"] = ordered::parse(rockmass_report_json(*r.rockmass).dump());
  ordered timings = ordered::object();
  for (const auto& [k, v] : r.timings_ms) timings[k] = tidy(v);
  j["timings_ms"] = timings;
  return j.dump(2) + "\n";
}

}  // namespace rockface::storage

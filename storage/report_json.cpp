// Writer of the analysis report (SCENE.md, rockface-report/1) and of its
// readable summary table.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "storage/report.h"
#include "storage/report_dynamics_json.h"

namespace rockface::storage {

namespace {

using nlohmann::json;
using ordered = nlohmann::ordered_json;

// Rounds for the report: 1e-9 relative keeps every digit a field measurement
// could justify and drops binary noise from the printed numbers.
double tidy(double v) {
  if (!std::isfinite(v) || v == 0) return v;
  const double scale = std::pow(10.0, 9 - std::ceil(std::log10(std::abs(v))));
  return std::round(v * scale) / scale;
}

ordered vec(const Eigen::Vector3d& v) {
  return ordered::array({tidy(v.x()), tidy(v.y()), tidy(v.z())});
}

ordered number_or_null(std::optional<double> v) {
  if (!v || !std::isfinite(*v)) return nullptr;  // JSON has no infinity: "no finite value"
  return tidy(*v);
}

ordered rigid_mode_json(const ReportRigidMode& m) {
  ordered j;
  j["translation"] = vec(m.translation);
  j["rotation"] = vec(m.rotation);
  j["kind"] = m.kind;
  return j;
}

ordered mechanics_json(const ReportMechanics& m) {
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

ordered mode_json(const ReportMode& m) {
  ordered j;
  j["type"] = m.type;
  j["planes"] = m.planes;
  if (m.direction) j["direction"] = vec(*m.direction);
  if (m.marginal) j["marginal"] = true;
  return j;
}

ordered pyramid_json(const ReportPyramid& p) {
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

ordered block_json(const ReportBlock& b) {
  ordered j;
  j["id"] = b.id;
  j["source"] = b.source;
  if (!b.traces.empty()) j["traces"] = b.traces;
  j["code"] = b.code;
  j["convex"] = b.convex;
  ordered verts = ordered::array();
  for (const auto& v : b.vertices) verts.push_back(vec(v));
  j["vertices"] = verts;
  if (b.volume) j["volume"] = tidy(*b.volume);
  if (b.mass) j["mass"] = tidy(*b.mass);
  if (b.centroid) j["centroid"] = vec(*b.centroid);
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
    ra["point"] = vec(b.remote_axis->point);
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

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string fos_text(const std::optional<ReportMode>& mode, std::optional<double> fos) {
  if (!mode) return "-";
  if (mode->type == "none") return "stable";
  if (!fos) return "-";
  if (!std::isfinite(*fos)) return "inf";
  return fixed(*fos, 2);
}

std::string mode_text(const std::optional<ReportMode>& mode) {
  if (!mode) return "-";
  std::string t = mode->type;
  if (!mode->planes.empty()) {
    t += " on ";
    for (size_t i = 0; i < mode->planes.size(); ++i) t += (i ? "+" : "") + mode->planes[i];
  }
  return t;
}

std::string pad(const std::string& s, size_t w) {
  return s.size() >= w ? s + " " : s + std::string(w - s.size(), ' ');
}

}  // namespace

std::string block_to_json(const ReportBlock& block) {
  return block_json(block).dump();
}

std::string report_to_json(const Report& r) {
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
  if (!r.rockmass_json.empty()) j["rockmass"] = ordered::parse(r.rockmass_json);
  ordered timings = ordered::object();
  for (const auto& [k, v] : r.timings_ms) timings[k] = tidy(v);
  j["timings_ms"] = timings;
  return j.dump(2) + "\n";
}

std::string report_summary(const Report& r) {
  std::ostringstream out;
  out << "effects simulated: ";
  for (size_t i = 0; i < r.effects_simulated.size(); ++i)
    out << (i ? ", " : "") << r.effects_simulated[i];
  out << "\n";
  if (!r.pyramids.empty()) {
    size_t removable = 0;
    for (const auto& p : r.pyramids) removable += p.removable;
    out << "\njoint pyramids: " << r.pyramids.size() << " (code x face), " << removable
        << " removable\n";
    out << pad("face", 10) << pad("code", 8) << pad("verdict", 16) << pad("margin", 10)
        << pad("mode", 22) << "FoS\n";
    for (const auto& p : r.pyramids) {
      if (!p.removable && !p.marginal) continue;  // the table lists what can move or might
      const std::string verdict =
          std::string(p.removable ? "removable" : (p.empty ? "empty" : "not removable")) +
          (p.marginal ? "?" : "");
      out << pad(p.face, 10) << pad(p.code, 8) << pad(verdict, 16)
          << pad(fixed(p.margin_deg, 2) + " deg", 10) << pad(mode_text(p.mode), 22)
          << fos_text(p.mode, p.fos) << "\n";
    }
    out << "(not listed: pyramids that are firmly not removable; '?' = marginal)\n";
  }
  if (!r.blocks.empty()) {
    // A non-convex trace block has one code per convex piece ("a+b+c" in
    // the report); the table shows the first and how many more.
    bool pieces = false;
    auto code_text = [&](const std::string& code) {
      const size_t n = static_cast<size_t>(std::count(code.begin(), code.end(), '+'));
      if (n == 0) return code;
      pieces = true;
      return code.substr(0, code.find('+')) + " +" + std::to_string(n);
    };
    size_t code_width = 8;
    for (const auto& b : r.blocks) code_width = std::max(code_width, code_text(b.code).size() + 2);
    out << "\nblocks: " << r.blocks.size() << "\n";
    out << pad("block", 10) << pad("source", 8) << pad("code", code_width) << pad("volume m3", 11)
        << pad("verdict", 16) << pad("margin", 10) << pad("mode", 22) << pad("FoS", 8)
        << "rotation\n";
    for (const auto& b : r.blocks) {
      const std::string verdict =
          std::string(!b.finite ? "infinite" : (b.removable ? "removable" : "finite, keyed")) +
          (b.marginal ? "?" : "");
      std::string rotation = "-";
      if (b.rotation) {
        int corners = 0, edges = 0;
        for (const auto& c : b.rotation->corners) corners += c.rotatable;
        for (const auto& e : b.rotation->edges) edges += e.rotatable;
        rotation = std::to_string(corners) + " corner, " + std::to_string(edges) + " edge";
      }
      if (b.remote_axis) rotation += b.remote_axis->found ? "; remote axis" : "; no remote axis";
      out << pad(b.id, 10) << pad(b.source, 8) << pad(code_text(b.code), code_width)
          << pad(b.volume ? fixed(*b.volume, 3) : "-", 11) << pad(verdict, 16)
          << pad(fixed(b.margin_deg, 2) + " deg", 10) << pad(mode_text(b.mode), 22)
          << pad(fos_text(b.mode, b.fos), 8) << rotation << "\n";
    }
    if (pieces)
      out << "(code +N: a non-convex block, the code of its first convex piece and N more; all "
             "in the report)\n";
  }
  // The equilibrium path, only where the scene asked for it.
  bool mechanics = false;
  for (const auto& b : r.blocks) mechanics = mechanics || b.mechanics.has_value();
  if (mechanics) {
    out << "\nequilibrium path (strength reduction to the first limit point):\n";
    out << pad("block", 10) << pad("FoS", 8) << pad("failure mode", 14) << pad("stability", 12)
        << "outcome\n";
    for (const auto& b : r.blocks) {
      if (!b.mechanics) continue;
      const ReportMechanics& m = *b.mechanics;
      out << pad(b.id, 10)
          << pad(m.fos_limit_point ? fixed(*m.fos_limit_point, 2) : std::string("-"), 8)
          << pad(m.failure_mode.kind, 14) << pad(m.stability, 12) << m.outcome << "\n";
    }
  }
  // The motion after failure, only where the scene asked for it.
  for (const auto& b : r.blocks) {
    if (!b.dynamics) continue;
    out << "\nmotion of " << b.id << " after failure (" << b.dynamics->trigger << "):\n";
    for (const auto& e : b.dynamics->events) out << "  " << event_text(e) << "\n";
  }
  for (const auto& n : r.notes) out << "note: " << n << "\n";
  return out.str();
}

}  // namespace rockface::storage

#include "storage/report/report_dynamics_json.h"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/common/number_format.h"
#include "storage/report/report_numbers.h"

namespace rockface::storage {

namespace {

using ordered = nlohmann::ordered_json;
using nlohmann::json;

double tidy_dynamics(double v) {
  // 9 significant digits: far beyond what the integration gives. An unknown
  // (NaN, infinity) stays one: the JSON writes it as null, not as 0.
  if (!std::isfinite(v)) return v;
  return std::strtod(format_significant(v, 9).c_str(), nullptr);
}

ordered vec_dynamics(const Eigen::Vector3d& v) {
  return ordered::array({tidy_dynamics(v(0)), tidy_dynamics(v(1)), tidy_dynamics(v(2))});
}

// An absolute point (m): to 1e-5 m at survey coordinates (report_numbers.h).
ordered point_dynamics(const Eigen::Vector3d& v) {
  return ordered::array({tidy_coordinate(v(0)), tidy_coordinate(v(1)), tidy_coordinate(v(2))});
}

// A number read back: null is an unknown (NaN).
double number_at(const json& o, const char* key, double otherwise) {
  if (!o.contains(key)) return otherwise;
  const json& v = o[key];
  return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>();
}

double number_of(const json& v) {
  return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>();
}

Eigen::Vector3d vec3(const json& j) {
  if (!j.is_array() || j.size() != 3) return Eigen::Vector3d::Zero();
  return {number_of(j[0]), number_of(j[1]), number_of(j[2])};
}

}  // namespace

ordered dynamics_to_json(const analysis::ReportDynamics& d) {
  ordered j;
  j["trigger"] = d.trigger;
  j["outcome"] = d.outcome;
  if (!d.stopped.empty()) j["stopped"] = d.stopped;
  ordered friction = ordered::object();
  for (const auto& [plane, deg] : d.friction_deg) friction[plane] = tidy_dynamics(deg);
  j["friction_deg"] = friction;
  j["cohesion"] = "lost";
  if (d.strength_divisor != 1) j["strength_divisor"] = tidy_dynamics(d.strength_divisor);
  ordered events = ordered::array();
  for (const auto& e : d.events) {
    ordered o;
    o["time_s"] = tidy_dynamics(e.time_s);
    o["kind"] = e.kind;
    o["event"] = e.what;
    o["planes"] = e.planes;
    o["text"] = event_text(e);
    events.push_back(o);
  }
  j["events"] = events;
  ordered path = ordered::array();
  for (const auto& s : d.path) {
    ordered o;
    o["t"] = tidy_dynamics(s.time_s);
    o["position"] = point_dynamics(s.position);
    o["orientation"] =
        ordered::array({tidy_dynamics(s.orientation(0)), tidy_dynamics(s.orientation(1)),
                        tidy_dynamics(s.orientation(2)), tidy_dynamics(s.orientation(3))});
    o["velocity"] = vec_dynamics(s.velocity);
    o["angular_velocity"] = vec_dynamics(s.angular_velocity);
    o["energy"] = {{"kinetic_translational", tidy_dynamics(s.kinetic_translational)},
                   {"kinetic_rotational", tidy_dynamics(s.kinetic_rotational)},
                   {"work", tidy_dynamics(s.work)},
                   {"dissipated", tidy_dynamics(s.dissipated)}};
    path.push_back(o);
  }
  j["path"] = path;
  if (d.landing) {
    const analysis::ReportLanding& l = *d.landing;
    ordered o;
    o["time_s"] = tidy_dynamics(l.time_s);
    o["point"] = point_dynamics(l.point);
    o["centroid"] = point_dynamics(l.centroid);
    o["speed"] = tidy_dynamics(l.speed);
    o["corner_speed"] = tidy_dynamics(l.corner_speed);
    o["angular_speed"] = tidy_dynamics(l.angular_speed);
    o["kinetic_energy"] = tidy_dynamics(l.kinetic_translational + l.kinetic_rotational);
    o["kinetic_translational"] = tidy_dynamics(l.kinetic_translational);
    o["kinetic_rotational"] = tidy_dynamics(l.kinetic_rotational);
    o["distance_from_start"] = tidy_dynamics(l.distance_from_start);
    if (l.distance_from_face) {
      o["distance_from_face"] = tidy_dynamics(*l.distance_from_face);
      o["face"] = l.face;
    }
    j["landing"] = o;
  }
  if (d.floor)
    j["floor"] = {{"point", point_dynamics(d.floor->first)},
                  {"normal", vec_dynamics(d.floor->second)}};
  j["numerics"] = {{"duration_s", tidy_dynamics(d.duration_s)},
                   {"sample_s", tidy_dynamics(d.sample_s)},
                   {"end_time_s", tidy_dynamics(d.end_time_s)},
                   {"abs_tol", d.abs_tol},
                   {"rel_tol", d.rel_tol},
                   {"max_step_s", tidy_dynamics(d.max_step_s)},
                   {"steps", d.steps},
                   {"rejected_steps", d.rejected_steps},
                   {"evaluations", d.evaluations},
                   {"drift_before_m", d.drift_before_m},
                   {"drift_after_m", d.drift_after_m},
                   {"drift_bound_m", d.drift_bound_m}};
  if (d.picture) j["picture"] = *d.picture;
  if (!d.notes.empty()) j["notes"] = d.notes;
  return j;
}

std::optional<analysis::ReportDynamics> dynamics_from_json(const json& j) {
  if (!j.is_object()) return std::nullopt;
  analysis::ReportDynamics d;
  try {
    d.trigger = j.value("trigger", "");
    d.outcome = j.value("outcome", "");
    d.stopped = j.value("stopped", "");
    d.strength_divisor = number_at(j, "strength_divisor", 1.0);
    const json friction = j.value("friction_deg", json::object());
    for (auto it = friction.begin(); it != friction.end(); ++it)
      d.friction_deg[it.key()] = number_of(it.value());
    for (const json& e : j.value("events", json::array())) {
      analysis::ReportMotionEvent ev;
      ev.time_s = number_at(e, "time_s", 0.0);
      ev.kind = e.value("kind", "");
      ev.what = e.value("event", "");
      for (const json& p : e.value("planes", json::array()))
        ev.planes.push_back(p.get<std::string>());
      d.events.push_back(ev);
    }
    for (const json& s : j.value("path", json::array())) {
      analysis::ReportMotionSample m;
      m.time_s = number_at(s, "t", 0.0);
      m.position = vec3(s["position"]);
      const json& q = s["orientation"];
      if (q.is_array() && q.size() == 4)
        m.orientation =
            Eigen::Vector4d(number_of(q[0]), number_of(q[1]), number_of(q[2]), number_of(q[3]));
      m.velocity = vec3(s["velocity"]);
      m.angular_velocity = vec3(s["angular_velocity"]);
      const json& en = s.value("energy", json::object());
      m.kinetic_translational = number_at(en, "kinetic_translational", 0.0);
      m.kinetic_rotational = number_at(en, "kinetic_rotational", 0.0);
      m.work = number_at(en, "work", 0.0);
      m.dissipated = number_at(en, "dissipated", 0.0);
      d.path.push_back(m);
    }
    if (j.contains("landing")) {
      const json& o = j["landing"];
      analysis::ReportLanding l;
      l.time_s = number_at(o, "time_s", 0.0);
      l.point = vec3(o["point"]);
      l.centroid = vec3(o["centroid"]);
      l.speed = number_at(o, "speed", 0.0);
      l.corner_speed = number_at(o, "corner_speed", 0.0);
      l.angular_speed = number_at(o, "angular_speed", 0.0);
      l.kinetic_translational = number_at(o, "kinetic_translational", 0.0);
      l.kinetic_rotational = number_at(o, "kinetic_rotational", 0.0);
      l.distance_from_start = number_at(o, "distance_from_start", 0.0);
      if (o.contains("distance_from_face")) {
        l.distance_from_face = number_of(o["distance_from_face"]);
        l.face = o.value("face", "");
      }
      d.landing = l;
    }
    if (j.contains("floor"))
      d.floor = std::make_pair(vec3(j["floor"]["point"]), vec3(j["floor"]["normal"]));
    const json& n = j.value("numerics", json::object());
    d.duration_s = number_at(n, "duration_s", 0.0);
    d.sample_s = number_at(n, "sample_s", 0.0);
    d.end_time_s = number_at(n, "end_time_s", 0.0);
    d.abs_tol = number_at(n, "abs_tol", 0.0);
    d.rel_tol = number_at(n, "rel_tol", 0.0);
    d.max_step_s = number_at(n, "max_step_s", 0.0);
    d.steps = n.value("steps", 0);
    d.rejected_steps = n.value("rejected_steps", 0);
    d.evaluations = n.value("evaluations", 0);
    d.drift_before_m = number_at(n, "drift_before_m", 0.0);
    d.drift_after_m = number_at(n, "drift_after_m", 0.0);
    d.drift_bound_m = number_at(n, "drift_bound_m", 0.0);
    if (j.contains("picture")) d.picture = j["picture"].get<std::string>();
    for (const json& note : j.value("notes", json::array()))
      d.notes.push_back(note.get<std::string>());
  } catch (const json::exception&) {
    return std::nullopt;  // not a report this program wrote
  }
  return d;
}

}  // namespace rockface::storage

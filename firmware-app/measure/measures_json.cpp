#include "firmware-app/measure/measures_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/common/units.h"
#include "core/measure/pair_photo.h"

namespace rockface::app {

namespace {

using nlohmann::json;

json vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

json pixels_json(const std::vector<Eigen::Vector2d>& px) {
  json a = json::array();
  for (const auto& p : px) a.push_back({p.x(), p.y()});
  return a;
}

json finite_or_null(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

}  // namespace

// The orientation fields of one plane estimate.
void put_plane_json(nlohmann::json& j, const measure::PlaneEstimate& p,
                    const Eigen::Vector3d& datum) {
  j["orientation_known"] = p.known;
  if (p.known) {
    j["dip"] = rad_to_deg(p.orientation.dip);
    j["dipdir"] = rad_to_deg(p.orientation.dipdir);
    j["sigma_deg"] = rad_to_deg(p.sigma);
  } else {
    j["dip"] = nullptr;
    j["dipdir"] = nullptr;
    j["sigma_deg"] = nullptr;
  }
  j["note"] = p.problem;
  j["fit_points"] = p.fit.count;
  j["outliers"] = p.outliers;
  j["rms_m"] = p.fit.rms_off_plane();
  j["centroid"] = vec(p.fit.centroid + datum);
}

std::string measures_json(const measure::MeasuredPicks& r, const measure::MeasureContext& c,
                          const std::string& model,
                          const std::map<std::string, std::string>& further_models) {
  json j;
  j["format"] = "rockface-measures/1";
  j["model"] = model;
  // Each measurement names its pair and that pair's 3D image.
  auto put_pair = [&](json& m, const std::string& photo) {
    m["pair"] = measure::pair_of_photo(photo);
    const auto f = further_models.find(photo);
    m["model"] = f != further_models.end() ? f->second : model;
  };
  std::map<std::string, std::string> joined_into;
  for (const auto& jt : r.joined)
    for (const auto& id : jt.face.pieces) joined_into[id] = jt.face.label;
  j["point_sigma_m"] = c.settings.point_sigma;
  j["datum"] = vec(c.datum);
  json ms = json::array();
  for (const auto& t : r.traces) {
    json m;
    m["id"] = t.m.id;
    m["type"] = "trace";
    m["method"] = !t.cost.empty() ? "semi_automatic" : t.taps.empty() ? "points" : "taps";
    m["joint"] = t.joint;
    m["origin"] = t.origin;  // hand | proposed | corrected (issue 25)
    if (t.compass) {  // issue 27: its plane is a compass reading, and how the trace lies in it
      json c;
      c["dip"] = t.compass->reading.dip_deg;
      c["dip_direction"] = t.compass->reading.dip_direction_deg;
      c["trace_off_deg"] = t.compass->trace_off_deg;
      c["fitted_off_deg"] =
          t.compass->fitted_off_deg ? json(*t.compass->fitted_off_deg) : json(nullptr);
      c["margin_deg"] = t.compass->margin_deg;
      c["marginal"] = t.compass->marginal();
      m["compass"] = c;
    }
    m["set"] = r.set_of(t.m.id);
    m["photo"] = t.m.picks.empty() ? json("") : json(t.m.picks.front().photo);
    put_pair(m, m["photo"].get<std::string>());
    if (const auto into = joined_into.find(t.m.id); into != joined_into.end())
      m["joined_into"] = into->second;
    m["pixels"] = pixels_json(t.taps);
    if (!t.cost.empty()) {
      std::vector<Eigen::Vector2d> path;
      for (const auto& p : t.m.picks) path.push_back(p.pixel);
      m["path_pixels"] = pixels_json(path);
      m["cost"] = t.cost;
      m["mean_cost"] = t.mean_cost;
    }
    put_plane_json(m, t.m.plane, c.datum);
    m["relief_m"] = t.m.plane.relief_off_face;
    m["length_m"] = t.m.length;
    m["censored"] = t.m.censored;
    ms.push_back(m);
  }
  for (const auto& a : r.areas) {
    json m;
    m["id"] = a.m.id;
    m["type"] = "area";
    m["set"] = r.set_of(a.m.id);
    m["rock_side"] = a.rock_side;
    // How the camera saw the area: the least angle between its plane and
    // the sight lines to the camera, and what telling its side needs; a
    // free face's rock side says where it came from (free_face_side.h).
    m["seen_at_deg"] = a.sight.least_deg;
    m["seen_needs_deg"] = a.sight.needed_deg;
    if (!a.rock_side.empty()) {
      m["rock_side_from"] = a.rock_side_from;
      m["marginal"] = a.marginal;
    }
    m["photo"] = a.m.outline.empty() ? json("") : json(a.m.outline.front().photo);
    put_pair(m, m["photo"].get<std::string>());
    std::vector<Eigen::Vector2d> px;
    for (const auto& p : a.m.outline) px.push_back(p.pixel);
    m["pixels"] = pixels_json(px);
    put_plane_json(m, a.m.plane, c.datum);
    m["area_m2"] = a.m.area;
    m["mesh_vertices"] = a.m.vertices;
    ms.push_back(m);
  }
  for (const auto& p : r.points) {
    json m;
    m["id"] = p.id;
    m["type"] = "point";
    m["set"] = r.set_of(p.id);
    m["photo"] = p.pick.photo;
    put_pair(m, p.pick.photo);
    m["pixels"] = pixels_json({p.pick.pixel});
    put_plane_json(m, p.plane, c.datum);
    m["point"] = vec(p.point + c.datum);
    ms.push_back(m);
  }
  j["measurements"] = ms;
  // Pieces of one joint trace measured on different pairs: one trace.
  json traces = json::array();
  for (const auto& jt : r.joined) {
    json m;
    m["id"] = jt.face.label;
    m["joint"] = jt.face.joint;
    m["pieces"] = jt.face.pieces;
    json pairs = json::array();
    for (const int image : jt.face.images) pairs.push_back(image);
    m["pairs"] = pairs;
    put_plane_json(m, jt.plane, c.datum);
    m["length_m"] = jt.length;
    m["censored"] = jt.censored;
    json points = json::array();
    for (const auto& p : jt.face.points) points.push_back(vec(p + c.datum));
    m["points"] = points;
    traces.push_back(m);
  }
  j["joined_traces"] = traces;
  json joints = json::array();
  for (const auto& jt : r.joints) {
    json m;
    m["label"] = jt.label;
    m["traces"] = jt.traces;
    put_plane_json(m, jt.plane, c.datum);
    joints.push_back(m);
  }
  j["joints"] = joints;
  json sets = json::array();
  for (std::size_t k = 0; k < r.sets.size(); ++k) {
    const auto& s = r.sets[k];
    json m;
    m["label"] = s.label;
    m["count"] = s.fisher.count;
    const auto o = s.fisher.plane();
    m["dip"] = rad_to_deg(o.dip);
    m["dipdir"] = rad_to_deg(o.dipdir);
    m["fisher_k"] = finite_or_null(s.fisher.kappa);
    m["alpha95_deg"] = finite_or_null(rad_to_deg(s.fisher.alpha95));
    m["spacing_m"] = s.spacing ? json(*s.spacing) : json(nullptr);
    m["mean_trace_length_m"] = s.mean_trace_length ? json(*s.mean_trace_length) : json(nullptr);
    m["mean_uncensored_trace_length_m"] =
        s.mean_uncensored_trace_length ? json(*s.mean_uncensored_trace_length) : json(nullptr);
    m["traces"] = s.traces;
    m["censored_traces"] = s.censored_traces;
    m["persistence_m"] = s.persistence ? json(*s.persistence) : json(nullptr);
    m["censoring"] = s.censoring;
    json members = json::array();
    for (std::size_t i = 0; i < r.poles.size(); ++i)
      if (r.clusters.set_of[i] == static_cast<int>(k)) members.push_back(r.pole_id(i));
    m["members"] = members;
    sets.push_back(m);
  }
  j["sets"] = sets;
  return j.dump(2) + "\n";
}

}  // namespace rockface::app

#include "firmware-app/measure_picks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/measure/least_cost_trace.h"

namespace rockface::app {

namespace {

using nlohmann::json;

const measure::PhotoView& view_of(const MeasureContext& c, const std::string& photo,
                                  const std::string& where) {
  const auto it = c.views.find(photo);
  if (it == c.views.end())
    throw InputError(where + ".photo", "the " + photo +
                                           " photograph's pose is not known for this model "
                                           "(a model file knows only the left one)");
  return it->second;
}

// The 3D image a photograph's picks land on: its pair's.
const measure::MeshPicker& picker_of(const MeasureContext& c, const std::string& photo) {
  const auto own = c.pickers.find(photo);
  return own != c.pickers.end() ? *own->second : *c.picker;
}

void require_in_image(const measure::PhotoView& view, const std::vector<Eigen::Vector2d>& pixels,
                      const std::string& where) {
  for (std::size_t i = 0; i < pixels.size(); ++i)
    if (!measure::pixel_in_image(view, pixels[i])) {
      std::ostringstream s;
      s << "pixel (" << pixels[i].x() << ", " << pixels[i].y() << ") is outside the " << view.name
        << " photograph (" << view.camera.width << " x " << view.camera.height << ")";
      throw InputError(where + "[" + std::to_string(i) + "]", s.str());
    }
}

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

// The orientation fields of one plane estimate.
void put_plane(json& j, const measure::PlaneEstimate& p, const Eigen::Vector3d& datum) {
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

std::optional<double> opt(double v, bool when) {
  return when ? std::optional<double>(v) : std::nullopt;
}

}  // namespace

std::string pair_photo(int pair, const std::string& side) {
  return pair == 1 ? side : "pair " + std::to_string(pair) + " " + side;
}

int pair_of_photo(const std::string& photo) {
  if (photo.rfind("pair ", 0) != 0) return 1;
  return std::stoi(photo.substr(5));
}

storage::Picks picks_by_pair_photo(storage::Picks picks) {
  for (auto& t : picks.traces)
    if (!t.photo.empty()) t.photo = pair_photo(t.pair, t.photo);
  for (auto& a : picks.areas) a.photo = pair_photo(a.pair, a.photo);
  for (auto& p : picks.points) p.photo = pair_photo(p.pair, p.photo);
  return picks;
}

const std::string& MeasuredPicks::pole_id(std::size_t k) const {
  const PoleSource& s = poles[k];
  switch (s.kind) {
    case 't':
      return traces[s.index].m.id;
    case 'a':
      return areas[s.index].m.id;
    case 'j':
      return joined[s.index].face.label;
    default:
      return points[s.index].id;
  }
}

const measure::PlaneEstimate& MeasuredPicks::pole_plane(std::size_t k) const {
  const PoleSource& s = poles[k];
  switch (s.kind) {
    case 't':
      return traces[s.index].m.plane;
    case 'a':
      return areas[s.index].m.plane;
    case 'j':
      return joined[s.index].plane;
    default:
      return points[s.index].plane;
  }
}

std::string MeasuredPicks::set_of(const std::string& id) const {
  for (std::size_t k = 0; k < poles.size(); ++k)
    if (pole_id(k) == id) {
      const int set = clusters.set_of.empty() ? -1 : clusters.set_of[k];
      return set >= 0 && set < static_cast<int>(sets.size()) ? sets[set].label : std::string();
    }
  return {};
}

MeasuredPicks measure_picks(const storage::Picks& picks, const MeasureContext& c,
                            std::optional<int> wanted_sets) {
  if (!c.picker) throw Error("measure_picks: no mesh");
  const std::string prefix = c.source.empty() ? std::string() : c.source + ": ";
  MeasuredPicks out;
  for (const auto& t : picks.traces) {
    const std::string where = prefix + t.where;
    MeasuredTrace mt;
    mt.joint = t.joint;
    if (!t.points.empty()) {
      std::vector<Eigen::Vector3d> relative;
      for (const auto& p : t.points) relative.push_back(p - c.datum);
      mt.m = measure::measure_trace_points(*c.picker, t.id, relative, c.settings, where);
    } else if (!t.pixels.empty()) {
      const measure::PhotoView& view = view_of(c, t.photo, where);
      require_in_image(view, t.pixels, where + ".pixels");
      mt.taps = t.pixels;
      mt.m = measure::measure_trace(picker_of(c, t.photo), view, t.id, t.pixels, c.settings, where);
    } else {
      const measure::PhotoView& view = view_of(c, t.photo, where);
      const std::vector<Eigen::Vector2d> ends{(*t.ends)[0], (*t.ends)[1]};
      require_in_image(view, ends, where + ".ends");
      const auto photo = c.photos.find(t.photo);
      if (photo == c.photos.end() || photo->second.empty())
        throw InputError(where + ".ends", "semi-automatic tracing needs the " + t.photo +
                                              " photograph, which this model does not have");
      measure::TraceRequest request;
      request.from = ends[0];
      request.to = ends[1];
      request.cost = measure::trace_cost_by_name(t.cost, where + ".cost");
      if (request.cost == measure::TraceCost::Curvature && t.photo != "left")
        throw InputError(where + ".cost",
                         "the curvature cost follows the 3D image on the left photograph only");
      for (std::size_t k = 0; k < 2; ++k)
        if (!c.picker->pick(view, ends[k], where))
          throw InputError(where + ".ends[" + std::to_string(k) + "]",
                           "no surface of the 3D image under this pick");
      const measure::TracedPath path =
          measure::trace_between(photo->second, &c.picker->mesh(), request, where + ".ends");
      // The path may cross small holes of the 3D image (a dark trace is
      // where dense matching fails first): the fit uses the pixels with
      // surface under them.
      std::vector<Eigen::Vector2d> on_surface;
      for (const auto& px : path.pixels)
        if (c.picker->pick(view, px, where)) on_surface.push_back(px);
      mt.taps = ends;
      mt.cost = t.cost;
      mt.mean_cost = path.mean_cost;
      mt.m = measure::measure_trace(*c.picker, view, t.id, on_surface, c.settings, where);
    }
    out.traces.push_back(std::move(mt));
  }
  for (const auto& a : picks.areas) {
    const std::string where = prefix + a.where;
    const measure::PhotoView& view = view_of(c, a.photo, where);
    require_in_image(view, a.polygon, where + ".polygon");
    out.areas.push_back(
        {measure::measure_area(picker_of(c, a.photo), view, a.id, a.polygon, c.settings, where),
         a.rock_side});
  }
  for (const auto& p : picks.points) {
    const std::string where = prefix + p.where;
    const measure::PhotoView& view = view_of(c, p.photo, where);
    require_in_image(view, {p.pixel}, where + ".pixel");
    out.points.push_back(measure::measure_point(picker_of(c, p.photo), view, p.id, p.pixel,
                                                p.radius, c.settings, where));
  }

  // Joints marked piece by piece: their traces' points fitted together.
  std::map<std::string, std::size_t> joint_index;
  for (const auto& t : out.traces) {
    if (t.joint.empty()) continue;
    auto [it, added] = joint_index.emplace(t.joint, out.joints.size());
    if (added) out.joints.push_back({t.joint, {}, {}});
    out.joints[it->second].traces.push_back(t.m.id);
  }
  for (auto& j : out.joints) {
    std::vector<Eigen::Vector3d> points, normals;
    for (const auto& t : out.traces)
      if (t.joint == j.label) {
        points.insert(points.end(), t.m.points.begin(), t.m.points.end());
        normals.insert(normals.end(), t.m.surface_normals.begin(), t.m.surface_normals.end());
      }
    if (normals.size() != points.size()) normals.clear();
    j.plane = measure::fit_trace_plane(points, normals, c.settings);
  }

  // Pieces of one trace tapped in different pairs' photographs are one
  // trace (the same rule as the replay's and the tablet's): one pole, one
  // trace length, in the statistics below.
  out.joined = joined_traces(photogrammetry::join_trace_pieces(trace_pieces(out)), out, c.settings);
  std::set<std::string> in_joined;
  for (const auto& j : out.joined) in_joined.insert(j.face.pieces.begin(), j.face.pieces.end());

  // Joint sets over the discontinuities whose plane is known.
  std::vector<Eigen::Vector3d> poles;
  std::vector<measure::SetMember> members;
  for (std::size_t i = 0; i < out.traces.size(); ++i) {
    const auto& m = out.traces[i].m;
    if (!m.plane.known || in_joined.count(m.id)) continue;
    out.poles.push_back({'t', i});
    poles.push_back(m.plane.fit.normal);
    members.push_back({m.plane.fit.normal, m.plane.fit.centroid, m.length, m.censored});
  }
  for (std::size_t i = 0; i < out.joined.size(); ++i) {
    const auto& j = out.joined[i];
    if (!j.plane.known) continue;
    out.poles.push_back({'j', i});
    poles.push_back(j.plane.fit.normal);
    members.push_back({j.plane.fit.normal, j.plane.fit.centroid, j.length, j.censored});
  }
  for (std::size_t i = 0; i < out.areas.size(); ++i) {
    const auto& a = out.areas[i];
    if (!a.m.plane.known || !a.rock_side.empty()) continue;  // a free face is no joint
    out.poles.push_back({'a', i});
    poles.push_back(a.m.plane.fit.normal);
    members.push_back({a.m.plane.fit.normal, a.m.plane.fit.centroid, std::nullopt, false});
  }
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const auto& p = out.points[i];
    if (!p.plane.known) continue;
    out.poles.push_back({'p', i});
    poles.push_back(p.plane.fit.normal);
    members.push_back({p.plane.fit.normal, p.point, std::nullopt, false});
  }
  if (!poles.empty()) {
    measure::ClusterOptions options;
    options.count = wanted_sets.value_or(0);
    if (options.count > static_cast<int>(poles.size()))
      throw InputError(prefix + "sets", "asks for " + std::to_string(options.count) +
                                            " sets but only " + std::to_string(poles.size()) +
                                            " planes are known");
    out.clusters = measure::cluster_poles(poles, options);
    out.sets = measure::summarise_joint_sets(members, out.clusters);
  }
  return out;
}

std::string measures_json(const MeasuredPicks& r, const MeasureContext& c, const std::string& model,
                          const std::map<std::string, std::string>& further_models) {
  json j;
  j["format"] = "rockface-measures/1";
  j["model"] = model;
  // Each measurement names its pair and that pair's 3D image.
  auto put_pair = [&](json& m, const std::string& photo) {
    m["pair"] = pair_of_photo(photo);
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
    put_plane(m, t.m.plane, c.datum);
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
    m["photo"] = a.m.outline.empty() ? json("") : json(a.m.outline.front().photo);
    put_pair(m, m["photo"].get<std::string>());
    std::vector<Eigen::Vector2d> px;
    for (const auto& p : a.m.outline) px.push_back(p.pixel);
    m["pixels"] = pixels_json(px);
    put_plane(m, a.m.plane, c.datum);
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
    put_plane(m, p.plane, c.datum);
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
    put_plane(m, jt.plane, c.datum);
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
    put_plane(m, jt.plane, c.datum);
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

std::vector<storage::Measurement> measurement_records(
    const MeasuredPicks& r, storage::RecordId visit_id, const PairRecords& first,
    const std::map<std::string, PairRecords>& further) {
  std::vector<storage::Measurement> out;
  auto base = [&](storage::Measurement::Kind kind, const std::string& id,
                  const measure::PlaneEstimate& plane) {
    storage::Measurement m;
    m.visit_id = visit_id;
    m.model_id = first.model_id;
    m.kind = kind;
    m.label = id;
    if (plane.known) {
      m.dip_deg = rad_to_deg(plane.orientation.dip);
      m.dipdir_deg = rad_to_deg(plane.orientation.dipdir);
      m.sigma_deg = rad_to_deg(plane.sigma);
    }
    m.fit_rms_m = plane.fit.rms_off_plane();
    m.note = plane.problem;
    return m;
  };
  auto photo = [&](storage::Measurement& m, const std::vector<measure::PhotoPixel>& px) {
    if (px.empty()) return;
    m.photo = px.front().photo;
    if (const auto pair = further.find(m.photo); pair != further.end()) {
      m.model_id = pair->second.model_id;
      m.photo_capture_id = pair->second.capture_id;
    } else if (m.photo == "left" || m.photo == "right") {
      m.photo_capture_id = first.capture_id;
    }
    for (const auto& p : px) m.pixels.push_back(p.pixel);
  };
  for (const auto& t : r.traces) {
    storage::Measurement m = base(storage::Measurement::Kind::trace, t.m.id, t.m.plane);
    m.joint_label = t.joint;
    m.points = t.m.points;
    photo(m, t.m.picks);
    m.trace_length_m = t.m.length;
    m.censored = t.m.censored;
    out.push_back(std::move(m));
  }
  for (const auto& a : r.areas) {
    storage::Measurement m = base(storage::Measurement::Kind::area, a.m.id, a.m.plane);
    m.points = a.m.outline_points;
    m.rock_side = a.rock_side;
    photo(m, a.m.outline);
    out.push_back(std::move(m));
  }
  for (const auto& p : r.points) {
    // The store keeps a point orientation only with its plane (a point
    // without one says nothing); MEASURES.json still lists it.
    if (!p.plane.known) continue;
    storage::Measurement m = base(storage::Measurement::Kind::point_orientation, p.id, p.plane);
    m.points = {p.point};
    photo(m, {p.pick});
    out.push_back(std::move(m));
  }
  return out;
}

std::vector<storage::JointSet> joint_set_records(const MeasuredPicks& r) {
  std::vector<storage::JointSet> out;
  for (const auto& s : r.sets) {
    storage::JointSet js;
    js.label = s.label;
    const auto o = s.fisher.plane();
    js.dip_deg = rad_to_deg(o.dip);
    js.dipdir_deg = rad_to_deg(o.dipdir);
    // The store keeps a finite K; all poles identical (K infinite) is kept
    // as the largest double, which no real set reaches.
    js.fisher_k =
        std::isfinite(s.fisher.kappa) ? s.fisher.kappa : std::numeric_limits<double>::max();
    js.count = static_cast<int>(s.fisher.count);
    if (std::isfinite(s.fisher.alpha95) && s.fisher.alpha95 < M_PI)
      js.alpha95_deg = rad_to_deg(s.fisher.alpha95);
    js.spacing_m = s.spacing;
    js.mean_trace_length_m = s.mean_trace_length;
    js.censored_traces = s.censored_traces;
    js.persistence_m = s.persistence;
    out.push_back(js);
  }
  return out;
}

std::vector<storage::Joint> joint_records(const MeasuredPicks& r, storage::RecordId visit_id) {
  std::vector<storage::Joint> out;
  auto add = [&](const std::string& id, const char* type, const measure::PlaneEstimate& plane,
                 std::optional<double> persistence) {
    if (!plane.known) return;
    storage::Joint j;
    j.visit_id = visit_id;
    j.label = id;
    j.set_label = r.set_of(id);
    j.dip_deg = rad_to_deg(plane.orientation.dip);
    j.dipdir_deg = rad_to_deg(plane.orientation.dipdir);
    j.point = plane.fit.centroid;
    j.source = std::string(type) + " " + id;
    j.type = type;
    j.persistence_m = persistence;
    out.push_back(std::move(j));
  };
  for (const auto& t : r.traces) add(t.m.id, "trace", t.m.plane, opt(t.m.length, true));
  for (const auto& a : r.areas)
    if (a.rock_side.empty()) add(a.m.id, "area", a.m.plane, std::nullopt);
  for (const auto& p : r.points) add(p.id, "point", p.plane, std::nullopt);
  return out;
}

void join_trace_records(const std::vector<JoinedTrace>& joined,
                        std::vector<storage::Measurement>& records) {
  for (const auto& j : joined) {
    const std::set<std::string> pieces(j.face.pieces.begin(), j.face.pieces.end());
    std::vector<storage::Measurement> kept;
    for (auto& m : records) {
      if (m.kind != storage::Measurement::Kind::trace || !pieces.count(m.label)) {
        kept.push_back(std::move(m));
        continue;
      }
      if (m.label != j.face.label) continue;  // a further piece: in the first one now
      m.points = j.face.points;
      m.trace_length_m = j.length;
      m.censored = j.censored;
      m.dip_deg.reset();
      m.dipdir_deg.reset();
      m.sigma_deg.reset();
      if (j.plane.known) {
        m.dip_deg = rad_to_deg(j.plane.orientation.dip);
        m.dipdir_deg = rad_to_deg(j.plane.orientation.dipdir);
        m.sigma_deg = rad_to_deg(j.plane.sigma);
        m.fit_rms_m = j.plane.fit.rms_off_plane();
      }
      m.note = "joined from";
      for (const auto& id : j.face.pieces) m.note += " " + id;
      m.note += " (the pixels are the first piece's)";
      if (!j.plane.problem.empty()) m.note += "; " + j.plane.problem;
      kept.push_back(std::move(m));
    }
    records = std::move(kept);
  }
}

void join_trace_joints(const std::vector<JoinedTrace>& joined,
                       std::vector<storage::Joint>& joints) {
  for (const auto& j : joined) {
    std::vector<storage::Joint> kept;
    for (auto& joint : joints) {
      const bool piece =
          joint.type == "trace" &&
          std::find(j.face.pieces.begin(), j.face.pieces.end(), joint.label) != j.face.pieces.end();
      // A further piece goes; so does the first when the joined trace's
      // plane is unknown (its record says why).
      if (piece && (joint.label != j.face.label || !j.plane.known)) continue;
      if (piece) {
        joint.persistence_m = j.length;
        joint.dip_deg = rad_to_deg(j.plane.orientation.dip);
        joint.dipdir_deg = rad_to_deg(j.plane.orientation.dipdir);
        joint.point = j.plane.fit.centroid;
      }
      kept.push_back(std::move(joint));
    }
    joints = std::move(kept);
  }
}

std::vector<photogrammetry::TracePiece> trace_pieces(const MeasuredPicks& measured) {
  std::vector<photogrammetry::TracePiece> out;
  for (const auto& t : measured.traces)
    out.push_back({t.m.id, t.joint,
                   pair_of_photo(t.m.picks.empty() ? std::string() : t.m.picks.front().photo),
                   t.m.points});
  return out;
}

std::vector<JoinedTrace> joined_traces(std::vector<photogrammetry::FaceTrace> faces,
                                       const MeasuredPicks& measured,
                                       const measure::MeasureSettings& settings) {
  std::map<std::string, const MeasuredTrace*> by_id;
  for (const auto& t : measured.traces) by_id[t.m.id] = &t;
  std::vector<JoinedTrace> out;
  for (auto& face : faces) {
    // Pieces in one photograph are traces the geologist drew apart (as for
    // a visit of one pair); pieces in different pairs' photographs are the
    // one trace crossing from one image to the next.
    if (std::set<int>(face.images.begin(), face.images.end()).size() < 2) continue;
    JoinedTrace j;
    std::vector<Eigen::Vector3d> points, normals;
    for (const auto& id : face.pieces) {
      const measure::TraceMeasurement& m = by_id.at(id)->m;
      points.insert(points.end(), m.points.begin(), m.points.end());
      normals.insert(normals.end(), m.surface_normals.begin(), m.surface_normals.end());
    }
    if (normals.size() != points.size()) normals.clear();
    j.plane = measure::fit_trace_plane(points, normals, settings);
    // Along the points in steps of the join distance: where the pieces
    // overlap their points interleave, differing across the run by the
    // registration residual (~1 cm), and summed point to point that
    // zigzag would lengthen the trace.
    const double step = photogrammetry::FaceTraceOptions{}.join_distance;
    Eigen::Vector3d last = face.points.front();
    for (std::size_t k = 1; k < face.points.size(); ++k)
      if (const double d = (face.points[k] - last).norm();
          d >= step || k + 1 == face.points.size()) {
        j.length += d;
        last = face.points[k];
      }
    // Each end of the joined trace is some piece's end: censored as that
    // end is (the piece ends where pieces meet are inside the trace).
    for (const Eigen::Vector3d& end : {face.points.front(), face.points.back()}) {
      double nearest = std::numeric_limits<double>::infinity();
      bool censored = false;
      for (const auto& id : face.pieces) {
        const measure::TraceMeasurement& m = by_id.at(id)->m;
        if (m.points.empty()) continue;
        for (const int e : {0, 1})
          if (const double d = ((e == 0 ? m.points.front() : m.points.back()) - end).norm();
              d < nearest) {
            nearest = d;
            censored = m.censored_ends[e];
          }
      }
      j.censored = j.censored || censored;
    }
    j.face = std::move(face);
    out.push_back(std::move(j));
  }
  return out;
}

std::string joined_note(const JoinedTrace& joined) {
  std::string list;
  for (const auto& id : joined.face.pieces) list += (list.empty() ? "" : ", ") + id;
  return joined.face.label + ": one trace across the pairs' photographs (" + list + ")";
}

}  // namespace rockface::app

#include "firmware-app/measure/measure_records.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"

namespace rockface::app {

namespace {

std::optional<double> opt(double v, bool when) {
  return when ? std::optional<double>(v) : std::nullopt;
}

// "traces T1 T2": the source `rockface replay` gives a joint fitted to
// several traces, which the tablet reads back (trace_map_runner.cpp).
std::string traces_source(const measure::MeasuredJoint& j) {
  std::string source = "traces";
  for (const auto& t : j.traces) source += " " + t;
  return source;
}

}  // namespace

std::vector<storage::Measurement> measurement_records(
    const measure::MeasuredPicks& r, storage::RecordId visit_id, const PairRecords& first,
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
    m.origin = t.origin;
    m.points = t.m.points;
    photo(m, t.m.picks);
    m.trace_length_m = t.m.length;
    m.censored = t.m.censored;
    if (t.compass) {  // issue 27: the plane is this reading (360 stored as 0, both north)
      m.compass_dip_deg = t.compass->reading.dip_deg;
      m.compass_dipdir_deg = std::fmod(t.compass->reading.dip_direction_deg, 360.0);
      m.compass_off_deg =
          std::max(t.compass->trace_off_deg, t.compass->fitted_off_deg.value_or(0.0));
    }
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

std::vector<storage::JointSet> joint_set_records(const measure::MeasuredPicks& r) {
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

std::vector<storage::Joint> joint_records(const measure::MeasuredPicks& r,
                                          storage::RecordId visit_id) {
  std::vector<storage::Joint> out;
  auto add = [&](const std::string& id, const char* type, const measure::PlaneEstimate& plane,
                 std::optional<double> persistence, bool compass = false) {
    if (!plane.known) return;
    storage::Joint j;
    j.visit_id = visit_id;
    j.label = id;
    j.set_label = r.set_of(id);
    j.dip_deg = rad_to_deg(plane.orientation.dip);
    j.dipdir_deg = rad_to_deg(plane.orientation.dipdir);
    j.point = plane.fit.centroid;
    // A plane read with a compass says so (the field report's source column).
    j.source = std::string(type) + " " + id + (compass ? " (compass)" : "");
    j.type = type;
    j.persistence_m = persistence;
    out.push_back(std::move(j));
  };
  for (const auto& t : r.traces)
    add(t.m.id, "trace", t.m.plane, opt(t.m.length, true), t.compass.has_value());
  for (const auto& a : r.areas)
    if (a.rock_side.empty()) add(a.m.id, "area", a.m.plane, std::nullopt);
  for (const auto& p : r.points) add(p.id, "point", p.plane, std::nullopt);
  return out;
}

void add_named_joints(const measure::MeasuredPicks& r, storage::RecordId visit_id,
                      std::vector<storage::Joint>& joints) {
  // The traces' own joints go: one discontinuity, one joint.
  std::set<std::string> covered;
  for (const auto& named : r.joints)
    if (named.plane.known) covered.insert(named.traces.begin(), named.traces.end());
  joints.erase(std::remove_if(joints.begin(), joints.end(),
                              [&](const storage::Joint& j) {
                                return j.type == "trace" && covered.count(j.label);
                              }),
               joints.end());
  for (const auto& named : r.joints) {
    if (!named.plane.known) continue;  // its traces keep their own joints
    for (const auto& j : joints)
      if (j.label == named.label)
        throw InputError("traces (joint " + named.label + ")",
                         "the joint name \"" + named.label + "\" is also the id of a measured " +
                             j.type + ": rename the joint or the " + j.type);
    storage::Joint j;
    j.visit_id = visit_id;
    j.label = named.label;
    // Its set: the one its traces are in, when they agree.
    std::set<std::string> sets;
    for (const auto& t : named.traces) sets.insert(r.set_of(t));
    if (sets.size() == 1) j.set_label = *sets.begin();
    j.dip_deg = rad_to_deg(named.plane.orientation.dip);
    j.dipdir_deg = rad_to_deg(named.plane.orientation.dipdir);
    j.point = named.plane.fit.centroid;
    j.source = traces_source(named);
    j.type = "trace";
    joints.push_back(std::move(j));
  }
}

void unname_joints_without_plane(const measure::MeasuredPicks& r,
                                 std::vector<storage::Measurement>& records) {
  for (const auto& named : r.joints) {
    if (named.plane.known) continue;
    for (auto& m : records)
      if (m.kind == storage::Measurement::Kind::trace && m.joint_label == named.label) {
        m.joint_label.clear();
        m.note += std::string(m.note.empty() ? "" : "; ") + "named joint " + named.label +
                  ", not stored (" + traces_source(named) + "): " + named.plane.problem;
      }
  }
}

std::vector<std::string> named_joint_notes(const measure::MeasuredPicks& r) {
  std::vector<std::string> out;
  for (const auto& named : r.joints) {
    std::string said = named.label + " (" + traces_source(named) + "): ";
    if (named.plane.known) {
      said += "joint " + format_fixed(rad_to_deg(named.plane.orientation.dip), 1) + "/" +
              format_fixed(rad_to_deg(named.plane.orientation.dipdir), 1) + ", sigma " +
              format_fixed(rad_to_deg(named.plane.sigma), 1, " deg");
      if (!named.plane.problem.empty()) said += "; " + named.plane.problem;
    } else {
      said += "no joint stored: " + named.plane.problem;
    }
    out.push_back(std::move(said));
  }
  return out;
}

void join_trace_records(const std::vector<measure::JoinedTrace>& joined,
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

void join_trace_joints(const std::vector<measure::JoinedTrace>& joined,
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

}  // namespace rockface::app

#include "core/tunnel/drive_sets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "core/common/degrees_per_radian.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/geometry/orientation.h"

namespace rockface::tunnel {

namespace {

// Resultant length of N unit poles with Fisher K: K = (N - 1) / (N - R).
double resultant_of(double k, int n) {
  if (n <= 1) return n;
  if (std::isinf(k)) return n;
  return std::max(1e-9, n - (n - 1) / k);
}

double alpha95_of(double n, double r) {
  if (n < 2 || r <= 0) return 180;
  if (r >= n) return 0;
  const double c = 1 - (n - r) / r * (std::pow(20.0, 1 / (n - 1)) - 1);
  if (c <= -1) return 180;
  return std::acos(std::min(1.0, c)) * kDegPerRad;
}

double axial_angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.dot(b)))) * kDegPerRad;
}

Eigen::Vector3d upward(Eigen::Vector3d n) {
  if (n.z() < 0 || (n.z() == 0 && (n.y() < 0 || (n.y() == 0 && n.x() < 0)))) n = -n;
  return n;
}

// A track while the visits are walked.
struct Live {
  std::size_t track = 0;
  Eigen::Vector3d last = Eigen::Vector3d::UnitZ();    // orientation when last seen
  Eigen::Vector3d running = Eigen::Vector3d::Zero();  // sum of R_i m_i since the last turn
  double running_n = 0;
  int missing = 0;
  std::size_t first_missing = 0;  // visit index where it went missing
  bool closed = false;
};

// Refuses options and visits out of range, naming the field; turns every
// set's pole into a unit normal pointing up.
void check_drive_sets_input(std::vector<VisitSets>& visits, const DriveSetOptions& options) {
  if (!(options.max_match_angle_deg > 0) || options.max_match_angle_deg > 90)
    throw InputError("options.max_match_angle_deg", "must be in (0, 90] degrees");
  if (options.max_missing_visits < 1)
    throw InputError("options.max_missing_visits", "must be at least 1");
  std::set<std::int64_t> ids;
  for (std::size_t i = 0; i < visits.size(); ++i) {
    const std::string where = "visits[" + std::to_string(i) + "]";
    if (!std::isfinite(visits[i].chainage)) throw InputError(where + ".chainage", "must be finite");
    if (!ids.insert(visits[i].visit_id).second)
      throw InputError(where + ".visit_id",
                       "visit " + std::to_string(visits[i].visit_id) + " is given twice");
    for (std::size_t j = 0; j < visits[i].sets.size(); ++j) {
      auto& s = visits[i].sets[j];
      const std::string w = where + ".sets[" + std::to_string(j) + "] (" + s.name + ")";
      if (!s.normal.allFinite() || s.normal.norm() == 0)
        throw InputError(w + ".normal", "must be a finite, non-zero vector");
      if (std::isnan(s.fisher_k) || s.fisher_k < 0)
        throw InputError(w + ".fisher_k", "must be >= 0 (or infinite)");
      if (s.count < 0) throw InputError(w + ".count", "must not be negative");
      s.normal = upward(s.normal.normalized());
    }
  }
}

// Each of the visit's sets matched to an open live track (-1: none), the
// pairs within the matching angle taken nearest first; live_used marks the
// tracks taken.
std::vector<long> match_visit_sets(const VisitSets& visit, const std::vector<Live>& live,
                                   const DriveSetOptions& options, std::vector<char>& live_used) {
  // Candidate pairs (set, live track) within the matching angle, nearest first.
  struct Pair {
    double angle;
    std::size_t set, live;
  };
  std::vector<Pair> pairs;
  for (std::size_t j = 0; j < visit.sets.size(); ++j)
    for (std::size_t t = 0; t < live.size(); ++t) {
      if (live[t].closed) continue;
      const double a = axial_angle_deg(visit.sets[j].normal, live[t].last);
      if (a <= options.max_match_angle_deg) pairs.push_back({a, j, t});
    }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    if (a.angle != b.angle) return a.angle < b.angle;
    return a.set != b.set ? a.set < b.set : a.live < b.live;
  });
  std::vector<long> track_of_set(visit.sets.size(), -1);
  live_used.assign(live.size(), 0);
  for (const Pair& p : pairs) {
    if (track_of_set[p.set] >= 0 || live_used[p.live]) continue;
    track_of_set[p.set] = static_cast<long>(p.live);
    live_used[p.live] = 1;
  }
  return track_of_set;
}

// A new track for a set no live track matched ("appears" after the first
// visit); returns its live index.
std::size_t open_set_track(const std::vector<VisitSets>& visits, std::size_t v,
                           const SetObservation& obs, DriveSets& out, std::vector<Live>& live,
                           std::vector<char>& live_used) {
  const VisitSets& visit = visits[v];
  SetTrack track;
  track.id = static_cast<int>(out.tracks.size()) + 1;
  if (v > 0) {
    track.appears = true;
    TrackEvent e;
    e.kind = TrackEvent::Kind::appears;
    e.chainage = visit.chainage;
    e.previous_chainage = visits[v - 1].chainage;
    e.visit_id = visit.visit_id;
    e.message = "set " + std::to_string(track.id) + " (" + obs.name + ") appears at chainage " +
                format_fixed(visit.chainage, 2) + ", not seen before";
    track.events.push_back(e);
  }
  out.tracks.push_back(track);
  Live l;
  l.track = out.tracks.size() - 1;
  l.last = obs.normal;
  live.push_back(l);
  live_used.push_back(1);
  return live.size() - 1;
}

// The set seen at this visit added to its track: its point, a turn when it
// leaves the track's mean since the last turn by more than both confidence
// cones (the running mean then starts again), the running mean updated.
void follow_set_track(const VisitSets& visit, std::size_t v, const SetObservation& obs, Live& l,
                      SetTrack& track) {
  TrackPoint pt;
  pt.visit_index = v;
  pt.visit_id = visit.visit_id;
  pt.chainage = visit.chainage;
  pt.name = obs.name;
  // Align the pole with the track's sense before any averaging.
  const Eigen::Vector3d m = obs.normal.dot(l.last) < 0 ? Eigen::Vector3d(-obs.normal) : obs.normal;
  pt.normal = upward(m);
  const geometry::PlaneOrientation o = geometry::plane_orientation(m);
  pt.dip_deg = o.dip * kDegPerRad;
  pt.dipdir_deg = o.dipdir * kDegPerRad;
  pt.fisher_k = obs.fisher_k;
  pt.count = obs.count;
  pt.alpha95_deg = fisher_alpha95_deg(obs.fisher_k, obs.count);
  const double r = resultant_of(obs.fisher_k, obs.count);
  if (l.running_n > 0) {
    const Eigen::Vector3d mean = l.running.normalized();
    const double running_a95 = alpha95_of(l.running_n, l.running.norm());
    pt.angle_to_running_mean_deg = axial_angle_deg(m, mean);
    pt.turn_cone_deg = pt.alpha95_deg + running_a95;
    pt.turned = pt.angle_to_running_mean_deg > pt.turn_cone_deg;
  }
  if (pt.turned) {
    track.turns = true;
    TrackEvent e;
    e.kind = TrackEvent::Kind::turns;
    e.chainage = visit.chainage;
    e.previous_chainage = track.points.back().chainage;
    e.visit_id = visit.visit_id;
    e.angle_deg = pt.angle_to_running_mean_deg;
    e.cone_deg = pt.turn_cone_deg;
    e.message = "set " + std::to_string(track.id) + " (" + obs.name + ") turns between chainage " +
                format_fixed(e.previous_chainage, 2) + " and " + format_fixed(e.chainage, 2) +
                ": " + format_fixed(e.angle_deg, 1) +
                " deg from its mean so far, beyond the confidence cones (" +
                format_fixed(e.cone_deg, 1) + " deg)";
    track.events.push_back(e);
    l.running.setZero();
    l.running_n = 0;
  }
  const Eigen::Vector3d aligned = l.running_n > 0 && m.dot(l.running) < 0 ? Eigen::Vector3d(-m) : m;
  l.running += r * aligned;
  l.running_n += std::max(obs.count, 1);
  l.last = m;
  l.missing = 0;
  track.points.push_back(pt);
}

// Tracks not seen in visit v: counted missing, closed after too many.
void age_unseen_tracks(std::vector<Live>& live, const std::vector<char>& live_used, std::size_t v,
                       const DriveSetOptions& options) {
  for (std::size_t t = 0; t < live.size(); ++t) {
    Live& l = live[t];
    if (l.closed || live_used[t]) continue;
    if (l.missing == 0) l.first_missing = v;
    ++l.missing;
    if (l.missing >= options.max_missing_visits) l.closed = true;
  }
}

// Vanished: missing at the end, or closed for missing too long.
void note_vanished_tracks(const std::vector<Live>& live, const std::vector<VisitSets>& visits,
                          DriveSets& out) {
  for (const Live& l : live) {
    if (l.missing == 0) continue;
    SetTrack& track = out.tracks[l.track];
    track.vanishes = true;
    TrackEvent e;
    e.kind = TrackEvent::Kind::vanishes;
    e.chainage = visits[l.first_missing].chainage;
    e.previous_chainage = track.points.back().chainage;
    e.visit_id = visits[l.first_missing].visit_id;
    e.message = "set " + std::to_string(track.id) + " (" + track.points.back().name +
                ") vanishes: last seen at chainage " + format_fixed(e.previous_chainage, 2) +
                ", not at " + format_fixed(e.chainage, 2);
    track.events.push_back(e);
  }
}

// Each track's mean pole over its points (weighted by their resultants) and
// its events in the drive's order.
void finish_set_tracks(DriveSets& out, double sense) {
  for (SetTrack& track : out.tracks) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const TrackPoint& p : track.points) {
      const double r = resultant_of(p.fisher_k, p.count);
      sum += (sum.dot(p.normal) < 0 ? -r : r) * p.normal;
    }
    if (sum.norm() > 0) track.mean_normal = upward(sum.normalized());
    std::stable_sort(track.events.begin(), track.events.end(),
                     [&](const TrackEvent& a, const TrackEvent& b) {
                       return sense * a.chainage < sense * b.chainage;
                     });
  }
}

}  // namespace

const char* track_event_name(TrackEvent::Kind kind) {
  switch (kind) {
    case TrackEvent::Kind::appears:
      return "appears";
    case TrackEvent::Kind::vanishes:
      return "vanishes";
    case TrackEvent::Kind::turns:
      return "turns";
  }
  return "appears";
}

double fisher_alpha95_deg(double fisher_k, int count) {
  return alpha95_of(count, resultant_of(fisher_k, count));
}

DriveSets track_sets_along_drive(std::vector<VisitSets> visits, const DriveSetOptions& options) {
  check_drive_sets_input(visits, options);
  const double sense = options.drive == Drive::ascending ? 1.0 : -1.0;
  std::stable_sort(visits.begin(), visits.end(), [&](const VisitSets& a, const VisitSets& b) {
    if (a.chainage != b.chainage) return sense * a.chainage < sense * b.chainage;
    return a.visit_id < b.visit_id;
  });

  DriveSets out;
  std::vector<Live> live;
  std::vector<char> live_used;
  for (std::size_t v = 0; v < visits.size(); ++v) {
    const VisitSets& visit = visits[v];
    std::vector<long> track_of_set = match_visit_sets(visit, live, options, live_used);
    for (std::size_t j = 0; j < visit.sets.size(); ++j) {
      const SetObservation& obs = visit.sets[j];
      if (track_of_set[j] < 0)
        track_of_set[j] = static_cast<long>(open_set_track(visits, v, obs, out, live, live_used));
      Live& l = live[static_cast<std::size_t>(track_of_set[j])];
      follow_set_track(visit, v, obs, l, out.tracks[l.track]);
    }
    age_unseen_tracks(live, live_used, v, options);
  }
  note_vanished_tracks(live, visits, out);
  finish_set_tracks(out, sense);
  out.visits = std::move(visits);
  return out;
}

}  // namespace rockface::tunnel

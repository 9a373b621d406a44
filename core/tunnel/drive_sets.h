#pragma once
// The joint sets along the drive: each visit's sets (mean orientation,
// Fisher K, count) matched across visits into tracks by orientation, never by
// name, and the changes a tunnel geologist looks for flagged with their
// chainage: a set that appears after the first visit, one that vanishes,
// one that turns.
//
// Matching: visits are taken in drive order (chainage ascending or
// descending as the drive goes; ties by visit id). A visit's sets are
// matched to the live tracks greedily, smallest angle first, one to one,
// against the orientation the track had when last seen (so a set that turns
// gradually stays one track), accepted within max_match_angle_deg. Poles are
// axes: a normal and its negative are the same plane.
//
// Turning: a track's running mean is the Fisher mean of its visits since its
// last turn (each visit weighted by its resultant length R = N - (N - 1) / K,
// so a visit with many tight poles counts more). A visit turns the set when
// its mean lies farther from that running mean than the two 95 % confidence
// cones together (alpha95 of the visit + alpha95 of the running mean: the
// cones do not overlap). Against consecutive visits a gradual turn would
// never show (each step inside the cones); against the running mean it
// accumulates until it does. Requiring the cones to part, not just the
// visit's cone, keeps a noisy visit (few poles) from flagging. After a turn
// the running mean starts again at the turning visit.
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/alignment.h"

namespace rockface::tunnel {

struct SetObservation {
  std::string name;  // as the visit named it (kept, not used for matching)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // mean pole, either sense
  double fisher_k = 0;                                // +infinity when all poles coincide
  int count = 0;                                      // poles behind the mean
};

struct VisitSets {
  std::int64_t visit_id = 0;
  double chainage = 0;
  std::vector<SetObservation> sets;
};

struct DriveSetOptions {
  Drive drive = Drive::ascending;
  double max_match_angle_deg = 20;
  // A track not seen in this many consecutive visits is closed (vanished);
  // a set of that orientation seen later starts a new track.
  int max_missing_visits = 2;
};

struct TrackPoint {
  std::size_t visit_index = 0;  // in drive order
  std::int64_t visit_id = 0;
  double chainage = 0;
  std::string name;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // upward
  double dip_deg = 0, dipdir_deg = 0;
  double fisher_k = 0;
  int count = 0;
  double alpha95_deg = 180;  // 180 when undefined (fewer than two poles)
  // Angle to the track's running mean before this visit, and the cone it was
  // tested against (alpha95 visit + alpha95 running mean); 0 / 0 for the
  // first point of a stretch.
  double angle_to_running_mean_deg = 0, turn_cone_deg = 0;
  bool turned = false;
};

struct TrackEvent {
  enum class Kind { appears, vanishes, turns };
  Kind kind = Kind::appears;
  double chainage = 0;  // the visit where it is found (vanishes: the first visit without it)
  double previous_chainage = 0;  // the visit before (where it was last as before)
  std::int64_t visit_id = 0;
  double angle_deg = 0, cone_deg = 0;  // turns: the angle and the cone it left
  std::string message;
};
const char* track_event_name(TrackEvent::Kind kind);

struct SetTrack {
  int id = 0;  // 1, 2, ... in order of first sighting
  std::vector<TrackPoint> points;
  std::vector<TrackEvent> events;
  bool appears = false, vanishes = false, turns = false;
  Eigen::Vector3d mean_normal = Eigen::Vector3d::UnitZ();  // over all its visits, upward
};

struct DriveSets {
  std::vector<VisitSets> visits;  // in drive order
  std::vector<SetTrack> tracks;
};

// Throws InputError("visits[i].sets[j]...") for a zero / non-finite normal,
// a negative K or count, a non-finite chainage; a duplicate visit id too.
DriveSets track_sets_along_drive(std::vector<VisitSets> visits,
                                 const DriveSetOptions& options = {});

// alpha95 (degrees) of N poles with Fisher K: cos a95 = 1 - (N - R) / R
// ((1 / 0.05)^(1 / (N - 1)) - 1), R = N - (N - 1) / K. 180 when N < 2.
double fisher_alpha95_deg(double fisher_k, int count);

}  // namespace rockface::tunnel

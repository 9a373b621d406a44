#pragma once
// The design cross-section (the "A-line" / theoretical excavation line of the
// drawings): a closed chain of line and circular-arc segments in the tunnel's
// cross-section frame, u = right, v = up (metres, looking in the drive
// direction, relative to the alignment axis; alignment.h's TunnelFrame).
//
// The chain runs counter-clockwise in (u, v) (a profile given clockwise is
// turned round by DesignProfile's constructor, its start point kept), so the
// outward normal is the chain's direction turned clockwise. Arc length s
// starts at the first segment's start: the helpers below start at the middle
// of the invert (u = 0, floor), so the developed view reads invert - right
// wall - crown - left wall - invert.
//
// Rays: the deviation of the excavated surface is measured along rays from
// one point of the cross-section, the ray centre (given, or the centroid of
// the profile's area). The profile must be star-shaped from it: every ray
// meets the outline once (validate() checks).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rockface::tunnel {

struct ProfileSegment {
  enum class Kind { line, arc };
  Kind kind = Kind::line;
  Eigen::Vector2d from{0, 0}, to{0, 0};
  // Arc only: its centre, and the sense in which it runs from `from` to
  // `to` (true = counter-clockwise in (u, v)). Its radius is |from - centre|;
  // |to - centre| must agree within kProfileJoinM.
  Eigen::Vector2d centre{0, 0};
  bool ccw = true;

  static ProfileSegment line(const Eigen::Vector2d& from, const Eigen::Vector2d& to);
  static ProfileSegment arc(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                            const Eigen::Vector2d& centre, bool ccw = true);
  // An arc from polar angles (radians, counter-clockwise from +u): runs
  // counter-clockwise when end > start, clockwise when end < start.
  static ProfileSegment arc_polar(const Eigen::Vector2d& centre, double radius, double start_angle,
                                  double end_angle);

  double radius() const { return (from - centre).norm(); }
  // Signed sweep of an arc (radians, + counter-clockwise); 0 for a line.
  double sweep() const;
  double length() const;
  Eigen::Vector2d point_at(double t) const;      // t in [0, length()]
  Eigen::Vector2d direction_at(double t) const;  // unit, along the chain
};

// One ray from the ray centre to the outline.
struct ProfileHit {
  double distance = 0;  // m, ray centre to the outline
  Eigen::Vector2d point{0, 0};
  double s = 0;                          // arc length of the hit
  Eigen::Vector2d outward_normal{0, 0};  // unit, of the outline at the hit
  std::size_t segment = 0;
};

// A validation finding: `ok` false with the reason and the segment concerned.
struct ProfileCheck {
  bool ok = true;
  std::string message;
  std::optional<std::size_t> segment;
};

class DesignProfile {
 public:
  DesignProfile() = default;
  // Takes the segments as given (turned round when clockwise); the ray
  // centre defaults to the centroid of the enclosed area. Does not throw on
  // a bad chain: call validate() / require_valid().
  explicit DesignProfile(std::vector<ProfileSegment> segments,
                         std::optional<Eigen::Vector2d> ray_centre = std::nullopt,
                         std::string name = {});

  // Closed (each segment starts where the previous ends, the last ends at
  // the first's start), every segment at least kProfileSegmentMinM long,
  // arcs consistent (both ends on the circle), not self-intersecting,
  // enclosing a positive area, and star-shaped from the ray centre (which
  // lies inside).
  ProfileCheck validate() const;
  // validate(), throwing InputError(where + ".segments[i]", message) if bad.
  void require_valid(const std::string& where) const;

  const std::vector<ProfileSegment>& segments() const { return segments_; }
  const Eigen::Vector2d& ray_centre() const { return ray_centre_; }
  bool ray_centre_given() const { return ray_centre_given_; }
  const std::string& name() const { return name_; }
  double perimeter() const;
  double area() const;  // m², enclosed (lines and arcs exactly)
  Eigen::Vector2d centroid() const;

  // s wraps into [0, perimeter()).
  Eigen::Vector2d point_at_length(double s) const;
  Eigen::Vector2d outward_normal_at_length(double s) const;
  // Polar angle (radians, counter-clockwise from +u) of the outline point at
  // s seen from the ray centre.
  double angle_at_length(double s) const;

  // The ray from the ray centre at `angle` (radians, counter-clockwise from
  // +u; up = pi/2) to the outline. On a valid profile every ray hits.
  ProfileHit ray_hit(double angle) const;
  double radius_toward(double angle) const { return ray_hit(angle).distance; }

 private:
  std::vector<ProfileSegment> segments_;
  std::vector<double> start_s_;  // arc length at each segment's start
  Eigen::Vector2d ray_centre_{0, 0};
  bool ray_centre_given_ = false;
  std::string name_;
};

// A circle of radius r about (0, centre_v), starting at its bottom.
DesignProfile circle_profile(double radius, double centre_v = 0);
// A rectangle `width` x `height` with its floor at v = floor_v, centred on
// u = 0, starting at the middle of the floor.
DesignProfile rectangle_profile(double width, double height, double floor_v);
// A horseshoe (the classic one-centre crown, two-centre walls): a crown
// semicircle of radius `crown_radius` centred at (0, springline_v); two wall
// arcs of radius `wall_radius` (>= crown_radius) that meet the crown
// tangentially at the springline, the right wall centred at
// (crown_radius - wall_radius, springline_v) and the left one mirrored; a
// flat invert at v = invert_v (< springline_v) between the walls. The ray
// centre is the crown's centre. Throws InputError naming the dimension when
// they do not close (the walls do not reach the invert, or cross before it).
DesignProfile horseshoe_profile(double crown_radius, double springline_v, double wall_radius,
                                double invert_v);

}  // namespace rockface::tunnel

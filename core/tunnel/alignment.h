#pragma once
// The tunnel's alignment: the surveyor's table of stations (chainage,
// easting, northing, elevation) joined by straight lines and circular
// horizontal arcs, or a dense polyline of stations. It maps chainage to the
// survey frame and back: a point of the axis and the tunnel's frame at a
// chainage, and for any point its chainage, offset and height.
//
// Conventions (DESIGN.md, and what a site surveyor expects):
// - Stations are survey coordinates (E, N, elevation; 10^6 m and more). The
//   alignment keeps them relative to the project's datum, and every 3D point
//   of this API that is not named `survey` is datum-relative ("local", the
//   frame of the project's meshes), so nothing loses precision.
// - Chainage is the horizontal length along the axis, ascending in the
//   table's order. Elevation runs linearly in chainage between two stations
//   (a constant grade per element). Cross-sections are normal to the axis,
//   so where the grade or the direction changes at a station (no vertical
//   or transition curve in the table) the sections of the two elements
//   overlap on one side of the axis and leave a wedge on the other, as wide
//   as the change in angle times the distance from the axis: place() takes
//   the nearer foot there, and the station's chainage in the wedge.
// - An arc's radius has a sign: + turns right (clockwise seen from above)
//   walking toward ascending chainage, - turns left. Of the two arcs of that
//   radius through two stations, the shorter (less than half a circle) is
//   meant, as in every alignment table.
// - The drive (excavation) advances toward ascending or descending
//   chainage. tangent_at(), frame_at() and place() look in the drive
//   direction: "right" and "offset" are to the right of a geologist facing
//   the face.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rockface::tunnel {

struct AlignmentStation {
  double chainage = 0;                               // m
  Eigen::Vector3d survey = Eigen::Vector3d::Zero();  // E, N, elevation, m
};

enum class Drive { ascending, descending };
// "ascending" / "descending"; drive_of throws InputError(where, ...) otherwise.
const char* drive_name(Drive drive);
Drive drive_of(const std::string& text, const std::string& where);

// The tunnel's frame at a chainage: origin on the axis (datum-relative),
// along = unit tangent in the drive direction (with the grade), right =
// horizontal unit vector to the right looking along, up = right x along
// (unit, normal to along, pointing up). (right, up) span the cross-section,
// whose coordinates are (u, v) = (right, up) in design_profile.h.
struct TunnelFrame {
  double chainage = 0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d along = Eigen::Vector3d::UnitY();
  Eigen::Vector3d right = Eigen::Vector3d::UnitX();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  // Local point at cross-section coordinates (u, v) and `a` metres along.
  Eigen::Vector3d to_local(double u, double v, double a = 0) const {
    return origin + u * right + v * up + a * along;
  }
};

// Where a point lies relative to the tunnel.
struct AlignmentPlace {
  // Chainage of the foot of the perpendicular from the point onto the axis
  // (the cross-section through the point). Outside the alignment it is
  // extrapolated along the end's tangent, never clamped.
  double chainage = 0;
  double offset = 0;  // m, to the right of the axis looking in the drive direction (+)
  double height = 0;  // m, above the axis in the cross-section (+ up)
  // 0 inside [first chainage, last chainage]; else how far (m of chainage)
  // the point's cross-section lies beyond the nearer end.
  double beyond_range = 0;
  bool inside() const { return beyond_range == 0; }
  // Distance from the axis in the cross-section, hypot(offset, height).
  double distance() const;
};

class Alignment {
 public:
  // Stations joined by elements: element i runs from stations[i] to
  // stations[i + 1] and is straight when radii[i] == 0, else a horizontal
  // circular arc of signed radius radii[i] (m; + right). radii has one entry
  // per element (stations.size() - 1). Refused with an InputError naming the
  // station ("stations[3]", chainage) and the reason: fewer than two
  // stations, a non-finite value, chainages not strictly ascending
  // (unordered or duplicate), a zero-length element, |radius| below half the
  // chord, an element whose chainage difference does not match its
  // horizontal length (tolerances.h).
  static Alignment from_elements(const std::vector<AlignmentStation>& stations,
                                 const std::vector<double>& radii, const Eigen::Vector3d& datum,
                                 Drive drive = Drive::ascending);
  // A dense polyline (straight chords between the stations; the stations'
  // chainages are authoritative along each chord). Same refusals, with a
  // looser chainage check (kPolylineMismatchRelative).
  static Alignment from_polyline(const std::vector<AlignmentStation>& stations,
                                 const Eigen::Vector3d& datum, Drive drive = Drive::ascending);

  Drive drive() const { return drive_; }
  void set_drive(Drive drive) { drive_ = drive; }
  const Eigen::Vector3d& datum() const { return datum_; }
  double first_chainage() const;
  double last_chainage() const;
  const std::vector<AlignmentStation>& stations() const { return stations_; }
  const std::vector<double>& radii() const { return radii_; }  // per element; 0 = straight
  bool is_polyline() const { return polyline_; }

  // The axis at a chainage (datum-relative). Outside the range: extrapolated
  // along the end's tangent (callers check contains()).
  Eigen::Vector3d point_at(double chainage) const;
  Eigen::Vector3d survey_point_at(double chainage) const { return point_at(chainage) + datum_; }
  // Unit tangent in the drive direction (with the grade).
  Eigen::Vector3d tangent_at(double chainage) const;
  TunnelFrame frame_at(double chainage) const;
  bool contains(double chainage) const;

  // A datum-relative point's place; place_survey() takes survey coordinates.
  AlignmentPlace place(const Eigen::Vector3d& local) const;
  AlignmentPlace place_survey(const Eigen::Vector3d& survey) const {
    return place(survey - datum_);
  }
  Eigen::Vector3d to_local(const Eigen::Vector3d& survey) const { return survey - datum_; }
  Eigen::Vector3d to_survey(const Eigen::Vector3d& local) const { return local + datum_; }

  // Horizontal azimuth (radians, clockwise from north) of the drive at a
  // chainage: the tunnel axis's trend for strike_vs_drive.h.
  double drive_trend_at(double chainage) const;

  struct Element {
    double c0 = 0, c1 = 0;              // chainage range
    Eigen::Vector2d a{0, 0}, b{0, 0};   // horizontal ends, datum-relative
    double z0 = 0, z1 = 0;              // elevations at the ends, datum-relative
    double radius = 0;                  // signed; 0 = straight
    Eigen::Vector2d centre{0, 0};       // arc centre
    double start_angle = 0, sweep = 0;  // arc: polar angle of a, signed sweep
  };
  const std::vector<Element>& elements() const { return elements_; }

 private:
  Alignment() = default;
  static Alignment build(const std::vector<AlignmentStation>& stations,
                         const std::vector<double>& radii, const Eigen::Vector3d& datum,
                         Drive drive, bool polyline);
  std::size_t element_at(double chainage) const;
  // In the table's direction (ascending chainage).
  Eigen::Vector3d ascending_tangent(const Element& e, double chainage) const;
  Eigen::Vector3d point_on(const Element& e, double chainage) const;
  // The foot of the perpendicular from p on element e, kept within it, and
  // its distance from p.
  std::pair<double, double> foot_on(const Element& e, const Eigen::Vector3d& p) const;
  // place()'s search: the chainage of the nearest foot (the first element's
  // on a tie), found through the bounding spheres below, so that a table of
  // 10^5 rows is not scanned whole for every point placed (issue 41: a
  // replay's rock points x 100 000 rows took 75 s).
  double nearest_foot(const Eigen::Vector3d& p) const;
  void build_bounds();

  // A sphere holding elements [first, last) (the chain's consecutive
  // elements), its children's indices in bounds_ (-1: a leaf).
  struct Bound {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = 0;
    std::size_t first = 0, last = 0;
    int left = -1, right = -1;
  };
  int build_bound(std::size_t first, std::size_t last);

  std::vector<AlignmentStation> stations_;
  std::vector<double> radii_;
  std::vector<Element> elements_;
  Eigen::Vector3d datum_ = Eigen::Vector3d::Zero();
  Drive drive_ = Drive::ascending;
  bool polyline_ = false;
  std::vector<Bound> bounds_;         // bounds_[0]: the root
  std::vector<Eigen::Vector3d> mid_;  // per element: the point at its middle chainage
  std::vector<double> reach_;         // per element: half its 3D length (>= any point's distance)
};

}  // namespace rockface::tunnel

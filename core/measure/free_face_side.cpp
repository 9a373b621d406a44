#include "core/measure/free_face_side.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/measure/tolerances.h"

namespace rockface::measure {

namespace {

std::string degrees(double v) {
  return format_fixed(v, 1, "\u00b0");
}

std::string quoted(const std::string& s) {
  return "\"" + s + "\"";
}

// The angle (degrees) at which the sight line from p to the camera centre
// meets the plane, positive on the side `outward` points to.
double sight_angle_deg(const Eigen::Vector3d& outward, const Eigen::Vector3d& p,
                       const Eigen::Vector3d& centre) {
  const Eigen::Vector3d d = centre - p;
  const double length = d.norm();
  if (length == 0) return 0;
  return rad_to_deg(std::asin(std::clamp(outward.dot(d) / length, -1.0, 1.0)));
}

void add_note(PlaneEstimate& plane, const std::string& note) {
  plane.problem += (plane.problem.empty() ? "" : "; ") + note;
}

std::string edge_on(const PhotoView& view, const AreaSight& s, const char* what) {
  return "the " + view.name + " photograph sees the " + what + " edge-on (" + degrees(s.least_deg) +
         " at its most grazing corner, " + degrees(s.needed_deg) + " needed to tell its side)";
}

}  // namespace

AreaSight sight_of_area(const AreaMeasurement& a, const PhotoView& view) {
  AreaSight s;
  const Eigen::Vector3d& centre = view.pose.centre;
  const Eigen::Vector3d n = a.plane.fit.normal.normalized();
  const Eigen::Vector3d& c = a.plane.fit.centroid;
  s.outward = n.dot(centre - c) >= 0 ? n : Eigen::Vector3d(-n);
  s.least_deg = sight_angle_deg(s.outward, c, centre);
  for (const auto& p : a.outline_points)
    s.least_deg = std::min(s.least_deg, sight_angle_deg(s.outward, p, centre));
  s.needed_deg = std::max(kMinFreeFaceViewDeg, kFreeFaceViewInSigmas * rad_to_deg(a.plane.sigma));
  return s;
}

bool wind_outward(AreaMeasurement& a, const Eigen::Vector3d& outward) {
  const auto& p = a.outline_points;
  if (p.size() < 3) return false;
  // The Newell normal: twice the vector area, whatever the corners' origin.
  Eigen::Vector3d newell = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < p.size(); ++i)
    newell += (p[i] - p[0]).cross(p[(i + 1) % p.size()] - p[0]);
  const double along = newell.dot(outward);
  if (along == 0) return false;
  if (along < 0) {
    std::reverse(a.outline.begin(), a.outline.end());
    std::reverse(a.outline_points.begin(), a.outline_points.end());
  }
  return true;
}

FreeFaceSide free_face_side(AreaMeasurement& a, const PhotoView& view, const std::string& picked,
                            const std::string& where) {
  FreeFaceSide side;
  side.sight = sight_of_area(a, view);
  const AreaSight& s = side.sight;
  // The half-space of the upward normal of the orientation stored (what
  // the analysis rebuilds the plane from): the air's side, the rock's.
  const Eigen::Vector3d up = geometry::plane_normal(a.plane.orientation);
  const bool air_above = s.outward.dot(up) > 0;
  const std::string seen = air_above ? "lower" : "upper";
  const double from_vertical = 90.0 - rad_to_deg(a.plane.orientation.dip);
  const bool near_vertical = from_vertical < kFreeFaceNearVerticalDeg;
  const std::string photograph = "the " + view.name + " photograph";

  if (!a.plane.known) {
    // No plane, no free face for the analysis (MEASURES.json lists it): the
    // pick's side is kept, its corners wound as the photograph sees them.
    side.rock_side = picked;
    side.from = "pick";
    if (s.told()) wind_outward(a, s.outward);
    return side;
  }
  if (s.told()) {
    side.rock_side = seen;
    side.from = "photograph";
    wind_outward(a, s.outward);
    if (picked == seen) return side;
    if (!near_vertical)
      throw InputError(where + ".rock_side",
                       quoted(picked) + ", but " + photograph + " sees this face (dip " +
                           degrees(rad_to_deg(a.plane.orientation.dip)) + ") from its " +
                           (air_above ? "upper" : "lower") + " side, at " + degrees(s.least_deg) +
                           " to it: the rock behind it is on its " + seen + " side");
    add_note(a.plane, "rock_side " + quoted(picked) + " read as behind the face " + photograph +
                          " sees (" + degrees(s.least_deg) + "): " + quoted(seen) +
                          " for this face, " + degrees(std::abs(from_vertical)) +
                          " from vertical, where upper and lower swap");
    return side;
  }
  // Edge-on: the photograph does not tell the side.
  if (near_vertical)
    throw InputError(where, edge_on(view, s, "face") + " and the face is " +
                                degrees(from_vertical) + " from vertical, where rock_side " +
                                quoted(picked) +
                                " may mean either side: pick it in a photograph that sees it");
  side.rock_side = picked;
  side.from = "pick";
  side.marginal = true;
  // The air on the side the pick does not give the rock.
  wind_outward(a, picked == "lower" ? up : Eigen::Vector3d(-up));
  add_note(a.plane, "marginal: rock side " + quoted(picked) +
                        " from the pick alone: " + edge_on(view, s, "face"));
  return side;
}

AreaSight wind_toward_camera(AreaMeasurement& a, const PhotoView& view) {
  const AreaSight s = sight_of_area(a, view);
  if (s.told())
    wind_outward(a, s.outward);
  else if (a.plane.known)  // without a plane (a sliver) there is no side to see
    add_note(a.plane, edge_on(view, s, "area") + ": its corners are kept in the order tapped");
  return s;
}

}  // namespace rockface::measure

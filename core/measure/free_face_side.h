#pragma once
// Which side of a measured area the air is on, and the rock side of a free
// face (an area picked with `rock_side`, docs/scene-extensions.md), from the
// geometry: the camera that photographed the area saw it from the air, so
// the rock lies behind the face as seen from the centre of the camera whose
// photograph (its pair's) the area was picked in. The tap order says
// nothing: a geologist goes round a polygon either way, and the area's
// corners are put in the order that turns counter-clockwise seen from the
// air (its Newell normal outward, as the analysis reads a surface patch,
// SCENE.md; core/faces/free_surface.cpp).
#include <string>

#include <Eigen/Core>

#include "core/measure/photo_view.h"
#include "core/measure/plane_measurement.h"

namespace rockface::measure {

// How the camera sees an area's plane.
struct AreaSight {
  // Unit normal of the area's plane on the camera's side (toward the air).
  Eigen::Vector3d outward = Eigen::Vector3d::UnitZ();
  // The least angle (degrees) between the plane and the sight lines from
  // the area's centroid and its corners to the camera centre; negative when
  // a corner sees the plane from the other side than the centroid does.
  double least_deg = 0;
  // What telling the side needs (tolerances.h: kMinFreeFaceViewDeg, or
  // kFreeFaceViewInSigmas sigmas of the plane's normal when larger).
  double needed_deg = 0;
  bool told() const { return least_deg >= needed_deg; }
  // The verdict's margin: how far beyond (negative: short of) the need.
  double margin_deg() const { return least_deg - needed_deg; }
};

AreaSight sight_of_area(const AreaMeasurement& area, const PhotoView& view);

// Puts the corners (pixels and points alike) in the order that turns
// counter-clockwise seen from the side `outward` points to. False, and
// nothing changed, when the corners on the surface enclose no area to wind
// (fewer than three of them, or a figure of eight).
bool wind_outward(AreaMeasurement& area, const Eigen::Vector3d& outward);

struct FreeFaceSide {
  std::string rock_side;  // "upper" | "lower": the half-space of the stored plane's upward normal
  // "photograph": behind the face as its photograph sees it (the pick's
  // rock_side agreeing, or read so on a face near vertical); "pick": the
  // pick's rock_side, where the photograph cannot tell (the face seen
  // edge-on, or no plane measured).
  std::string from;
  AreaSight sight;
  bool marginal = false;  // the photograph sees the face edge-on: the side is the pick's alone
};

// The rock side of a free face picked with `picked` ("upper" | "lower"),
// its corners wound counter-clockwise seen from the air, and what a
// geologist must know added to its note (area.plane.problem). The camera
// decides where it tells the side (AreaSight::told); a pick it contradicts
// on a face more than kFreeFaceNearVerticalDeg from vertical is refused
// (InputError at `where`.rock_side), nearer vertical it is read as "behind
// the face" and the note says so. A face seen edge-on takes the pick's
// side, marginal, its note giving the angle; edge-on and near vertical as
// well, neither tells, and it is refused (InputError at `where`).
FreeFaceSide free_face_side(AreaMeasurement& area, const PhotoView& view, const std::string& picked,
                            const std::string& where);

// An area that is no free face (a mapped surface, a joint face) wound
// counter-clockwise seen from the camera where the photograph tells the
// side; seen edge-on it stays as tapped and, when it has a plane, its note
// says so.
AreaSight wind_toward_camera(AreaMeasurement& area, const PhotoView& view);

}  // namespace rockface::measure

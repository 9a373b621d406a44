#pragma once
// A visit's place in the tunnel, found from its 3D image once the image lies
// in the project frame: the face's chainage is where rays along the axis
// meet it (face_front.h; the median of their hits), else the part of the
// surface farthest in the drive direction (surface_reach.h); the offset and
// height are of the surface within 0.3 m of the face. How the image came
// into the project frame says how the visit was placed: monitoring targets
// with survey coordinates (ground control, with their residuals) or the
// chainage the geologist typed for the range pole plus the compass line.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/profile_deviation.h"

namespace rockface::tunnel {

// Misfit of one control item (a pole target, a monitoring target) after the
// registration, in metres, project frame.
struct TargetResidual {
  std::string label;
  Eigen::Vector3d residual = Eigen::Vector3d::Zero();
};

// How a visit was placed in the tunnel and where its face stands.
struct VisitPlacement {
  enum class Method {
    ground_control,    // monitoring targets with survey coordinates seen in the photographs
    chainage_compass,  // the chainage the geologist typed plus the compass line
  };
  Method method = Method::chainage_compass;
  double chainage = 0;  // of the face
  double offset_m = 0;  // of the face's centre from the axis, + right
  std::optional<double> height_m;
  // Ground control: residuals of the targets (label, dx, dy, dz in m) and
  // their rms; chainage + compass: the compass azimuth used (degrees).
  std::vector<TargetResidual> residuals;
  std::optional<double> rms_m;
  std::optional<double> compass_azimuth_deg;
  std::string note;
};

// How the visit's 3D image came into the project frame, as its registration
// says: the method and what the placement reports of it.
struct FrameRegistration {
  VisitPlacement::Method method = VisitPlacement::Method::chainage_compass;
  std::vector<TargetResidual> residuals;      // ground control
  double rms_m = 0;                           // ground control
  std::optional<double> compass_azimuth_deg;  // chainage + compass, when the registration has it
  // Chainage + compass: the 3D image has a north (issue 42: a model the pole
  // scaled and levelled without a compass line was placed as if it had one).
  bool north_known = true;
  // Chainage + compass: how the pole's place was given ("chainage 112.00
  // typed"); empty when the pole's position was surveyed.
  std::string typed;
};

// The typed placement of the range pole (scene `tunnel.placement`, or the
// tablet's form): its lower target at a chainage, offset and height above
// the axis. Returns the target centre, datum-relative. Throws InputError
// naming tunnel.placement.chainage when the chainage is off the alignment.
Eigen::Vector3d typed_pole_position(const Alignment& alignment, double chainage, double offset,
                                    double height);

// `surface`: the visit's 3D images in the project frame, the range pole
// marked as not rock (per vertex). Throws InputError naming `visit` ("visit
// 7") when the surface has no rock or its face lies off the alignment.
VisitPlacement place_visit(const Alignment& alignment, const DesignProfile& profile,
                           const SurfaceInput& surface, const FrameRegistration& registration,
                           const std::string& visit);

}  // namespace rockface::tunnel

#include "core/measure/compass_reading.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/measure/plane_measurement.h"

namespace rockface::measure {

namespace {

std::string degrees_text(double deg) {
  return format_fixed(deg, 1, "°");
}

// The angle (degrees) between a line and a plane of unit normal n.
double line_off_plane_deg(const Eigen::Vector3d& line, const Eigen::Vector3d& n) {
  return rad_to_deg(std::asin(std::min(1.0, std::abs(line.normalized().dot(n)))));
}

// The angle (degrees) between two planes by their normals (either sense).
double plane_to_plane_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

}  // namespace

void check_compass_reading(const CompassReading& r, const std::string& where) {
  auto bad = [&](const char* field, double v, const char* range) {
    throw InputError(where + "." + field,
                     std::isfinite(v)
                         ? format_significant(v, 6) + " is not a compass reading (" + range + ")"
                         : std::string("must be a finite number"));
  };
  if (!std::isfinite(r.dip_deg) || r.dip_deg < 0 || r.dip_deg > 90)
    bad("dip", r.dip_deg, "a dip is from 0 to 90 degrees");
  if (!std::isfinite(r.dip_direction_deg) || r.dip_direction_deg < 0 || r.dip_direction_deg > 360)
    bad("dip_direction", r.dip_direction_deg, "a dip direction is from 0 to 360 degrees");
}

CompassCheck apply_compass_reading(TraceMeasurement& trace, const CompassReading& reading,
                                   const std::string& where) {
  check_compass_reading(reading, where);
  PlaneEstimate& plane = trace.plane;
  const Eigen::Vector3d n = geometry::plane_normal_deg(reading.dip_deg, reading.dip_direction_deg);
  CompassCheck check;
  check.reading = reading;
  check.trace_off_deg = line_off_plane_deg(plane.fit.line, n);
  if (plane.known) check.fitted_off_deg = plane_to_plane_deg(plane.fit.normal, n);
  const double worst = std::max(check.trace_off_deg, check.fitted_off_deg.value_or(0.0));
  check.margin_deg = kMaxTraceOffCompassDeg - worst;

  // What the trace alone said, kept in words beside the reading.
  const std::string fitted = plane.known
                                 ? "the plane fitted to the trace, " +
                                       degrees_text(rad_to_deg(plane.orientation.dip)) + " / " +
                                       degrees_text(rad_to_deg(plane.orientation.dipdir)) +
                                       ", is " + degrees_text(*check.fitted_off_deg) + " from it"
                                 : std::string();
  std::string note;
  if (check.marginal()) {
    note = check.trace_off_deg >= check.fitted_off_deg.value_or(0.0)
               ? "the trace runs " + degrees_text(check.trace_off_deg) +
                     " out of the compass plane: check the reading"
               : fitted + ": check the reading";
    note += " (tolerance " + degrees_text(kMaxTraceOffCompassDeg) + ")";
    if (plane.known && check.trace_off_deg >= *check.fitted_off_deg) note += "; " + fitted;
  } else {
    note = "orientation from a compass reading; the trace runs " +
           degrees_text(check.trace_off_deg) + " out of its plane";
    if (plane.known) note += "; " + fitted;
  }

  plane.known = true;
  plane.fit.normal = n;  // upward (DESIGN.md), through the points' centroid
  plane.orientation.dip = deg_to_rad(reading.dip_deg);
  plane.orientation.dipdir = geometry::wrap_azimuth(deg_to_rad(reading.dip_direction_deg));
  plane.sigma = deg_to_rad(kCompassSigmaDeg);
  plane.problem = note;
  return check;
}

}  // namespace rockface::measure

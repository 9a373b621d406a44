#include "firmware-app/reconstruct/registration_options.h"

#include <cmath>
#include <fstream>

#include "core/common/error.h"
#include "core/photogrammetry/estimators/registration.h"
#include "core/photogrammetry/targets/reference_line.h"

namespace rockface::app {

photogrammetry::RegistrationSources registration_sources(const RegistrationOptions& o) {
  if (o.azimuth.has_value() != !o.reference_line.empty())
    throw InputError(o.azimuth ? o.reference_line_name : o.azimuth_name,
                     o.azimuth_name + " and " + o.reference_line_name +
                         " go together (the compass bearing of a line given by two pixels of the "
                         "left image)");
  if (o.declination && !o.azimuth)
    throw InputError(o.declination_name,
                     "needs " + o.azimuth_name + " and " + o.reference_line_name);
  if (o.azimuth && !(std::isfinite(*o.azimuth) && *o.azimuth >= 0 && *o.azimuth <= 360))
    throw InputError(o.azimuth_name, "a compass bearing is 0 to 360 degrees");
  if (o.declination && !(std::abs(*o.declination) <= 90))
    throw InputError(o.declination_name, "a declination is -90 to 90 degrees (east positive)");
  // Neither can be longer than a site's tape: a typo (2000 for 2.000).
  if (o.range_pole && !(*o.range_pole > 0 && *o.range_pole <= 50))
    throw InputError(o.range_pole_name, "the pole length must be > 0 m and at most 50 m");
  if (o.baseline && !(*o.baseline > 0 && *o.baseline <= 1000))
    throw InputError(o.baseline_name, "the base must be > 0 m and at most 1000 m");

  photogrammetry::RegistrationSources sources;
  sources.range_pole_m = o.range_pole;
  sources.baseline_m = o.baseline;
  if (o.azimuth) {
    photogrammetry::NorthReference n;
    const auto line = photogrammetry::parse_reference_line(o.reference_line, o.reference_line_name);
    n.from_px = line[0];
    n.to_px = line[1];
    n.azimuth_deg = *o.azimuth;
    n.declination_deg = o.declination.value_or(0.0);
    n.where = o.reference_line_name;
    sources.north = n;
  }
  if (!o.gcp.empty()) {
    std::ifstream in(o.gcp);
    if (!in) throw InputError(o.gcp, "cannot open the control-point file");
    sources.control_points = photogrammetry::parse_control_points(in, o.gcp);
    sources.control_points_where = o.gcp;
    if (sources.control_points.size() < 3)
      throw InputError(o.gcp, "need three or more control points, found " +
                                  std::to_string(sources.control_points.size()));
  }
  return sources;
}

}  // namespace rockface::app

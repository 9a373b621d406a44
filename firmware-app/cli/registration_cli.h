#pragma once
// The options that register a pair (registration_options.h), the same on
// every verb that takes photographs: `reconstruct` and `replay FOLDER`.
#include <CLI/CLI.hpp>

#include "firmware-app/reconstruct/registration_options.h"

namespace rockface::app {

inline void add_registration_options(CLI::App& sub, RegistrationOptions& o) {
  sub.add_option("--range-pole", o.range_pole,
                 "distance between the two target centres of the vertical range pole, m");
  sub.add_option("--azimuth", o.azimuth,
                 "compass bearing of the reference line, degrees clockwise from north");
  sub.add_option("--reference-line", o.reference_line,
                 "U1,V1,U2,V2: the reference line's two pixels in the left image");
  sub.add_option("--declination", o.declination, "magnetic declination, degrees, east positive");
  sub.add_option("--gcp", o.gcp,
                 "ground control points, CSV id,u,v,X,Y,Z (u, v in the left image)");
  sub.add_option("--baseline", o.baseline, "measured distance between the camera stations, m");
}

}  // namespace rockface::app

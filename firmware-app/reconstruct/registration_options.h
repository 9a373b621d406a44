#pragma once
// What registers a pair, as the geologist gives it outside a scene: the range
// pole's length, the compass bearing of a reference line (two pixels of the
// left photograph), the declination, control points, the measured base.
// `rockface reconstruct` takes them as options; `rockface replay FOLDER`
// (issue 42) as options or from the visit file beside the photographs
// (visit_file.h). Every value is checked here, naming the option or field,
// before any long work starts.
#include <optional>
#include <string>

#include "core/photogrammetry/reconstruction/reconstruction.h"

namespace rockface::app {

struct RegistrationOptions {
  std::optional<double> range_pole;   // m between the two target centres
  std::optional<double> azimuth;      // compass bearing of the reference line, degrees
  std::string reference_line;         // "U1,V1,U2,V2" in the left photograph
  std::optional<double> declination;  // degrees, east positive
  std::string gcp;                    // control points, CSV id,u,v,X,Y,Z; empty: none
  std::optional<double> baseline;     // m between the camera stations

  // How each is named in a refusal: the command line's options by default;
  // a visit file names its fields.
  std::string range_pole_name = "--range-pole", azimuth_name = "--azimuth",
              reference_line_name = "--reference-line", declination_name = "--declination",
              baseline_name = "--baseline";
};

// Throws InputError naming the option (or field) at fault.
photogrammetry::RegistrationSources registration_sources(const RegistrationOptions& options);

}  // namespace rockface::app

#pragma once
// The visit file beside a camera's photographs (rockface-visit/1, issue 42):
// what the geologist noted on site for a visit brought home on a card, so
// that `rockface replay FOLDER` gives a scaled, north-oriented visit without
// a scene. Every field is optional; an unknown one is refused by name.
//
//   {"format": "rockface-visit/1",
//    "range_pole_m": 2.0,
//    "compass": {"reference_line_px": [[412, 655], [1210, 671]],
//                "azimuth_deg": 87.5, "declination_deg": 2.3},
//    "control_points": "gcp.csv",     (beside the visit file)
//    "baseline_m": 1.8,
//    "preset": "standard",
//    "heading": "North portal",       (the face of a tunnel driven from more than one,
//                                       storage/tunnel/visit_heading.h)
//    "geologist": "Anna Berger",      (who mapped the visit, storage/project/visit_geologist.h)
//    "note": "round 112"}
#include <array>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/common/preset.h"

namespace rockface::storage {

struct VisitFile {
  std::string source;  // the file, for messages
  std::optional<double> range_pole_m;
  std::optional<std::array<Eigen::Vector2d, 2>> reference_line_px;  // left photograph
  std::optional<double> azimuth_deg, declination_deg;
  std::string control_points;  // a path, made absolute against the visit file's folder
  std::optional<double> baseline_m;
  std::optional<Preset> preset;
  std::string heading;    // "" none
  std::string geologist;  // "" none
  std::string note;
};

// Throws InputError naming the file and the field ("visit.json: compass.azimuth_deg").
VisitFile load_visit_file(const std::string& path);
// The same from the file's text; `path` names it in messages and is the
// folder `control_points` is relative to.
VisitFile parse_visit_file(const std::string& text, const std::string& path);

}  // namespace rockface::storage

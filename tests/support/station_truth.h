#pragma once
// What a rendered scene's camera stations say, for tests that compare a
// reconstruction's scale and north with them: the true bearing of a
// station's view axis, the true base between two stations, and the bearing
// of a stored model's camera axis in the model's frame.
#include <cmath>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/common/units.h"
#include "storage/project/project_records.h"

namespace rockface::test {

// Degrees clockwise from north (+y) of the station's axis, station to its
// look-at point, in [0, 360).
inline double true_view_bearing_deg(const nlohmann::json& station) {
  const auto p = station.at("position"), q = station.at("look_at");
  const double a = rad_to_deg(
      std::atan2(q[0].get<double>() - p[0].get<double>(), q[1].get<double>() - p[1].get<double>()));
  return a < 0 ? a + 360 : a;
}

// Metres between two stations' positions.
inline double true_base_m(const nlohmann::json& a, const nlohmann::json& b) {
  double s = 0;
  for (int i = 0; i < 3; ++i) {
    const double d = a.at("position")[i].get<double>() - b.at("position")[i].get<double>();
    s += d * d;
  }
  return std::sqrt(s);
}

// Degrees clockwise from the model frame's +y of the left camera's axis.
inline double model_axis_bearing_deg(const storage::Model& m) {
  const Eigen::Vector3d axis = m.camera_to_mesh->R * Eigen::Vector3d::UnitZ();
  const double a = rad_to_deg(std::atan2(axis.x(), axis.y()));
  return a < 0 ? a + 360 : a;
}

}  // namespace rockface::test

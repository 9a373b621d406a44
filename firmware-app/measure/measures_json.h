#pragma once
// The measured picks as the file `rockface measure --out` writes:
// rockface-measures/1 (docs/scene-extensions.md).
#include <map>
#include <string>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/measure/pick_measurement.h"

namespace rockface::app {

// rockface-measures/1; coordinates absolute. `model`: the first pair's 3D
// image; `further_models` a further pair's by its photographs' names
// (measure::pair_photo): each measurement names its own.
std::string measures_json(const measure::MeasuredPicks& measured,
                          const measure::MeasureContext& context, const std::string& model,
                          const std::map<std::string, std::string>& further_models = {});

// One plane estimate's fields (dip, dipdir, sigma_deg or nulls with the
// note, fit points, outliers, rms, absolute centroid) into `j`: the same
// for every measured plane of every file.
void put_plane_json(nlohmann::json& j, const measure::PlaneEstimate& p,
                    const Eigen::Vector3d& datum);

}  // namespace rockface::app

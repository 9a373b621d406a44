#pragma once
// The measured picks as the file `rockface measure --out` writes:
// rockface-measures/1 (docs/scene-extensions.md).
#include <map>
#include <string>

#include "core/measure/pick_measurement.h"

namespace rockface::app {

// rockface-measures/1; coordinates absolute. `model`: the first pair's 3D
// image; `further_models` a further pair's by its photographs' names
// (measure::pair_photo): each measurement names its own.
std::string measures_json(const measure::MeasuredPicks& measured,
                          const measure::MeasureContext& context, const std::string& model,
                          const std::map<std::string, std::string>& further_models = {});

}  // namespace rockface::app

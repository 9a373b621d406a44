#pragma once
// The rock mass of a visit as JSON (format rockface-rockmass/1): what
// `rockface rockmass --out` writes and the `rockmass` section of the block
// report (docs/scene-extensions.md, "The rock mass in figures"). Lengths m,
// areas m2, volumes m3, angles degrees, RQD %, Jv per m3; every rating with
// its source ("measured" | "entered" | "measured + entered" | "not
// entered") and its table; a total only when complete.
#include <nlohmann/json.hpp>

#include "core/rockmass/rock_mass_figures.h"

namespace rockface::storage {

nlohmann::json rockmass_report_json(const rockmass::RockMassFigures& figures);

}  // namespace rockface::storage

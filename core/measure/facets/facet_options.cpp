#include "core/measure/facets/facet_options.h"

#include <cmath>
#include <string>

#include "core/common/error.h"

namespace rockface::measure {

FacetOptions facet_options(Preset preset) {
  FacetOptions o;
  switch (preset) {
    case Preset::fast:
      o.angle_tolerance_deg = 12.0;
      o.min_area_m2 = 0.10;
      o.smoothing_passes = 2;
      o.refit_growth = 2.0;
      break;
    case Preset::standard:
      break;
    case Preset::precise:
      o.angle_tolerance_deg = 8.0;
      o.min_area_m2 = 0.02;
      o.smoothing_passes = 4;
      o.refit_growth = 1.25;
      break;
  }
  return o;
}

void check_facet_options(const FacetOptions& o) {
  auto refuse = [](const char* field, const std::string& why) {
    throw InputError(std::string("facets.") + field, why);
  };
  if (!(o.angle_tolerance_deg > 0 && o.angle_tolerance_deg < 45))
    refuse("angle_tolerance_deg",
           "must be in (0, 45) degrees, got " + std::to_string(o.angle_tolerance_deg));
  if (!(o.min_area_m2 > 0) || !std::isfinite(o.min_area_m2))
    refuse("min_area_m2", "must be a positive area, got " + std::to_string(o.min_area_m2));
  if (!(o.planarity_in_sigmas >= 1) || !std::isfinite(o.planarity_in_sigmas))
    refuse("planarity_in_sigmas",
           "must be at least 1 (the noise itself), got " + std::to_string(o.planarity_in_sigmas));
  if (o.smoothing_passes < 0 || o.smoothing_passes > 200)
    refuse("smoothing_passes", "must be in [0, 200], got " + std::to_string(o.smoothing_passes));
  if (!(o.refit_growth > 1) || !std::isfinite(o.refit_growth))
    refuse("refit_growth", "must be more than 1, got " + std::to_string(o.refit_growth));
}

}  // namespace rockface::measure

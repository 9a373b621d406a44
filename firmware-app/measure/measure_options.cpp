#include "firmware-app/measure/measure_options.h"

#include <exception>
#include <sstream>
#include <stdexcept>

#include "core/common/error.h"
#include "storage/project/visit_geologist.h"

namespace rockface::app {
namespace {

// --add-to-visit N: measure on visit N's 3D images and store in it; the
// visit is then given by this option alone.
void take_visit_to_add_to(const std::optional<storage::RecordId>& add_to_visit,
                          MeasureRequest& request) {
  if (!add_to_visit) return;
  if (request.on.visit || request.on.model)
    throw InputError("--add-to-visit",
                     "it names the visit measured on and stored in: leave out --visit and --model");
  request.on.visit = add_to_visit;
  request.add_to_visit = true;
  // A visit's own geologist is named where the visit is, not by a
  // measurement added to it.
  if (!request.geologist.empty())
    throw InputError("--geologist", "it names a new visit's geologist: name visit " +
                                        std::to_string(*add_to_visit) +
                                        "'s with `rockface place PROJECT --visit " +
                                        std::to_string(*add_to_visit) + " --geologist NAME`");
}

// --sets: a count in [1, 12], or "auto".
void parse_sets(const std::string& text, MeasureRequest& request) {
  request.automatic_sets = text == "auto";
  if (text.empty() || text == "auto") return;
  try {
    std::size_t used = 0;
    request.sets = std::stoi(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw InputError("--sets", "\"" + text + "\" is not a count or \"auto\"");
  }
  if (*request.sets < 1 || *request.sets > 12)
    throw InputError("--sets", text + " is outside [1, 12]");
}

// --point-sigma: a picked point's precision, a length in (0, 10] m (issue
// 41: nan, inf, 0 or -1 made every joint "orientation unknown").
void check_point_sigma(const std::optional<double>& sigma) {
  if (sigma && !(*sigma > 0 && *sigma <= 10)) {
    std::ostringstream value;
    value << *sigma;
    throw InputError("--point-sigma", value.str() + " is outside (0, 10] m");
  }
}

// --friction: the stereonet overlay's friction angle, in (0, 90) degrees
// and finite (issue 41: nan, 90 or 1e308 drew a meaningless overlay).
void check_friction(double friction_deg) {
  if (!(friction_deg > 0 && friction_deg < 90)) {
    std::ostringstream value;
    value << friction_deg;
    throw InputError("--friction", value.str() + " is outside (0, 90) degrees");
  }
}

}  // namespace

MeasureRequest measure_request(const MeasureOptions& o) {
  MeasureRequest request = o.request;
  check_point_sigma(request.on.point_sigma);
  check_friction(request.friction_deg);
  parse_sets(o.sets, request);
  request.geologist = storage::checked_geologist(request.geologist, "--geologist");
  take_visit_to_add_to(o.add_to_visit, request);
  return request;
}

}  // namespace rockface::app

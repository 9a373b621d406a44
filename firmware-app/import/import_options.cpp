#include "firmware-app/import/import_options.h"

#include <array>
#include <cmath>
#include <exception>
#include <sstream>
#include <vector>

#include "core/common/error.h"
#include "storage/project/visit_geologist.h"

namespace rockface::app {
namespace {

// `count` finite numbers separated by commas; `shape` names them in the
// refusal ("three numbers E,N,Z").
std::vector<double> parse_numbers(const std::string& text, std::size_t count,
                                  const std::string& option, const std::string& shape) {
  const std::string refusal = "'" + text + "' is not " + shape;
  std::vector<double> v;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || item.find_first_not_of(" ", used) != std::string::npos || !std::isfinite(x))
      throw InputError(option, refusal);
    v.push_back(x);
  }
  if (v.size() != count || (!text.empty() && text.back() == ',')) throw InputError(option, refusal);
  return v;
}

Eigen::Vector3d parse_triple(const std::string& text, const std::string& option) {
  const auto v = parse_numbers(text, 3, option, "three numbers E,N,Z");
  return {v[0], v[1], v[2]};
}

// Two points of the cloud, in the file's coordinates.
std::array<Eigen::Vector3d, 2> parse_two_points(const std::string& text,
                                                const std::string& option) {
  const auto v = parse_numbers(text, 6, option, "six numbers X1,Y1,Z1,X2,Y2,Z2");
  return {Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Vector3d(v[3], v[4], v[5])};
}

}  // namespace

ImportRequest import_request(const ImportOptions& o) {
  ImportRequest request;
  request.file = o.file;
  if (!o.columns.empty())
    request.file_options.columns = storage::parse_point_columns(o.columns, "--columns");
  if (!o.offset.empty()) request.file_options.offset = parse_triple(o.offset, "--offset");
  if (!o.view_from.empty()) request.view_from = parse_triple(o.view_from, "--view-from");
  request.frame = o.frame;
  request.gcp_file = o.gcp;
  if (o.pole == "auto") {
    request.find_pole = true;
  } else if (!o.pole.empty()) {
    const auto ends = parse_two_points(o.pole, "--pole");
    request.pole = ImportPole{ends[0], ends[1]};
  } else if (o.range_pole) {
    throw InputError("--range-pole", "needs --pole (the targets' centres on the cloud)");
  }
  request.pole_length_m = o.range_pole;
  if (o.azimuth.has_value() != !o.reference_line.empty())
    throw InputError(o.azimuth ? "--reference-line" : "--azimuth",
                     "--azimuth and --reference-line go together (the compass bearing of a "
                     "line given by two points of the cloud)");
  if (o.declination && !o.azimuth)
    throw InputError("--declination", "needs --azimuth and --reference-line");
  if (o.azimuth) {
    const auto ends = parse_two_points(o.reference_line, "--reference-line");
    request.north = ImportCompassLine{ends[0], ends[1], *o.azimuth, o.declination.value_or(0)};
  }
  if (o.visit != 0) request.visit = o.visit;
  request.geologist = storage::checked_geologist(o.geologist, "--geologist");
  if (request.visit && !request.geologist.empty())
    throw InputError("--geologist", "it names a new visit's geologist: name visit " +
                                        std::to_string(o.visit) +
                                        "'s with `rockface place PROJECT --visit " +
                                        std::to_string(o.visit) + " --geologist NAME`");
  return request;
}

}  // namespace rockface::app

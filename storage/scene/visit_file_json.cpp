#include "storage/scene/visit_file_json.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/json_reader.h"
#include "storage/project/visit_geologist.h"
#include "storage/tunnel/visit_heading.h"

namespace rockface::storage {

namespace {

using nlohmann::json;

Eigen::Vector2d visit_pixel(const Reader& r, const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 2) r.fail(path, "must be a pixel [u, v]");
  return {r.non_negative(v[0], path + "[0]"), r.non_negative(v[1], path + "[1]")};
}

}  // namespace

VisitFile load_visit_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the visit file");
  std::stringstream text;
  text << in.rdbuf();
  return parse_visit_file(text.str(), path);
}

VisitFile parse_visit_file(const std::string& text, const std::string& path) {
  // As every JSON reader: a number beyond double's range or a bare NaN is
  // named by its field (it was "not JSON", no field said; issue 41).
  const json doc = parse_json_naming_nan(text, path);
  const Reader r(path);
  r.only_fields(doc, "",
                {"format", "range_pole_m", "compass", "control_points", "baseline_m", "preset",
                 "heading", "geologist", "note"});
  if (r.string(r.require(doc, "", "format"), "format") != "rockface-visit/1")
    r.fail("format", "must be \"rockface-visit/1\"");
  VisitFile out;
  out.source = path;
  if (const json* v = r.optional(doc, "", "range_pole_m"))
    out.range_pole_m = r.positive(*v, "range_pole_m");
  if (const json* c = r.optional(doc, "", "compass")) {
    r.only_fields(*c, "compass", {"reference_line_px", "azimuth_deg", "declination_deg"});
    const json& line =
        r.array(r.require(*c, "compass", "reference_line_px"), "compass.reference_line_px");
    if (line.size() != 2) r.fail("compass.reference_line_px", "must hold two pixels");
    out.reference_line_px = {visit_pixel(r, line[0], "compass.reference_line_px[0]"),
                             visit_pixel(r, line[1], "compass.reference_line_px[1]")};
    out.azimuth_deg =
        r.number_in(r.require(*c, "compass", "azimuth_deg"), "compass.azimuth_deg", 0, 360);
    if (const json* d = r.optional(*c, "compass", "declination_deg"))
      out.declination_deg = r.number_in(*d, "compass.declination_deg", -90, 90);
  }
  if (const json* v = r.optional(doc, "", "control_points")) {
    const std::string file = r.id(*v, "control_points");
    const std::filesystem::path p(file);
    out.control_points =
        p.is_absolute() ? file : (std::filesystem::path(path).parent_path() / p).string();
  }
  if (const json* v = r.optional(doc, "", "baseline_m"))
    out.baseline_m = r.positive(*v, "baseline_m");
  if (const json* v = r.optional(doc, "", "preset"))
    out.preset = parse_preset(r.string(*v, "preset"), r.where("preset"));
  if (const json* v = r.optional(doc, "", "heading"))
    out.heading = checked_heading(r.string(*v, "heading"), r.where("heading"));
  if (const json* v = r.optional(doc, "", "geologist"))
    out.geologist = checked_geologist(r.string(*v, "geologist"), r.where("geologist"));
  if (const json* v = r.optional(doc, "", "note")) out.note = r.string(*v, "note");
  return out;
}

}  // namespace rockface::storage

#include "firmware-app/tunnel/visit_profile_json.h"
#include "storage/field_report/field_report.h"

#include <cmath>

#include <nlohmann/json.hpp>

namespace rockface::app {

namespace {

using nlohmann::json;

// Millimetres for lengths, cm^2-level for areas: what survey of a profile
// resolves; more digits would claim what the mesh does not give.
double round_to(double v, double step) {
  return std::round(v / step) * step;
}

json position(const tunnel::ProfilePosition& p) {
  return {{"chainage", round_to(p.chainage, 0.001)},
          {"s_m", round_to(p.s, 0.001)},
          {"angle_deg", round_to(p.angle * 180 / M_PI, 0.1)},
          {"survey",
           {round_to(p.survey.x(), 0.001), round_to(p.survey.y(), 0.001),
            round_to(p.survey.z(), 0.001)}}};
}

}  // namespace

std::string visit_profile_json(const VisitProfile& v) {
  const auto& d = v.deviation;
  json j;
  j["tunnel"] = {{"name", v.tunnel.name},
                 {"drive", tunnel::drive_name(v.tunnel.drive)},
                 {"underbreak_tolerance_m", v.tunnel.underbreak_tolerance_m},
                 {"profile_perimeter_m", round_to(v.tunnel.profile.perimeter(), 0.001)},
                 {"profile_area_m2", round_to(v.tunnel.profile.area(), 0.001)}};
  json placement = {{"visit", v.placement.visit_id},
                    {"method", storage::placement_method_name(v.placement.method)},
                    {"face_chainage", round_to(v.placement.chainage, 0.001)},
                    {"face_offset_m", round_to(v.placement.offset_m, 0.001)},
                    {"note", v.placement.note}};
  if (v.placement.rms_m) placement["residual_rms_m"] = *v.placement.rms_m;
  if (v.placement.compass_azimuth_deg)
    placement["compass_azimuth_deg"] = round_to(*v.placement.compass_azimuth_deg, 0.01);
  j["placement"] = placement;
  j["round"] = {{"from_chainage", round_to(v.round_from, 0.001)},
                {"to_chainage", round_to(v.round_to, 0.001)},
                {"from", v.round_from_source}};
  j["status"] = tunnel::deviation_status_name(d.status);
  j["message"] = d.message;
  // Issue 38: with no wall or roof in view (or the round off the alignment)
  // nothing was compared: the volumes and the largest overbreak are
  // unknown (null), never 0, which would read as "excavated to the design".
  const bool measured = d.status != tunnel::DeviationStatus::no_walls_in_view &&
                        d.status != tunnel::DeviationStatus::outside_alignment;
  const auto known = [measured](double value) { return measured ? json(value) : json(nullptr); };
  j["overbreak_volume_m3"] = known(round_to(d.overbreak_volume_m3, 0.001));
  j["underbreak_volume_m3"] = known(round_to(d.underbreak_volume_m3, 0.001));
  j["seen_fraction"] = round_to(d.seen_fraction, 0.001);
  j["excluded_fraction"] = round_to(d.excluded_fraction, 0.001);
  // Issue 38: the cells filled across holes of the 3D image from their
  // measured neighbours, and their part of the volumes (included above).
  j["interpolated"] = {
      {"fraction", round_to(d.interpolated_fraction, 0.001)},
      {"overbreak_volume_m3", known(round_to(d.interpolated_overbreak_m3, 0.001))},
      {"underbreak_volume_m3", known(round_to(d.interpolated_underbreak_m3, 0.001))},
      {"max_hole_m", round_to(d.max_interpolated_hole_m, 0.001)}};
  j["excluded_vertices_range_pole"] = v.pole_vertices;
  j["max_overbreak_m"] = known(round_to(d.max_overbreak_m, 0.001));
  if (measured && d.max_overbreak_m > 0) j["max_overbreak_at"] = position(d.max_overbreak);
  // Issue 38: what the figures count and leave out, and how sure they are.
  const auto sigma = [measured](const std::optional<double>& value, double step) {
    return measured && value ? json(round_to(*value, step)) : json(nullptr);
  };
  j["overbreak_volume_sigma_m3"] = sigma(d.overbreak_volume_sigma_m3, 0.001);
  j["underbreak_volume_sigma_m3"] = sigma(d.underbreak_volume_sigma_m3, 0.001);
  j["cell_sigma_m"] = sigma(d.cell_sigma_m, 0.0001);
  j["noise_threshold_m"] = round_to(d.noise_threshold_m, 0.0001);
  // Issue 38: each cell's own precision (its distance and incidence): how
  // it was predicted and its range; cell_sigma_m and noise_threshold_m are
  // then the median measured cell's.
  if (measured && v.cell_precision)
    j["cell_precision"] = {{"model", v.cell_precision->model},
                           {"min_sigma_m", round_to(v.cell_precision->min_sigma_m, 0.0001)},
                           {"median_sigma_m", round_to(v.cell_precision->median_sigma_m, 0.0001)},
                           {"max_sigma_m", round_to(v.cell_precision->max_sigma_m, 0.0001)}};
  if (measured && d.lining_offset.cells > 0)
    j["lining_offset"] = {{"median_m", round_to(d.lining_offset.median_m, 0.0001)},
                          {"standard_error_m", round_to(d.lining_offset.standard_error_m, 0.0001)},
                          {"cells", d.lining_offset.cells},
                          {"removed", d.lining_offset_removed}};
  j["cells_left_out"] = {{"off_the_lining", d.cells_off_lining},
                         {"below_the_invert", d.cells_below_invert},
                         {"max_invert_overbreak_m", round_to(d.max_invert_overbreak_m, 0.001)}};
  // Patches beyond the noise threshold no deeper than the lining around them
  // is rough (break_significance.h): left out of the volumes, and said.
  if (measured)
    j["noise_patches_left_out"] = {
        {"patches", d.noise_patches},
        {"overbreak_m3", round_to(d.noise_patches_overbreak_m3, 0.001)},
        {"underbreak_m3", round_to(d.noise_patches_underbreak_m3, 0.001)}};
  json left_out = json::array();
  for (const auto& l : d.sections_left_out)
    left_out.push_back({{"chainage_from", round_to(l.chainage_from, 0.001)},
                        {"chainage_to", round_to(l.chainage_to, 0.001)},
                        {"sections", l.sections},
                        {"why", l.why}});
  j["sections_left_out"] = left_out;
  if (d.has_underbreak) {
    j["max_underbreak_m"] = round_to(d.max_underbreak_m, 0.001);
    j["max_underbreak_at"] = position(d.max_underbreak);
  }
  json beyond = json::array();
  for (const auto& p : d.beyond_tolerance)
    beyond.push_back({{"chainage_from", round_to(p.chainage_from, 0.001)},
                      {"chainage_to", round_to(p.chainage_to, 0.001)},
                      {"s_from_m", round_to(p.s_from, 0.001)},
                      {"s_to_m", round_to(p.s_to, 0.001)},
                      {"area_m2", round_to(p.area_m2, 0.0001)},
                      {"max_depth_m", round_to(p.max_depth_m, 0.001)},
                      {"deepest", position(p.deepest)}});
  j["underbreak_beyond_tolerance"] = beyond;
  json sections = json::array();
  for (const auto& s : d.sections) {
    // A section that saw nothing has no figures: null, never 0.
    const auto seen = [&s](double value, double step) {
      return s.seen_fraction > 0 ? json(round_to(value, step)) : json(nullptr);
    };
    sections.push_back({{"chainage", round_to(s.chainage, 0.001)},
                        {"overbreak_area_m2", seen(s.overbreak_area_m2, 0.0001)},
                        {"underbreak_area_m2", seen(s.underbreak_area_m2, 0.0001)},
                        {"seen_fraction", round_to(s.seen_fraction, 0.001)},
                        {"roof_seen", round_to(s.roof_seen, 0.001)},
                        {"walls_seen", round_to(s.walls_seen, 0.001)},
                        {"floor_seen", round_to(s.floor_seen, 0.001)},
                        {"max_overbreak_m", seen(s.max_overbreak_m, 0.001)},
                        {"max_underbreak_m", seen(s.max_underbreak_m, 0.001)}});
  }
  j["sections"] = sections;
  return j.dump(2) + "\n";
}

std::vector<std::string> visit_profile_summary(const VisitProfile& v) {
  const auto& d = v.deviation;
  std::vector<std::string> lines;
  lines.push_back("tunnel " + v.tunnel.name + ", visit " + std::to_string(v.placement.visit_id) +
                  ": face at chainage " + storage::report_number(v.placement.chainage, 2) +
                  ", offset " + storage::report_number(v.placement.offset_m, 2) + " m (" +
                  v.placement.note + ")");
  lines.push_back("round from chainage " + storage::report_number(v.round_from, 2) + " (" +
                  v.round_from_source + ") to " + storage::report_number(v.round_to, 2));
  if (d.status == tunnel::DeviationStatus::no_walls_in_view ||
      d.status == tunnel::DeviationStatus::outside_alignment) {
    lines.push_back(d.message);
    return lines;
  }
  const auto plus_minus = [](const std::optional<double>& sigma) {
    return sigma ? " ± " + storage::report_number(*sigma, 3) : std::string();
  };
  lines.push_back("overbreak " + storage::report_number(d.overbreak_volume_m3, 2) +
                  plus_minus(d.overbreak_volume_sigma_m3) + " m³, underbreak " +
                  storage::report_number(d.underbreak_volume_m3, 2) +
                  plus_minus(d.underbreak_volume_sigma_m3) + " m³ over the round; " +
                  storage::report_number(d.seen_fraction * 100, 0) + " % of the outline seen");
  if (d.max_overbreak_m > 0)
    lines.push_back("largest overbreak " + storage::report_number(d.max_overbreak_m * 100, 1) +
                    " cm at chainage " + storage::report_number(d.max_overbreak.chainage, 2) +
                    ", " + storage::report_number(d.max_overbreak.s, 2) +
                    " m along the design line");
  if (d.has_underbreak)
    lines.push_back("deepest underbreak " + storage::report_number(d.max_underbreak_m * 100, 1) +
                    " cm at chainage " + storage::report_number(d.max_underbreak.chainage, 2) +
                    ", " + storage::report_number(d.max_underbreak.s, 2) +
                    " m along the design line");
  lines.push_back(std::to_string(d.beyond_tolerance.size()) +
                  (d.beyond_tolerance.size() == 1 ? " patch" : " patches") +
                  " of underbreak beyond the tolerance of " +
                  storage::report_number(v.tunnel.underbreak_tolerance_m * 100, 0) + " cm");
  if (!d.message.empty()) lines.push_back(d.message);
  return lines;
}

}  // namespace rockface::app

#include "firmware-app/propose/proposals_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/common/number_format.h"
#include "core/common/units.h"

namespace rockface::app {

namespace {

using nlohmann::json;

json proposal_vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

json finite_or_null_json(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

std::string orientation_text(const geometry::PlaneOrientation& o) {
  return format_fixed(rad_to_deg(o.dip), 0) + "/" + format_fixed(rad_to_deg(o.dipdir), 0);
}

}  // namespace

std::string proposals_json(const ProposeResult& r, Preset preset) {
  const Eigen::Vector3d& datum = r.model.datum;
  const measure::FacetSearch& f = r.facets;
  json j;
  j["format"] = "rockface-proposals/1";
  j["visit"] = r.visit;
  j["model"] = r.on;
  j["datum"] = proposal_vec(datum);
  j["preset"] = std::string(preset_name(preset));
  json knobs;
  knobs["angle_tolerance_deg"] = f.options.angle_tolerance_deg;
  knobs["min_area_m2"] = f.options.min_area_m2;
  knobs["planarity_in_sigmas"] = f.options.planarity_in_sigmas;
  knobs["smoothing_passes"] = f.options.smoothing_passes;
  knobs["point_sigma_m"] = f.point_sigma;
  j["knobs"] = knobs;
  j["mapped_area_m2"] = f.mapped_area;
  j["facet_area_m2"] = f.facet_area;
  j["rejected_regions"] = f.rejected_regions;
  j["rejected_area_m2"] = f.rejected_area;
  j["notes"] = f.notes;
  json facets = json::array();
  for (std::size_t i = 0; i < f.facets.size(); ++i) {
    const measure::Facet& x = f.facets[i];
    json m;
    m["id"] = "F" + std::to_string(x.id);
    m["dip"] = rad_to_deg(x.plane.orientation.dip);
    m["dipdir"] = rad_to_deg(x.plane.orientation.dipdir);
    m["sigma_deg"] = rad_to_deg(x.plane.sigma);
    m["area_m2"] = x.area;
    m["centroid"] = proposal_vec(x.centroid + datum);
    m["rms_m"] = x.plane.fit.rms_off_plane();
    m["fit_points"] = x.plane.fit.count;
    m["outliers"] = x.plane.outliers;
    m["triangles"] = x.triangles;
    m["planarity_margin_sigmas"] = x.planarity_margin_sigmas;
    m["orientation_margin_deg"] = x.orientation_margin_deg;
    m["marginal"] = x.marginal;
    const int s = r.sets.set_of.empty() ? -1 : r.sets.set_of[i];
    m["set"] = s >= 0 ? json(r.sets.sets[s].summary.label) : json(nullptr);
    json outline = json::array();
    for (const auto& p : x.outline) outline.push_back(proposal_vec(p + datum));
    m["outline"] = outline;
    m["holes"] = x.holes;
    facets.push_back(m);
  }
  j["facets"] = facets;
  json sets = json::array();
  for (const auto& s : r.sets.sets) {
    json m;
    m["label"] = s.summary.label;
    const auto o = s.summary.fisher.plane();
    m["dip"] = rad_to_deg(o.dip);
    m["dipdir"] = rad_to_deg(o.dipdir);
    m["count"] = s.summary.fisher.count;
    m["fisher_k"] = finite_or_null_json(s.summary.fisher.kappa);
    m["alpha95_deg"] = finite_or_null_json(rad_to_deg(s.summary.fisher.alpha95));
    m["spacing_m"] = s.summary.spacing ? json(*s.summary.spacing) : json(nullptr);
    m["spacing_gaps"] = s.summary.spacing_gaps;
    m["planes"] = s.planes;
    m["area_m2"] = s.area;
    json members = json::array();
    for (int id : s.facet_ids) members.push_back("F" + std::to_string(id));
    m["members"] = members;
    sets.push_back(m);
  }
  j["sets"] = sets;
  json not_sets = json::array();
  for (const auto& c : r.sets.not_sets) {
    json m;
    const auto o = c.fisher.plane();
    m["dip"] = rad_to_deg(o.dip);
    m["dipdir"] = rad_to_deg(o.dipdir);
    m["area_m2"] = c.area;
    json members = json::array();
    for (int id : c.facet_ids) members.push_back("F" + std::to_string(id));
    m["members"] = members;
    m["reason"] = c.reason;
    not_sets.push_back(m);
  }
  j["not_sets"] = not_sets;
  if (r.trace_proposals.is_null()) {
    j["trace_proposals"] = nullptr;
    j["trace_proposals_note"] = "trace proposals not asked for";
  } else {
    j["trace_proposals"] = r.trace_proposals;
  }
  return j.dump(2) + "\n";
}

std::vector<std::string> proposals_summary(const ProposeResult& r) {
  std::vector<std::string> lines;
  const auto& f = r.facets;
  lines.push_back(std::to_string(f.facets.size()) + " facets on " + r.on + ": " +
                  format_fixed(f.facet_area, 1) + " of " + format_fixed(f.mapped_area, 1) +
                  " m2 mapped" +
                  (f.rejected_regions > 0
                       ? ", " + std::to_string(f.rejected_regions) + " regions not planar (" +
                             format_fixed(f.rejected_area, 1) + " m2)"
                       : ""));
  for (const auto& s : r.sets.sets) {
    std::string line =
        s.summary.label + "  " + orientation_text(s.summary.fisher.plane()) + "  " +
        std::to_string(s.facet_ids.size()) + " facets on " + std::to_string(s.planes) +
        " planes, K " +
        (std::isfinite(s.summary.fisher.kappa) ? format_fixed(s.summary.fisher.kappa, 0)
                                               : std::string("inf")) +
        ", spacing " + (s.summary.spacing ? format_fixed(*s.summary.spacing, 2) + " m" : "-");
    lines.push_back(line);
  }
  for (const auto& c : r.sets.not_sets)
    lines.push_back("not a set (" + orientation_text(c.fisher.plane()) + ", " +
                    std::to_string(c.facet_ids.size()) + " facets): " + c.reason);
  for (const auto& n : f.notes) lines.push_back(n);
  if (r.trace_proposals.is_object()) {
    const auto& list = r.trace_proposals.at("proposals");
    int linked = 0;
    for (const auto& p : list) linked += !p.at("facet").is_null();
    lines.push_back(std::to_string(list.size()) + " trace proposals (" + std::to_string(linked) +
                    " along a facet's edge): accept them on the Mapping screen, or store them "
                    "from a picks file with `rockface measure`");
  }
  return lines;
}

}  // namespace rockface::app

#include "firmware-app/propose/report_facets.h"

#include <cmath>

#include "core/common/units.h"
#include "firmware-app/propose/proposals_picture.h"

namespace rockface::app {

void add_facets_to_report(const ProposeResult& r, Preset preset, storage::FieldReport& report) {
  using storage::report_number;
  storage::ReportedFacets f;
  const auto& s = r.facets;
  f.lines.push_back(std::to_string(s.facets.size()) + " planar facets on " + r.on + " (preset " +
                    std::string(preset_name(preset)) + ": within " +
                    report_number(s.options.angle_tolerance_deg, 0) + " deg and " +
                    report_number(s.options.planarity_in_sigmas, 1) +
                    " point sigmas of a plane, at least " +
                    report_number(s.options.min_area_m2, 2) + " m2; point sigma " +
                    report_number(s.point_sigma * 1000, 1) + " mm)");
  f.lines.push_back("facets cover " + report_number(s.facet_area, 1) + " of " +
                    report_number(s.mapped_area, 1) + " m2 mapped");
  for (const auto& set : r.sets.sets) {
    const auto o = set.summary.fisher.plane();
    f.rows.push_back(
        {set.summary.label,
         report_number(rad_to_deg(o.dip), 0) + "/" + report_number(rad_to_deg(o.dipdir), 0),
         std::to_string(set.facet_ids.size()), std::to_string(set.planes),
         std::isfinite(set.summary.fisher.kappa) ? report_number(set.summary.fisher.kappa, 0)
                                                 : "inf",
         set.summary.fisher.alpha95 < M_PI
             ? report_number(rad_to_deg(set.summary.fisher.alpha95), 1)
             : "-",
         report_number(set.summary.spacing, 2), report_number(set.area, 1)});
  }
  for (const auto& c : r.sets.not_sets) {
    const auto o = c.fisher.plane();
    f.notes.push_back(report_number(rad_to_deg(o.dip), 0) + "/" +
                      report_number(rad_to_deg(o.dipdir), 0) + " (" +
                      std::to_string(c.facet_ids.size()) + " facets): " + c.reason);
  }
  for (const auto& n : s.notes) f.notes.push_back(n);
  f.picture = proposals_picture(r, 1400);
  report.facets = std::move(f);
}

}  // namespace rockface::app

#include "firmware-app/wedges/report_wedges.h"

#include <numbers>

#include "core/analysis/effect_words.h"
#include "core/common/degrees_per_radian.h"
#include "firmware-app/wedges/wedges_json.h"
#include "firmware-app/wedges/wedges_workflow.h"
#include "storage/field_report/wedge_pictures.h"

namespace rockface::app {

void add_wedges_to_report(storage::ProjectStore& store, storage::FieldReport& report) {
  std::string why;
  const auto r = project_visit_wedges(store, report.visit_id, &why);
  if (!r) return;
  storage::ReportedWedges w;
  const WedgeRun& run = r->run;
  w.lines.push_back(
      "section " + (run.profile.name().empty() ? run.profile_source : run.profile.name()) +
      (run.chainage ? " at chainage " + storage::report_number(*run.chainage, 2) : "") +
      ", axis trend " + storage::report_number(run.trend_deg, 1) + " deg, plunge " +
      storage::report_number(run.plunge_deg, 1) + " deg");
  // Issue 39: a visit whose joints form no sets has its joints' wedges.
  bool joints = !run.sets.empty();
  for (const auto& s : run.sets) joints = joints && s.source == "joint";
  std::string sets;
  for (const auto& s : run.sets)
    sets += (sets.empty() ? "" : ", ") + s.id + " " + storage::report_number(s.dip_deg, 1) + "/" +
            storage::report_number(s.dipdir_deg, 1);
  w.lines.push_back(std::string(joints ? "joints, each taken as a set" : "sets") +
                    " (dip/dip direction): " + sets +
                    "; joints of unlimited persistence, every wedge at its largest");
  w.lines.push_back("effects simulated: " +
                    analysis::effects_in_words(r->analysis.effects_simulated));
  for (const auto& x : r->analysis.wedges)
    w.rows.push_back(
        {x.id, tunnel::wedge_place_name(x.place), x.code, storage::report_number(x.mass.volume, 3),
         storage::report_number(x.weight / 1000, 1), storage::report_number(x.apex_height, 2),
         storage::report_number(x.bolt_length_to_apex, 2),
         storage::report_number(x.removable.margin * kDegPerRad, 1) +
             (x.removable.marginal ? " ?" : ""),
         wedge_mode_words(x), wedge_fos_text(x.fos), wedge_fos_text(x.fos_supported)});
  for (const auto& x : r->analysis.wedges)
    for (const auto& c : x.corners) w.notes.push_back(x.id + " " + c);
  for (const auto& n : r->analysis.none) w.notes.push_back("no wedge " + n.code + ": " + n.reason);
  for (const auto& n : r->analysis.notes) w.notes.push_back(n);
  w.picture = storage::wedges_picture(r->analysis, 900);
  report.wedges = std::move(w);
}

}  // namespace rockface::app

// The tablet's Wedges view (ui::WedgeRunner): the wedges of the project's
// tunnel around the visit's face with its measured sets, as `rockface
// wedges PROJECT --visit N` finds them, laid out as a table in words.
#include <numbers>

#include "core/common/error.h"
#include "firmware-app/services/ui_services.h"
#include "firmware-app/wedges/wedges_json.h"
#include "firmware-app/wedges/wedges_workflow.h"
#include "storage/field_report/field_report.h"
#include "storage/field_report/wedge_pictures.h"
#include "storage/project/project_store.h"

namespace rockface::app {

ui::WedgeTable StoreWedgeRunner::wedges(const std::filesystem::path& project,
                                        storage::RecordId visit_id, Progress& progress) {
  progress.step("wedges around the excavation", 0.1);
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(project, read);
  const WedgeRun run = wedge_run_from_project(store, visit_id, {});
  const tunnel::WedgeAnalysis a = run_wedges(run);
  progress.step("section picture", 0.9);
  constexpr double kDeg = 180.0 / std::numbers::pi;
  ui::WedgeTable t;
  t.lines.push_back(
      "Section " + (run.profile.name().empty() ? run.profile_source : run.profile.name()) +
      (run.chainage ? " at chainage " + storage::report_number(*run.chainage, 2) + " m"
                    : std::string()) +
      ", drive trend " + storage::report_number(run.trend_deg, 1) + "°, plunge " +
      storage::report_number(run.plunge_deg, 1) + "°");
  std::string sets;
  for (const auto& s : run.sets)
    sets += (sets.empty() ? "" : ", ") + s.id + " " + storage::report_number(s.dip_deg, 1) + "°/" +
            storage::report_number(s.dipdir_deg, 1) + "°";
  t.lines.push_back("Sets (dip/dip direction): " + sets);
  std::string effects;
  for (const auto& e : a.effects_simulated) effects += (effects.empty() ? "" : ", ") + e;
  t.lines.push_back("Effects: " + effects);
  t.columns = {"Wedge",
               "Where",
               "Code",
               "Volume (m³)",
               "Weight (kN)",
               "Apex height (m)",
               "Bolt to apex (m)",
               "Margin",
               "Failure",
               "Factor of safety"};
  for (const auto& w : a.wedges) {
    t.rows.push_back(
        {w.id, tunnel::wedge_place_name(w.place), w.code, storage::report_number(w.mass.volume, 3),
         storage::report_number(w.weight / 1000, 1), storage::report_number(w.apex_height, 2),
         storage::report_number(w.bolt_length_to_apex, 2),
         storage::report_number(w.removable.margin * kDeg, 1) + "°", wedge_mode_words(w),
         wedge_fos_text(w.fos)});
    t.marginal.push_back(w.removable.marginal || (w.mode && w.mode->marginal));
    for (const auto& c : w.corners) t.notes.push_back(w.id + " " + c);
  }
  for (const auto& n : a.none) t.notes.push_back("No wedge " + n.code + ": " + n.reason);
  t.notes.insert(t.notes.end(), a.notes.begin(), a.notes.end());
  t.bgr = storage::wedges_picture(a, 900);
  return t;
}

}  // namespace rockface::app

// The tablet's Wedges view (ui::WedgeRunner): the wedges of the project's
// tunnel around the visit's face with its measured sets, as `rockface
// wedges PROJECT --visit N` finds them, laid out as a table in words.
#include <numbers>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "firmware-app/services/ui_services.h"
#include "firmware-app/wedges/wedges_json.h"
#include "firmware-app/wedges/wedges_workflow.h"
#include "storage/field_report/field_report.h"
#include "storage/field_report/wedge_pictures.h"
#include "storage/project/project_store.h"

namespace rockface::app {

namespace {

// A number as the command line takes it (all its digits: the form's value
// is read back exactly).
std::string option_number(double v) {
  return format_round_trip(v);
}

// The form as `rockface wedges`' options, so that the tablet and the
// command line run one workflow with one parser and one set of ranges.
WedgesRequest request_of(const std::filesystem::path& project, storage::RecordId visit,
                         const ui::WedgeForm& form) {
  WedgesRequest q;
  q.input = project.string();
  q.visit = visit;
  q.friction_deg = form.friction_deg;
  if (form.bolts)
    q.bolts = option_number(form.bolts->length_m) + "," + option_number(form.bolts->spacing_m) +
              "," + option_number(form.bolts->capacity_kn * 1000);
  if (form.shotcrete)
    q.shotcrete = option_number(form.shotcrete->thickness_mm / 1000) + "," +
                  option_number(form.shotcrete->shear_strength_mpa * 1e6);
  return q;
}

// The form's fields by the names the geologist sees, where the command line
// names its option.
std::string form_field(const std::string& where) {
  for (auto [option, words] : {std::pair{"--friction", "Friction"}, std::pair{"--bolts", "Bolts"},
                               std::pair{"--shotcrete", "Shotcrete"}})
    if (where == option) return words;
  return where;
}

}  // namespace

ui::WedgeTable StoreWedgeRunner::wedges(const std::filesystem::path& project,
                                        storage::RecordId visit_id, const ui::WedgeForm& form,
                                        Progress& progress) {
  progress.step("wedges around the excavation", 0.1);
  WedgesResult result;
  try {
    result = wedges_from_input(request_of(project, visit_id, form));
  } catch (const InputError& e) {
    throw InputError(form_field(e.where()), e.reason());
  }
  const WedgeRun& run = result.run;
  const tunnel::WedgeAnalysis& a = result.analysis;
  progress.step("section picture", 0.9);
  constexpr double kDeg = 180.0 / std::numbers::pi;
  ui::WedgeTable t;
  t.lines.push_back(
      "Section " + (run.profile.name().empty() ? run.profile_source : run.profile.name()) +
      (run.chainage ? " at chainage " + storage::report_number(*run.chainage, 2) + " m"
                    : std::string()) +
      ", drive trend " + storage::report_number(run.trend_deg, 1) + "°, plunge " +
      storage::report_number(run.plunge_deg, 1) + "°");
  t.lines.push_back(wedge_sets_line(run));
  t.lines.push_back(wedge_support_line(run));
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
               "Factor of safety",
               "With support"};
  for (const auto& w : a.wedges) {
    t.rows.push_back(
        {w.id, tunnel::wedge_place_name(w.place), w.code, storage::report_number(w.mass.volume, 3),
         storage::report_number(w.weight / 1000, 1), storage::report_number(w.apex_height, 2),
         storage::report_number(w.bolt_length_to_apex, 2),
         storage::report_number(w.removable.margin * kDeg, 1) + "°", wedge_mode_words(w),
         wedge_fos_text(w.fos),
         run.options.bolts || run.options.shotcrete ? wedge_fos_text(w.fos_supported) : "-"});
    t.marginal.push_back(w.removable.marginal || (w.mode && w.mode->marginal));
    for (const auto& c : w.corners) t.notes.push_back(w.id + " " + c);
  }
  for (const auto& n : a.none) t.notes.push_back("No wedge " + n.code + ": " + n.reason);
  t.notes.insert(t.notes.end(), a.notes.begin(), a.notes.end());
  t.bgr = storage::wedges_picture(a, 900);
  return t;
}

}  // namespace rockface::app

#include "ui/blocks/rockmass_view.h"

#include <memory>

#include <imgui.h>

#include "core/common/error.h"
#include "ui/app/app_state.h"
#include "ui/widgets/widgets_controls.h"

namespace rockface::ui {

namespace {

void compute(AppState& app, std::optional<rockmass::ClassificationForm> save) {
  RockMassRunner* runner = app.services.rockmass;
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  auto lines = std::make_shared<std::vector<std::string>>();
  app.task.start(
      save ? "Save the form and classify" : "Rock mass",
      [runner, file, visit, save, lines](Progress& progress) {
        *lines = runner->figures(file, visit, save, progress);
        return std::string(save ? "form saved" : "rock mass");
      },
      [&app, lines](const TaskOutcome& outcome) {
        RockMassState& r = app.blocks.rockmass;
        r.lines = outcome.kind == TaskOutcome::Kind::done
                      ? *lines
                      : std::vector<std::string>{outcome.message};
      });
}

void reload_rockmass(AppState& app) {
  RockMassState& r = app.blocks.rockmass;
  ProjectSession& s = *app.session;
  if (r.loaded && r.file == s.file() && r.visit == s.visit()) return;
  r.file = s.file();
  r.visit = s.visit();
  r.loaded = true;
  r.form = {};
  r.refusal.clear();
  r.lines.clear();
  try {
    if (s.visit())
      if (const auto stored = s.store().load_rockmass_form(*s.visit())) r.form = *stored;
  } catch (const std::exception& e) {
    r.lines = {std::string("The stored form could not be read: ") + e.what()};
  }
}

// One number of the form: a box to say it was entered, and its value.
void number_entry(AppState& app, const char* label, const char* unit, std::optional<double>& value,
                  double start) {
  bool entered = value.has_value();
  ImGui::PushID(label);
  if (checkbox(app.targets, std::string(label) + " entered", "", &entered))
    value = entered ? std::optional<double>(start) : std::nullopt;
  ImGui::SameLine();
  if (value) {
    number_field(app.targets, label, &*value, "%.3g", 120 * app.targets.scale());
    ImGui::SameLine();
    ui::label(std::string(label) + (*unit ? std::string(" (") + unit + ")" : ""));
  } else {
    ui::label(std::string(label) + ": not entered", ImGui::GetColorU32(ImGuiCol_TextDisabled));
  }
  ImGui::PopID();
}

// One choice of the form among the sheet's words, or "not entered".
template <class E>
void choice(AppState& app, const char* title, std::optional<E>& value,
            const std::vector<std::string>& words) {
  const std::string shown = value ? words[static_cast<int>(*value)] : "not entered";
  label(title);
  // "not entered" first, then the sheet's words.
  std::vector<std::string> items = {"not entered"};
  items.insert(items.end(), words.begin(), words.end());
  const auto current = value ? std::optional<std::size_t>(static_cast<std::size_t>(*value) + 1)
                             : std::optional<std::size_t>(0);
  if (const auto tapped = ui::choice(app.targets, title, shown, items, current))
    value = *tapped == 0 ? std::nullopt : std::optional<E>(static_cast<E>(*tapped - 1));
}

void draw_form(AppState& app) {
  rockmass::ClassificationForm& f = app.blocks.rockmass.form;
  note("RMR89: intact rock, joint condition, groundwater");
  number_entry(app, "UCS", "MPa", f.ucs_mpa, 100);
  number_entry(app, "Is50", "MPa", f.is50_mpa, 4);
  number_entry(app, "aperture", "mm", f.aperture_mm, 0.5);
  number_entry(app, "persistence (when not measured)", "m", f.persistence_m, 3);
  choice(app, "roughness", f.roughness, rockmass::roughness_words());
  choice(app, "infilling", f.infilling, rockmass::infilling_words());
  choice(app, "weathering", f.weathering, rockmass::weathering_words());
  number_entry(app, "condition rating (instead)", "0-30", f.condition_rating, 20);
  choice(app, "groundwater", f.groundwater, rockmass::groundwater_words());
  number_entry(app, "inflow per 10 m (instead)", "l/min", f.inflow_l_per_min, 0);
  choice(app, "orientation (without a tunnel)", f.orientation, rockmass::orientation_words());
  note("Q: Barton 2002 tables");
  number_entry(app, "Jr", "", f.jr, 1.5);
  number_entry(app, "Ja", "", f.ja, 1);
  number_entry(app, "Jw", "", f.jw, 1);
  number_entry(app, "SRF", "", f.srf, 1);
  number_entry(app, "ESR", "", f.esr, 1);
  number_entry(app, "span", "m", f.span_m, 10);
}

}  // namespace

void draw_rockmass_view(AppState& app) {
  if (!app.session || !app.session->visit()) {
    paragraph("Open a project with a visit first.");
    return;
  }
  reload_rockmass(app);
  RockMassState& r = app.blocks.rockmass;
  const bool idle = !app.task.running() && app.services.rockmass;
  if (app.targets.button("Rock mass figures", 0, idle)) compute(app, std::nullopt);
  if (app.targets.button_in_row("Save form", idle && !app.session->read_only())) {
    // Refused by name here, before the worker: the geologist sees at once
    // which value is off its table.
    try {
      rockmass::validate(r.form);
      r.refusal.clear();
      compute(app, r.form);
    } catch (const InputError& e) {
      r.refusal = e.where() + ": " + e.reason();
    }
  }
  if (!r.refusal.empty()) {
    paragraph("Refused: " + r.refusal, warning_colour());
  }
  for (const auto& line : r.lines) paragraph(line);
  if (collapsing_section(app.targets, "Entered on site (form)", true)) draw_form(app);
}

}  // namespace rockface::ui

#include "ui/project/geologist_entry.h"

#include <exception>

#include "storage/project/visit_geologist.h"
#include "ui/app/app_state.h"
#include "ui/widgets/widgets_controls.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

void draw_geologist_entry(AppState& app) {
  ProjectSession& s = *app.session;
  GeologistEntryState& g = app.project.geologist;
  const std::optional<std::string> stored = s.visit_geologist();
  // Another visit chosen (or begun): the field shows its own name.
  if (g.for_visit != s.visit()) {
    g.typed = stored.value_or("");
    g.for_visit = s.visit();
  }
  paragraph("Geologist: " + stored.value_or(storage::kGeologistNotRecorded));
  text_field(app.targets, "geologist", &g.typed);
  const bool can = !app.task.running() && !s.read_only() && s.visit().has_value() &&
                   g.typed != stored.value_or("");
  if (!app.targets.button_in_row("Set geologist", can)) return;
  try {
    s.name_geologist(g.typed);
    const std::optional<std::string> kept = s.visit_geologist();
    g.typed = kept.value_or("");
    // The tablet carries the name to each new visit from now on.
    app.settings.geologist = kept.value_or("");
    save_ui_settings(app.options.settings_file, app.settings);
    app.say("Visit " + std::to_string(*s.visit()) +
            " geologist: " + kept.value_or(storage::kGeologistNotRecorded));
  } catch (const std::exception& e) {
    app.fail(e.what());
  }
}

}  // namespace rockface::ui

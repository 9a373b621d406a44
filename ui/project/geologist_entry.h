#pragma once
// Project → This visit: the geologist who mapped the visit (issue 46), by
// name. Typed once on the tablet, the name is remembered in the tablet's
// settings (ui/app/ui_settings.h) and carried to each new visit begun here;
// typed on a visit, it changes that visit's alone (and is carried from then
// on). A visit without one shows "not recorded".
#include <optional>
#include <string>

#include "storage/project/project_records.h"

namespace rockface::ui {

struct AppState;

struct GeologistEntryState {
  std::string typed;                           // the field's text
  std::optional<storage::RecordId> for_visit;  // the visit it was filled for
};

// Draws the visit's geologist, the field and "Set geologist"; the project
// must be open with a visit chosen.
void draw_geologist_entry(AppState& app);

}  // namespace rockface::ui

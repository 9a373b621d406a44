#pragma once
// The office server on the Project screen (issue 24): the server the
// project syncs to (the tablet's libpq service, set once per tablet), what
// waits to go up, the last sync and how it ended, and a Sync button that
// runs the sync on the worker with progress and Cancel (a cancelled or cut
// sync is resumed by the next). Without a network it says so; the field
// work is untouched.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ui/app/field_services.h"

namespace rockface::ui {

struct AppState;

struct OfficeState {
  std::filesystem::path file;  // what `overview` was read for
  std::optional<SyncOverview> overview;
  std::string error;               // why the overview could not be read
  std::vector<std::string> lines;  // the last sync's outcome in words
  bool stale = true;               // re-read the overview
};

void draw_office_panel(AppState& app);

}  // namespace rockface::ui

#include "ui/project/office_panel.h"

#include <memory>

#include <imgui.h>

#include "ui/app/app_state.h"
#include "ui/widgets/format.h"

namespace rockface::ui {

namespace {

void reload(AppState& app) {
  OfficeState& o = app.project.office;
  if (!o.stale && o.file == app.session->file()) return;
  o.file = app.session->file();
  o.stale = false;
  o.overview.reset();
  o.error.clear();
  if (app.session->read_only()) return;
  try {
    o.overview = app.services.sync->overview(o.file);
  } catch (const std::exception& e) {
    o.error = e.what();
  }
}

void start_sync(AppState& app) {
  SyncRunner* runner = app.services.sync;
  const auto file = app.session->file();
  auto lines = std::make_shared<std::vector<std::string>>();
  app.task.start(
      "Sync to the office",
      [runner, file, lines](Progress& progress) {
        *lines = runner->sync(file, progress);
        return lines->size() > 1 ? (*lines)[1] : std::string("synced");
      },
      [&app, lines](const TaskOutcome& outcome) {
        OfficeState& o = app.project.office;
        o.stale = true;
        if (outcome.kind == TaskOutcome::Kind::done)
          o.lines = *lines;
        else if (outcome.kind == TaskOutcome::Kind::cancelled)
          o.lines = {"Sync cancelled: what was sent stays on the server; the next sync resumes."};
        else
          o.lines = {outcome.message};
      });
}

}  // namespace

void draw_office_panel(AppState& app) {
  if (!app.services.sync || !app.session) return;
  reload(app);
  OfficeState& o = app.project.office;
  ImGui::Separator();
  heading("Office server");
  if (app.session->read_only()) {
    note("A read-only project is not synced.");
    return;
  }
  if (!o.error.empty())
    paragraph("The sync record could not be read: " + o.error, warning_colour());
  if (o.overview) {
    const SyncOverview& v = *o.overview;
    paragraph("Syncs to " + v.server + (v.tunnel.empty() ? "" : ", tunnel " + v.tunnel));
    if (v.ever_synced)
      paragraph("Last sync: " +
                (v.last_sync_at.empty() ? std::string("not completed yet")
                                        : format::date_time(v.last_sync_at)) +
                (v.last_outcome.empty() ? "" : ", " + v.last_outcome));
    else
      label("Never synced.");
    if (v.records_waiting == 0)
      label("Nothing waits to go up.");
    else
      paragraph("Waiting to go up: " + format::count(v.records_waiting, "record", "records") +
                " of " + format::count(v.visits_waiting, "visit", "visits"));
  }
  const bool idle = !app.task.running();
  if (app.targets.button("Sync", 0, idle)) start_sync(app);
  for (const auto& line : o.lines) paragraph(line);
}

}  // namespace rockface::ui

#include "ui/office_panel.h"

#include <memory>

#include <imgui.h>

#include "ui/app_state.h"

namespace rockface::ui {

namespace {

void reload(AppState& app) {
  OfficeState& o = app.office;
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
        OfficeState& o = app.office;
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
  OfficeState& o = app.office;
  ImGui::Separator();
  ImGui::TextUnformatted("Office server");
  if (app.session->read_only()) {
    ImGui::TextDisabled("A read-only project is not synced.");
    return;
  }
  if (!o.error.empty())
    ImGui::TextWrapped("The sync record could not be read: %s", o.error.c_str());
  if (o.overview) {
    const SyncOverview& v = *o.overview;
    ImGui::Text("Syncs to %s%s%s", v.server.c_str(), v.tunnel.empty() ? "" : ", tunnel ",
                v.tunnel.c_str());
    if (v.ever_synced)
      ImGui::Text(
          "Last sync: %s  %s",
          v.last_sync_at.empty() ? "not completed yet" : v.last_sync_at.substr(0, 16).c_str(),
          v.last_outcome.c_str());
    else
      ImGui::TextUnformatted("Never synced.");
    if (v.records_waiting == 0)
      ImGui::TextUnformatted("Nothing waits to go up.");
    else
      ImGui::Text("Waiting to go up: %d records of %d visits", v.records_waiting, v.visits_waiting);
  }
  const bool idle = !app.task.running();
  if (app.targets.button("Sync", 0, idle)) start_sync(app);
  for (const auto& line : o.lines) ImGui::TextWrapped("%s", line.c_str());
}

}  // namespace rockface::ui

#include "ui/app/export_to_stick.h"

#include "ui/app/project_session.h"

namespace rockface::ui {

void draw_export_to_stick(AppState& app) {
  ExportRunner* runner = app.services.exports;
  if (!runner || !app.session) return;
  const bool can = app.session->visit() && !app.task.running();
  if (!app.targets.button_in_row("Export to USB stick", can)) return;
  // The sticks are looked for on the tap, not every frame: one plugged in
  // since the screen was drawn counts.
  const auto targets = runner->targets();
  if (targets.empty()) {
    app.fail("No USB stick found: plug one in and tap Export to USB stick again.");
    return;
  }
  const ExportTarget target = targets.front();
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  app.task.start("Export to USB stick", [runner, file, visit, target](Progress& progress) {
    return runner->write(file, visit, target, progress);
  });
}

}  // namespace rockface::ui

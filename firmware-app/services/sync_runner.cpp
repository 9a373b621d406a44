// The tablet's Sync button (ui::SyncRunner): the sync of `rockface sync` to
// the tablet's one server, with the no-network case said in words.
#include "firmware-app/office/office_workflows.h"
#include "firmware-app/services/ui_services.h"
#include "storage/office/pg_connection.h"
#include "storage/office/sync_push.h"

namespace rockface::app {

ui::SyncOverview StoreSyncRunner::overview(const std::filesystem::path& project) {
  const storage::office::SyncStatus s = storage::office::sync_status(project);
  ui::SyncOverview o;
  o.server = s.ever_synced ? s.server_label : tablet_server();
  o.ever_synced = s.ever_synced;
  o.tunnel = s.tunnel;
  o.last_sync_at = s.last_sync_at;
  o.last_outcome = s.last_outcome;
  o.records_waiting = s.records_waiting;
  o.visits_waiting = s.visits_waiting;
  return o;
}

std::vector<std::string> StoreSyncRunner::sync(const std::filesystem::path& project,
                                               Progress& progress) {
  try {
    return run_sync(project, tablet_server(), {}, progress);
  } catch (const storage::office::ServerError& e) {
    if (!e.connection_lost()) throw;
    throw Error("No network: the office server (" + tablet_server() +
                ") cannot be reached. Nothing is lost and field work goes on; the next sync "
                "sends what waits.");
  }
}

}  // namespace rockface::app

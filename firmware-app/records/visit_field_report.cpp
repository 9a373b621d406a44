#include "firmware-app/records/visit_field_report.h"

#include "firmware-app/rockmass/rock_mass_report.h"
#include "firmware-app/support/report_support.h"
#include "firmware-app/tunnel/report_tunnel.h"
#include "firmware-app/wedges/report_wedges.h"

namespace rockface::app {

storage::FieldReport collect_visit_report(storage::ProjectStore& store, storage::RecordId visit,
                                          const DriveFaces* drive) {
  storage::FieldReport report = storage::collect_field_report(store, visit);
  add_tunnel_to_report(store, report, Preset::standard, drive);
  add_wedges_to_report(store, report);
  add_rock_mass_to_report(store, report);
  add_support_to_report(store, report);
  return report;
}

}  // namespace rockface::app

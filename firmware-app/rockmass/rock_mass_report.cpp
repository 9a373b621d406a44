#include "firmware-app/rockmass/rock_mass_report.h"

#include "core/common/error.h"
#include "firmware-app/rockmass/visit_rock_mass.h"

namespace rockface::app {

void add_rock_mass_to_report(storage::ProjectStore& store, storage::FieldReport& report) {
  try {
    report.rockmass = visit_rock_mass(store, report.visit_id);
  } catch (const InputError& e) {
    // A visit without traces (or whose stored form no longer validates)
    // still gets its report; the section says why it has no figures.
    report.rockmass_note = "no rock-mass figures: " + e.reason();
  }
}

}  // namespace rockface::app

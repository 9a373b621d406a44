// ProjectStore: a stored trace's plane replaced in place (issue 27: a
// compass reading given or cleared on the tablet for a saved trace).
#include "core/common/error.h"
#include "storage/project/project_store.h"
#include "storage/project/project_store_rows.h"

namespace rockface::storage {

using namespace rows;  // row helpers and the SQLite wrappers

void ProjectStore::set_trace_plane(RecordId measurement_id, const Measurement& m) {
  const std::string doing = "replacing the plane of trace " + std::to_string(measurement_id);
  const std::string where = "measurement " + std::to_string(measurement_id);
  require_writable(doing);
  if (m.dip_deg.has_value() != m.dipdir_deg.has_value())
    throw InputError(where, "dip and dip direction must be given together");
  if (m.dip_deg) require_orientation(*m.dip_deg, *m.dipdir_deg, where);
  if (m.compass_dip_deg.has_value() != m.compass_dipdir_deg.has_value())
    throw InputError(where + ".compass", "dip and dip direction must be given together");
  if (m.compass_dip_deg)
    require_orientation(*m.compass_dip_deg, *m.compass_dipdir_deg, where + ".compass");
  if (m.compass_off_deg) require_finite(*m.compass_off_deg, where + ".compass_off_deg");
  if (m.sigma_deg) require_finite(*m.sigma_deg, where + ".sigma_deg");
  require_finite(m.fit_rms_m, where + ".fit_rms_m");
  WriteTransaction tx(db_, doing);
  Statement find(db_, "SELECT visit_id, label, kind FROM measurement WHERE id = ?", doing);
  find.bind(1, measurement_id);
  if (!find.step() || find.column_text(2) != "trace") throw InputError(where, "no such trace");
  const RecordId visit_id = find.column_int(0);
  const std::string label = find.column_text(1);
  Statement st(db_,
               "UPDATE measurement SET dip = ?, dipdir = ?, sigma_deg = ?, fit_rms_m = ?, "
               "note = ?, compass_dip = ?, compass_dipdir = ?, compass_off_deg = ? WHERE id = ?",
               doing);
  st.bind(1, m.dip_deg)
      .bind(2, m.dipdir_deg)
      .bind(3, m.sigma_deg)
      .bind(4, m.fit_rms_m)
      .bind(5, m.note)
      .bind(6, m.compass_dip_deg)
      .bind(7, m.compass_dipdir_deg)
      .bind(8, m.compass_off_deg)
      .bind(9, measurement_id)
      .run();
  insert_log(visit_id, m.compass_dip_deg ? "compass reading given" : "compass reading cleared",
             label);
  tx.commit();
}

}  // namespace rockface::storage

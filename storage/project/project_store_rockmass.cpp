// ProjectStore: the rock-mass classification form entered per visit
// (schema 6), kept as the JSON of storage/scene/rockmass_form_json.h.
#include "core/common/error.h"
#include "storage/project/project_store.h"
#include "storage/project/project_store_rows.h"
#include "storage/scene/rockmass_form_json.h"

namespace rockface::storage {

using namespace rows;  // row helpers and the SQLite wrappers

void ProjectStore::save_rockmass_form(RecordId visit_id, const rockmass::ClassificationForm& form) {
  const std::string doing = "saving the rock-mass form";
  require_writable(doing);
  rockmass::validate(form);  // InputError naming the field
  bool found = false;
  for (const auto& v : list_visits()) found = found || v.id == visit_id;
  if (!found)
    throw InputError("--visit",
                     "the project " + file_.string() + " has no visit " + std::to_string(visit_id));
  WriteTransaction tx(db_, doing);
  Statement st(db_,
               "INSERT INTO rockmass_form (visit_id, form_json, updated_at) VALUES (?, ?, ?) "
               "ON CONFLICT(visit_id) DO UPDATE SET form_json = excluded.form_json, "
               "updated_at = excluded.updated_at",
               doing);
  st.bind(1, visit_id).bind(2, rockmass_form_json(form).dump()).bind(3, utc_now_iso8601());
  st.run();
  insert_log(visit_id, "rock-mass form saved", rockmass_form_json(form).dump());
  tx.commit();
}

std::optional<rockmass::ClassificationForm> ProjectStore::load_rockmass_form(RecordId visit_id) {
  const std::string doing = "loading the rock-mass form";
  ReadTransaction tx(db_);
  Statement st(db_, "SELECT form_json FROM rockmass_form WHERE visit_id = ?", doing);
  st.bind(1, visit_id);
  if (!st.step()) return std::nullopt;
  RowReader row(st);
  return parse_rockmass_form(
      row.next_text(), file_.string() + ": rockmass_form of visit " + std::to_string(visit_id));
}

}  // namespace rockface::storage

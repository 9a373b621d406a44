// ProjectStore: the geologist who mapped a visit (schema 13,
// storage/project/visit_geologist.h), one row per visit with a name.
#include "core/common/error.h"
#include "storage/project/project_store.h"
#include "storage/project/project_store_rows.h"
#include "storage/project/visit_geologist.h"

namespace rockface::storage {

using namespace rows;  // row helpers and the SQLite wrappers

void ProjectStore::put_visit_geologist(RecordId visit_id, const std::string& name,
                                       const std::string& doing) {
  Statement put(db_,
                "INSERT INTO visit_geologist (visit_id, geologist) VALUES (?, ?) ON CONFLICT "
                "(visit_id) DO UPDATE SET geologist = excluded.geologist",
                doing);
  put.bind(1, visit_id).bind(2, name);
  put.run();
  insert_log(visit_id, "geologist named", name);
}

void ProjectStore::save_visit_geologist(RecordId visit_id, const std::string& geologist) {
  const std::string where = "visit " + std::to_string(visit_id) + " geologist";
  const std::string name = checked_geologist(geologist, where);
  const std::string doing = "saving the visit's geologist";
  require_writable(doing);
  WriteTransaction tx(db_, doing);
  Statement known(db_, "SELECT count(*) FROM visit WHERE id = ?", doing);
  known.bind(1, visit_id);
  known.step();
  if (known.column_int(0) == 0)
    throw InputError(where,
                     "the project " + file_.string() + " has no visit " + std::to_string(visit_id));
  if (name.empty()) {
    Statement del(db_, "DELETE FROM visit_geologist WHERE visit_id = ?", doing);
    del.bind(1, visit_id);
    del.run();
    insert_log(visit_id, "geologist taken away", "");
  } else {
    put_visit_geologist(visit_id, name, doing);
  }
  tx.commit();
}

std::optional<std::string> ProjectStore::load_visit_geologist(RecordId visit_id) {
  Statement st(db_, "SELECT geologist FROM visit_geologist WHERE visit_id = ?",
               "reading the visit's geologist");
  st.bind(1, visit_id);
  if (!st.step()) return std::nullopt;
  return st.column_text(0);
}

}  // namespace rockface::storage

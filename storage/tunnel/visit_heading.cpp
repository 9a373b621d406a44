#include "storage/tunnel/visit_heading.h"

#include "core/common/error.h"
#include "storage/project/one_line_name.h"
#include "storage/project/project_sqlite.h"

namespace rockface::storage {

namespace {

using sqlite::Connection;
using sqlite::Statement;

// The store's file on a connection of this call's own (through SQLite, as
// the store's: storage/project/project_store.h's threads note), in the
// store's access: the store's own connection is its class's.
Connection open_of(ProjectStore& store, bool write) {
  return Connection(store.file(),
                    write ? Connection::Access::read_write : Connection::Access::read_only);
}

}  // namespace

std::string checked_heading(const std::string& name, const std::string& field) {
  // The office lists a visit without a heading as "—" (and filters by it).
  static const OneLineNameRule rule{"a heading's name", "(\"North portal\", \"Bench\")", "—",
                                    "no heading: give the face's name, or none", kHeadingMaxChars};
  return checked_one_line_name(name, rule, field);
}

void save_visit_heading(ProjectStore& store, RecordId visit_id, const std::string& heading) {
  const std::string where = "visit " + std::to_string(visit_id) + " heading";
  const std::string name = checked_heading(heading, where);
  if (store.read_only())
    throw InputError(store.file().string(),
                     "cannot name the visit's heading: " + store.read_only_reason());
  Connection db = open_of(store, true);
  const std::string doing = "saving the visit's heading";
  sqlite::WriteTransaction tx(db, doing);
  Statement known(db, "SELECT count(*) FROM visit WHERE id = ?", doing);
  known.bind(1, visit_id);
  known.step();
  if (known.column_int(0) == 0)
    throw InputError(where, "the project " + store.file().string() + " has no visit " +
                                std::to_string(visit_id));
  if (name.empty()) {
    Statement del(db, "DELETE FROM visit_heading WHERE visit_id = ?", doing);
    del.bind(1, visit_id);
    del.run();
  } else {
    Statement put(db,
                  "INSERT INTO visit_heading (visit_id, heading) VALUES (?, ?) ON CONFLICT "
                  "(visit_id) DO UPDATE SET heading = excluded.heading",
                  doing);
    put.bind(1, visit_id).bind(2, name);
    put.run();
  }
  tx.commit();
}

std::string load_visit_heading(ProjectStore& store, RecordId visit_id) {
  Connection db = open_of(store, false);
  Statement st(db, "SELECT heading FROM visit_heading WHERE visit_id = ?",
               "reading the visit's heading");
  st.bind(1, visit_id);
  return st.step() ? st.column_text(0) : std::string();
}

std::map<RecordId, std::string> list_visit_headings(ProjectStore& store) {
  Connection db = open_of(store, false);
  Statement st(db, "SELECT visit_id, heading FROM visit_heading ORDER BY visit_id",
               "reading the visits' headings");
  std::map<RecordId, std::string> out;
  while (st.step()) out[st.column_int(0)] = st.column_text(1);
  return out;
}

}  // namespace rockface::storage

// ProjectStore: the tunnel's support classes and each visit's support
// decision (schema 10, issue 44), kept as the JSON of
// storage/support/support_classes_json.h, one row per save.
#include "core/common/error.h"
#include "storage/project/project_store.h"
#include "storage/project/project_store_rows.h"
#include "storage/support/support_classes_json.h"

namespace rockface::storage {

using namespace rows;  // row helpers and the SQLite wrappers

void ProjectStore::save_support_classes(const analysis::SupportClasses& classes) {
  const std::string doing = "saving the support classes";
  require_writable(doing);
  const std::string text = support_classes_json(classes).dump();
  // What the reader refuses is not stored either (a class file is the one
  // way in, but the tablet may build classes too).
  parse_support_classes(text, classes.source.empty() ? "support classes" : classes.source);
  WriteTransaction tx(db_, doing);
  Statement st(db_, "INSERT INTO support_classes (classes_json, source, saved_at) VALUES (?, ?, ?)",
               doing);
  st.bind(1, text).bind(2, classes.source).bind(3, utc_now_iso8601());
  st.run();
  insert_log(std::nullopt, "support classes saved",
             std::to_string(classes.classes.size()) + " classes from " + classes.source);
  tx.commit();
}

std::optional<analysis::SupportClasses> ProjectStore::load_support_classes() {
  const std::string doing = "loading the support classes";
  ReadTransaction tx(db_);
  Statement st(db_, "SELECT classes_json, source FROM support_classes ORDER BY id DESC LIMIT 1",
               doing);
  if (!st.step()) return std::nullopt;
  RowReader row(st);
  const std::string text = row.next_text();
  analysis::SupportClasses out = parse_support_classes(text, file_.string() + ": support_classes");
  out.source = row.next_text();
  return out;
}

void ProjectStore::save_support_decision(RecordId visit_id,
                                         const analysis::SupportDecision& decision) {
  const std::string doing = "saving the support decision";
  require_writable(doing);
  bool found = false;
  for (const auto& v : list_visits()) found = found || v.id == visit_id;
  if (!found)
    throw InputError("--visit",
                     "the project " + file_.string() + " has no visit " + std::to_string(visit_id));
  const std::string text = support_decision_json(decision).dump();
  parse_support_decision(text, "the support decision");  // the reader's refusals, before storing
  WriteTransaction tx(db_, doing);
  Statement st(db_,
               "INSERT INTO support_decision (visit_id, class_name, decision_json, decided_at) "
               "VALUES (?, ?, ?, ?)",
               doing);
  st.bind(1, visit_id).bind(2, decision.class_name).bind(3, text).bind(4, decision.decided_at);
  st.run();
  insert_log(visit_id, "support decided",
             decision.class_name + " by " + decision.decided_by +
                 (decision.reason.empty() ? "" : ": " + decision.reason));
  tx.commit();
}

std::vector<analysis::SupportDecision> ProjectStore::list_support_decisions(RecordId visit_id) {
  const std::string doing = "loading the support decisions";
  ReadTransaction tx(db_);
  Statement st(db_, "SELECT decision_json FROM support_decision WHERE visit_id = ? ORDER BY id",
               doing);
  st.bind(1, visit_id);
  std::vector<analysis::SupportDecision> out;
  while (st.step()) {
    RowReader row(st);
    out.push_back(parse_support_decision(
        row.next_text(),
        file_.string() + ": support_decision of visit " + std::to_string(visit_id)));
  }
  return out;
}

std::optional<analysis::SupportDecision> ProjectStore::load_support_decision(RecordId visit_id) {
  auto all = list_support_decisions(visit_id);
  if (all.empty()) return std::nullopt;
  return all.back();
}

}  // namespace rockface::storage

// ProjectStore: rows the geologist took back (issue 27: the tablet's undo of
// a saved trace, a replaced face outline, the joint table remade from the
// traces). The office sync needs nothing more: it sends a row it sent
// before and no longer finds as a deleted revision.
#include "storage/project/project_store.h"

#include <set>

#include "core/common/error.h"
#include "storage/project/project_store_rows.h"

namespace rockface::storage {

using namespace rows;  // row helpers and the SQLite wrappers

void ProjectStore::delete_measurement(RecordId measurement_id) {
  const std::string doing = "deleting measurement " + std::to_string(measurement_id);
  require_writable(doing);
  WriteTransaction tx(db_, doing);
  Statement find(db_, "SELECT visit_id, label FROM measurement WHERE id = ?", doing);
  find.bind(1, measurement_id);
  if (!find.step())
    throw InputError("measurement " + std::to_string(measurement_id), "no such measurement");
  const RecordId visit_id = find.column_int(0);
  const std::string label = find.column_text(1);
  // The joints fitted from it go with it (they name it: joint.measurement_id).
  Statement joints(db_, "DELETE FROM joint WHERE measurement_id = ?", doing);
  joints.bind(1, measurement_id).run();
  Statement del(db_, "DELETE FROM measurement WHERE id = ?", doing);
  del.bind(1, measurement_id).run();
  insert_log(visit_id, "measurement deleted", label);
  tx.commit();
}

void ProjectStore::delete_joints(RecordId visit_id, const std::vector<RecordId>& joint_ids,
                                 const std::vector<RecordId>& set_ids) {
  const std::string doing = "deleting joints of visit " + std::to_string(visit_id);
  require_writable(doing);
  WriteTransaction tx(db_, doing);
  const std::set<RecordId> joints_going(joint_ids.begin(), joint_ids.end());
  Statement joint_visit(db_, "SELECT visit_id FROM joint WHERE id = ?", doing);
  for (const RecordId id : joint_ids) {
    joint_visit.reset();
    joint_visit.bind(1, id);
    if (!joint_visit.step() || joint_visit.column_int(0) != visit_id)
      throw InputError(
          "joint " + std::to_string(id),
          "is not a joint of visit " + std::to_string(visit_id) + "; nothing was deleted");
  }
  Statement set_visit(db_, "SELECT visit_id FROM joint_set WHERE id = ?", doing);
  Statement named_by(db_, "SELECT id, label FROM joint WHERE set_id = ?", doing);
  for (const RecordId id : set_ids) {
    set_visit.reset();
    set_visit.bind(1, id);
    if (!set_visit.step() || set_visit.column_int(0) != visit_id)
      throw InputError(
          "joint set " + std::to_string(id),
          "is not a joint set of visit " + std::to_string(visit_id) + "; nothing was deleted");
    named_by.reset();
    named_by.bind(1, id);
    while (named_by.step())
      if (!joints_going.count(named_by.column_int(0)))
        throw InputError(
            "joint set " + std::to_string(id),
            "joint " + named_by.column_text(1) + " stays and names it; nothing was deleted");
  }
  Statement del_joint(db_, "DELETE FROM joint WHERE id = ?", doing);
  for (const RecordId id : joint_ids) {
    del_joint.reset();
    del_joint.bind(1, id).run();
  }
  Statement del_set(db_, "DELETE FROM joint_set WHERE id = ?", doing);
  for (const RecordId id : set_ids) {
    del_set.reset();
    del_set.bind(1, id).run();
  }
  insert_log(
      visit_id, "joints deleted",
      std::to_string(joint_ids.size()) + " joints, " + std::to_string(set_ids.size()) + " sets");
  tx.commit();
}

}  // namespace rockface::storage

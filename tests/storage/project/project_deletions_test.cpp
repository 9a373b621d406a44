// Issue 27: rows the geologist takes back on the tablet. A measurement goes
// with the joints fitted from it, in one transaction, logged; joints and
// sets of one visit go together; a row of another visit, a set that a
// staying joint names, or a missing row is refused by name with nothing
// deleted.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

struct Visit {
  RecordId id = 0;
  std::vector<RecordId> measurements, joints;
};

Visit sample_visit(ProjectStore& store) {
  Visit v;
  v.id = store.begin_visit("test");
  v.measurements = store.save_measurements(v.id, test::sample_measurements(std::nullopt));
  auto joints = test::sample_joints();
  joints[0].measurement_id = v.measurements[0];  // fitted from the first trace
  v.joints = store.save_joints(v.id, test::sample_joint_sets(), joints);
  return v;
}

TEST(ProjectDeletions, AMeasurementGoesWithTheJointsFittedFromIt) {
  TempDir dir("delete-measurement");
  auto store = ProjectStore::create(dir / "d.rockface", test::sample_project());
  const Visit v = sample_visit(store);
  const auto joints_before = store.list_joints(v.id);
  const std::string label = store.list_measurements(v.id)[0].label;
  store.delete_measurement(v.measurements[0]);
  const auto left = store.list_measurements(v.id);
  ASSERT_EQ(left.size(), v.measurements.size() - 1);
  for (const auto& m : left) EXPECT_NE(m.id, v.measurements[0]);
  const auto joints = store.list_joints(v.id);
  ASSERT_EQ(joints.size(), joints_before.size() - 1);
  for (const auto& j : joints) EXPECT_NE(j.id, v.joints[0]);
  std::size_t logged = 0;
  for (const auto& a : store.list_actions(v.id))
    logged += a.action == "measurement deleted" && a.detail == label;
  EXPECT_EQ(logged, 1u);
  EXPECT_TRUE(store.check_integrity().ok);
  try {
    store.delete_measurement(v.measurements[0]);
    FAIL() << "a deleted measurement deleted again";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "measurement " + std::to_string(v.measurements[0]));
  }
}

TEST(ProjectDeletions, JointsAndSetsOfOneVisitGoTogetherOrNotAtAll) {
  TempDir dir("delete-joints");
  auto store = ProjectStore::create(dir / "d.rockface", test::sample_project());
  const Visit a = sample_visit(store);
  const Visit b = sample_visit(store);
  const auto sets = store.list_joint_sets(a.id);
  ASSERT_FALSE(sets.empty());
  // A set still named by a joint that stays.
  RecordId named = 0;
  for (const auto& s : sets)
    for (const auto& j : store.list_joints(a.id))
      if (j.set_label == s.label) named = s.id;
  ASSERT_NE(named, 0);
  EXPECT_THROW(store.delete_joints(a.id, {}, {named}), InputError);
  // A joint of another visit.
  EXPECT_THROW(store.delete_joints(a.id, {a.joints[0], b.joints[0]}, {}), InputError);
  EXPECT_EQ(store.list_joints(a.id).size(), a.joints.size()) << "nothing deleted";
  EXPECT_EQ(store.list_joint_sets(a.id).size(), sets.size());
  // All of visit a's: gone; visit b's stay.
  std::vector<RecordId> set_ids;
  for (const auto& s : sets) set_ids.push_back(s.id);
  store.delete_joints(a.id, a.joints, set_ids);
  EXPECT_TRUE(store.list_joints(a.id).empty());
  EXPECT_TRUE(store.list_joint_sets(a.id).empty());
  EXPECT_EQ(store.list_joints(b.id).size(), b.joints.size());
  EXPECT_TRUE(store.check_integrity().ok);
}

}  // namespace
}  // namespace rockface::storage

// The support of the rounds in the project (schema 10): the tunnel's
// classes saved and the latest in force, a visit's decisions kept in order,
// an unknown visit refused and nothing stored.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

analysis::SupportClasses one_class(const std::string& name) {
  analysis::SupportClasses s;
  s.source = "classes.json";
  analysis::SupportClass c;
  c.name = name;
  c.round_length_m = 3;
  c.criteria.rmr = analysis::FigureRange{std::nullopt, std::nullopt};
  s.classes.push_back(c);
  return s;
}

TEST(ProjectSupport, ClassesAndDecisionsAreKeptInOrder) {
  TempDir dir("support");
  auto store = ProjectStore::create(dir / "s.rockface", test::sample_project());
  EXPECT_EQ(store.schema_version(), schema::kCurrentVersion);
  EXPECT_FALSE(store.load_support_classes());
  store.save_support_classes(one_class("A"));
  store.save_support_classes(one_class("B"));
  const auto classes = store.load_support_classes();
  ASSERT_TRUE(classes);
  EXPECT_EQ(classes->classes.at(0).name, "B");
  EXPECT_EQ(classes->source, "classes.json");

  const RecordId visit = store.begin_visit("test");
  EXPECT_FALSE(store.load_support_decision(visit));
  analysis::SupportDecision d;
  d.class_name = "A";
  d.proposed = "A";
  d.decided_by = "geologist";
  d.decided_at = "2026-11-28T22:00:00.000Z";
  store.save_support_decision(visit, d);
  d.class_name = "B";
  d.reason = "a wedge in the roof the bolts of A do not reach past";
  d.changes.push_back({"bolt length", "3 m", "4 m", "W2"});
  d.decided_at = "2026-11-28T22:30:00.000Z";
  store.save_support_decision(visit, d);
  const auto latest = store.load_support_decision(visit);
  ASSERT_TRUE(latest);
  EXPECT_EQ(latest->class_name, "B");
  ASSERT_EQ(latest->changes.size(), 1u);
  EXPECT_EQ(latest->changes[0].to, "4 m");
  const auto all = store.list_support_decisions(visit);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].class_name, "A");

  EXPECT_THROW(store.save_support_decision(visit + 7, d), InputError);
  EXPECT_EQ(store.list_support_decisions(visit + 7).size(), 0u);
}

}  // namespace
}  // namespace rockface::storage

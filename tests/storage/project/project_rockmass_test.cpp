// The rock-mass form per visit (schema step "rock-mass form"): saved,
// replaced, loaded; an out-of-range value refused by name and nothing
// stored; the scene's `rockmass` section read with the same checks.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "storage/scene/rockmass_form_json.h"
#include "storage/scene/scene.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

TEST(ProjectRockMass, TheFormRoundTripsAndIsReplaced) {
  TempDir dir("rockmass");
  auto store = ProjectStore::create(dir / "r.rockface", test::sample_project());
  EXPECT_EQ(store.schema_version(), schema::kCurrentVersion);
  const RecordId visit = store.begin_visit("test");
  EXPECT_FALSE(store.load_rockmass_form(visit));
  rockmass::ClassificationForm f;
  f.ucs_mpa = 85;
  f.roughness = rockmass::Roughness::rough;
  f.groundwater = rockmass::Groundwater::wet;
  f.jr = 3;
  f.ja = 0.75;
  f.note = "shotcrete test panel";
  store.save_rockmass_form(visit, f);
  auto back = store.load_rockmass_form(visit);
  ASSERT_TRUE(back);
  EXPECT_EQ(*back->ucs_mpa, 85);
  EXPECT_EQ(*back->roughness, rockmass::Roughness::rough);
  EXPECT_EQ(*back->groundwater, rockmass::Groundwater::wet);
  EXPECT_EQ(*back->jr, 3);
  EXPECT_EQ(*back->ja, 0.75);
  EXPECT_FALSE(back->jw);  // not entered stays not entered
  EXPECT_EQ(back->note, "shotcrete test panel");

  f.jr.reset();
  f.srf = 2.5;
  store.save_rockmass_form(visit, f);
  back = store.load_rockmass_form(visit);
  EXPECT_FALSE(back->jr);
  EXPECT_EQ(*back->srf, 2.5);
}

TEST(ProjectRockMass, AValueOutOfRangeIsRefusedByNameAndNothingStored) {
  TempDir dir("rockmass-bad");
  auto store = ProjectStore::create(dir / "r.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("test");
  rockmass::ClassificationForm f;
  f.srf = 1000;  // SRF's tables end at 400
  try {
    store.save_rockmass_form(visit, f);
    FAIL() << "SRF 1000 stored";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "SRF");
  }
  EXPECT_FALSE(store.load_rockmass_form(visit));
  EXPECT_THROW(store.save_rockmass_form(visit + 7, {}), InputError);  // no such visit
}

TEST(SceneRockMass, TheSectionIsReadWithItsChecks) {
  const std::string head =
      R"({"format": "rockface-scene/1", "joints": [], "free_faces": [], "rockmass": )";
  const Scene s =
      parse_scene(head + R"({"ucs_mpa": 60, "weathering": "slightly weathered"}})", "a.scene.json");
  ASSERT_TRUE(s.rockmass);
  EXPECT_EQ(*s.rockmass->ucs_mpa, 60);
  EXPECT_EQ(*s.rockmass->weathering, rockmass::Weathering::slightly);
  try {
    (void)parse_scene(head + R"({"Jw": 2}})", "b.scene.json");
    FAIL() << "Jw 2 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.where().find("rockmass.Jw"), std::string::npos) << e.what();
  }
  try {
    (void)parse_scene(head + R"({"roughness": "wavy"}})", "c.scene.json");
    FAIL() << "roughness wavy accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.where().find("rockmass.roughness"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("slightly rough"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)parse_scene(head + R"({"jr": 2}})", "d.scene.json"), InputError);
}

}  // namespace
}  // namespace rockface::storage

// Project → This visit: the geologist who mapped the visit (issue 46), on
// the headless tablet. A visit of the demo (replayed without one) shows
// "not recorded"; a name typed into the field through ImGui's own text
// input and set is stored on that visit and remembered by the tablet; a
// new visit carries it; changed on the new visit, only that visit changes;
// a tablet started again carries the last name set.
#include <filesystem>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <imgui.h>

#include "storage/project/project_store.h"
#include "tests/ui/demo_project.h"
#include "ui/app/ui_settings.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface::ui;
using Named = std::optional<std::string>;

constexpr int kWidth = 800, kHeight = 500;

std::unique_ptr<HeadlessSession> open_session(const fs::path& project, const fs::path& settings) {
  UiOptions options;
  options.project = project;
  options.scale = 0.6f;
  options.max_display_triangles = 20000;  // the model is not what is checked
  options.settings_file = settings;
  auto s = std::make_unique<HeadlessSession>(options, FieldServices{}, kWidth, kHeight);
  s->settle();
  s->tap("Project");
  return s;
}

Named stored_geologist(const fs::path& project, rockface::storage::RecordId visit) {
  return rockface::storage::ProjectStore::open(project).load_visit_geologist(visit);
}

TEST(VisitGeologistEntry, TypedOnceCarriedToEachNewVisitAndChangedPerVisit) {
  const fs::path project = rockface::test::copy_of_demo("geologist");
  const fs::path settings = rockface::test::ui_test_dir() / "geologist-settings" / "ui.json";
  fs::remove_all(settings.parent_path());
  rockface::storage::RecordId first = 0;
  {
    auto s = open_session(project, settings);
    AppState& app = s->state();
    ASSERT_TRUE(app.session && app.session->visit());
    first = *app.session->visit();
    EXPECT_EQ(app.session->visit_geologist(), std::nullopt) << "the demo names none";
    ASSERT_TRUE(app.targets.find("geologist"));
    EXPECT_FALSE(app.targets.find("Set geologist")->enabled) << "nothing typed yet";

    // Typed as a keyboard types: the field focused by a tap, the
    // characters through ImGui's input queue.
    s->tap("geologist");
    ImGui::GetIO().AddInputCharactersUTF8("O'Brien <b>");
    s->frame();
    s->frame();
    EXPECT_EQ(app.project.geologist.typed, "O'Brien <b>");
    s->tap("Set geologist");
    s->frame();
    EXPECT_EQ(stored_geologist(project, first), Named("O'Brien <b>"));
    EXPECT_EQ(load_ui_settings(settings).geologist, "O'Brien <b>") << "the tablet remembers it";

    s->tap("New visit");
    s->frame();
    const rockface::storage::RecordId second = *app.session->visit();
    ASSERT_NE(second, first);
    EXPECT_EQ(stored_geologist(project, second), Named("O'Brien <b>")) << "carried";
    EXPECT_EQ(app.project.geologist.typed, "O'Brien <b>") << "the field shows the new visit's";

    // Another geologist maps this visit: only this visit changes.
    app.project.geologist.typed = "Anna Berger";
    s->frame();
    s->tap("Set geologist");
    s->frame();
    EXPECT_EQ(stored_geologist(project, second), Named("Anna Berger"));
    EXPECT_EQ(stored_geologist(project, first), Named("O'Brien <b>"));
  }
  // The tablet started again: a new visit takes the last name set on it.
  auto s = open_session(project, settings);
  s->tap("New visit");
  s->frame();
  const rockface::storage::RecordId third = *s->state().session->visit();
  EXPECT_EQ(stored_geologist(project, third), Named("Anna Berger"));
  EXPECT_EQ(s->state().session->visit_geologist(), Named("Anna Berger"));
  if (!::testing::Test::HasFailure()) fs::remove_all(settings.parent_path());
}

}  // namespace
